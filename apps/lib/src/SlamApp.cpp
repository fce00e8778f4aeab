#include "omnirange_apps/SlamApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange_eval/GridMaps.h>
#include <omnirange_slam/IcpSlamIni.h>

#include <omnirange/config/Output.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace omnirange::app
{
namespace
{
constexpr char kProgram[] = "omnirange-slam";
}

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
	BoundArgs bound(cmd);
	bound.value("", "label", "label of the scans", o.scan_label, "LABEL");
	bound.value("", "odometry-label", "label of the odometry", o.odometry_label, "LABEL");
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	o.input = in.getValue(), o.ini = ini.getValue(), o.output = requiredPath(out);
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
	const std::vector<std::string> inputs{o_.input, o_.ini};
	const Output folder{o_.output, OutputKind::Folder};
	requireOutputsAllowed({folder}, kProgram, inputs);
	OutputSet set(kProgram, inputs);
	const std::string staged = set.stage(folder);
	const std::string map = staged + "/_finalmap_.simplemap", path = staged + "/log_estimated_path.txt";
	const slam::GuardedIcpResult r = slam::runGuardedIcp(o_.input, o_.scan_label, o_.odometry_label, options);
	std::string text = "% time [s], x [m], y [m], phi [rad]: the estimated pose at every scan\n";
	char line[128];
	for (const auto& p : r.path)
	{
		std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.6f\n", p.t, p.pose.x(), p.pose.y(), p.pose.phi());
		text += line;
	}
	std::filesystem::create_directory(staged);
	eval::saveSimplemap(r.keyframes, map);
	writeFileAtomically(path, text);
	set.commit();
	MRPT_LOG_INFO_STREAM(r.path.size() << " scans, " << r.keyframes.size() << " keyframes; " << r.matches
									   << " matches accepted, " << r.refused_jumps << " refused as jumps, "
									   << r.poor_matches << " too poor; " << r.weak_directions
									   << " directions left to the odometry; " << r.loops << " loops closed");
	return r;
}

}  // namespace omnirange::app
