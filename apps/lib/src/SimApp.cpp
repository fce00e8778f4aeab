#include "omnirange_apps/SimApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange/io/Progress.h>
#include <omnirange_sim/Route.h>

namespace omnirange::app
{
SimApp::Options SimApp::parse(int argc, const char* const* argv)
{
	Options o;
	auto& s = o.sim;
	TCLAP::CmdLine cmd("omnirange-sim: simulate an omnicam robot and write an MRPT rawlog", ' ', "0.1");
	TCLAP::ValueArg<std::string> world("w", "world", "world file (docs/worlds.md)", true, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> route("r", "route", "route file: one 'x y' waypoint per line [m]", true, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> robot("c", "robot", "robot ini (default: built-in OmniP2DX-like robot)", false, "", "INI", cmd);
	TCLAP::ValueArg<std::string> out("o", "output", "rawlog to write (NAME.rawlog; images go to NAME_Images/)", true, "", "FILE", cmd);
	BoundArgs bound(cmd);
	bound.value("n", "max-frames",
				"stop after this many frames (0: the whole route, which may give at most " +
					std::to_string(sim::kMaxRouteFrames) + ")",
				s.max_frames, "N");
	bound.value("j", "threads", "rendering threads", s.threads, "N");
	bound.value("f", "image-format", "png or jpg, overriding the robot ini", s.image_format, "FMT");
	ForceArg force(cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	s.force = force.value();
	s.world_file = world.getValue(), s.route_file = route.getValue(), s.robot_ini = robot.getValue();
	s.output = requiredPath(out);
	if (!s.image_format.empty() && s.image_format != "jpg" && s.image_format != "png")
		throw std::invalid_argument("-f must be png or jpg, not '" + s.image_format + "'");
	o.verbosity = verbosity.level();
	return o;
}

sim::SimSummary SimApp::run()
{
	sim::Simulator sim;
	sim.setMinLoggingLevel(o_.verbosity);
	Progress progress("frames");
	const bool show = o_.verbosity <= mrpt::system::LVL_INFO;
	const auto s = sim.run(o_.sim, [&](int done, int total) {
		if (show) progress.update(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
	});
	progress.finish();
	sim.logFmt(mrpt::system::LVL_INFO, "%d frames (%.1f s of route) in %.1f s: %.1f ms per frame", s.frames,
			   s.route_seconds, s.wall_seconds, 1000.0 * s.wall_seconds / std::max(1, s.frames));
	return s;
}

}  // namespace omnirange::app
