#include "omnirange_apps/SlamApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange_eval/GridMaps.h>
#include <omnirange_slam/IcpSlamIni.h>

#include <omnirange/config/AtomicWrite.h>
#include <omnirange/io/OutputRule.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace omnirange::app
{
SlamApp::Options SlamApp::parse(int argc, const char* const* argv)
{
	Options o;
	TCLAP::CmdLine cmd("omnirange-slam: a path and a map from range scans and odometry, by ICP guarded by the odometry, with loops closed on a pose graph",
					   ' ', "0.1");
	TCLAP::ValueArg<std::string> in("i", "input", "rawlog with the scans and the odometry", true, "", "RAWLOG", cmd);
	TCLAP::ValueArg<std::string> ini("c", "config", "icp-slam ini ([MappingApplication], [ICP]; optional [odometry_guard], [loop_closure])",
									 true, "", "INI", cmd);
	TCLAP::ValueArg<std::string> out("o", "output", "folder for _finalmap_.simplemap and log_estimated_path.txt", true, "",
									 "DIR", cmd);
	TCLAP::ValueArg<std::string> label("", "label", "label of the scans", false, o.scan_label, "LABEL", cmd);
	TCLAP::ValueArg<std::string> odometry("", "odometry-label", "label of the odometry", false, o.odometry_label,
										  "LABEL", cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	o.input = in.getValue(), o.ini = ini.getValue(), o.output = requiredPath(out);
	o.scan_label = label.getValue(), o.odometry_label = odometry.getValue();
	o.verbosity = verbosity.level();
	return o;
}

SlamApp::SlamApp(Options o) : mrpt::system::COutputLogger("omnirange-slam"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
}

slam::GuardedIcpResult SlamApp::run()
{
	const auto options = slam::GuardedIcpOptions::fromIniFile(o_.ini);
	for (const auto& setting : slam::mappingSettingsGuardedIcpIgnores(o_.ini))
		throw std::runtime_error(o_.ini + ": [MappingApplication] " + setting +
								 ": icp-slam follows this, omnirange-slam does not (it matches each scan against a "
								 "points map of its keyframes, from the rawlog's first entry)");
	// icp-slam's kind of outputs, in a folder of this program's that is swapped in whole.
	StagedFolder staged(o_.output, "omnirange-slam", {o_.input, o_.ini}, false);
	const std::string map = staged.path() + "/_finalmap_.simplemap", path = staged.path() + "/log_estimated_path.txt";
	const slam::GuardedIcpResult r = slam::runGuardedIcp(o_.input, o_.scan_label, o_.odometry_label, options);
	std::string text = "% time [s], x [m], y [m], phi [rad]: the estimated pose at every scan\n";
	char line[128];
	for (const auto& p : r.path)
	{
		std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.6f\n", p.t, p.pose.x(), p.pose.y(), p.pose.phi());
		text += line;
	}
	staged.fill([&] {
		eval::saveSimplemap(r.keyframes, map);
		writeFileAtomically(path, text);
	});
	staged.commit();
	MRPT_LOG_INFO_STREAM(r.path.size() << " scans, " << r.keyframes.size() << " keyframes; " << r.matches
									   << " matches accepted, " << r.refused_jumps << " refused as jumps, "
									   << r.poor_matches << " too poor; " << r.weak_directions
									   << " directions left to the odometry; " << r.loops << " loops closed");
	return r;
}

}  // namespace omnirange::app
