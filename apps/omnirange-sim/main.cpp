// omnirange-sim: world file + route + robot ini -> MRPT rawlog (OMNICAM,
// LASER, ODOMETRY, GT) with external images, plus the world's true map.
#include "AppMain.h"
#include "Progress.h"

#include <omnirange_sim/Simulator.h>

int main(int argc, char** argv)
{
	return omnirange::app::runApp("omnirange-sim", [&] {
		TCLAP::CmdLine cmd("omnirange-sim: simulate an omnicam robot and write an MRPT rawlog", ' ', "0.1");
		TCLAP::ValueArg<std::string> world("w", "world", "world file (docs/worlds.md)", true, "", "FILE", cmd);
		TCLAP::ValueArg<std::string> route("r", "route", "route file: one 'x y' waypoint per line [m]", true, "", "FILE", cmd);
		TCLAP::ValueArg<std::string> robot("c", "robot", "robot ini (default: built-in OmniP2DX-like robot)", false, "", "INI", cmd);
		TCLAP::ValueArg<std::string> out("o", "output", "rawlog to write (NAME.rawlog; images go to NAME_Images/)", true, "", "FILE", cmd);
		TCLAP::ValueArg<int> frames("n", "max-frames", "stop after this many frames (0: the whole route)", false, 0, "N", cmd);
		TCLAP::ValueArg<int> threads("j", "threads", "rendering threads", false, 2, "N", cmd);
		TCLAP::ValueArg<std::string> format("f", "image-format", "png or jpg, overriding the robot ini", false, "", "FMT", cmd);
		TCLAP::SwitchArg quiet("q", "quiet", "no progress or summary", cmd);
		omnirange::app::parseArgs(cmd, argc, argv);

		omnirange::sim::Simulator sim;
		sim.setMinLoggingLevel(quiet.getValue() ? mrpt::system::LVL_ERROR : mrpt::system::LVL_INFO);
		omnirange::sim::SimOptions o;
		o.world_file = world.getValue();
		o.route_file = route.getValue();
		o.robot_ini = robot.getValue();
		o.output = out.getValue();
		o.max_frames = frames.getValue();
		o.threads = threads.getValue();
		o.image_format = format.getValue();
		const auto s = sim.run(o, [&](int done, int total) {
			if (!quiet.getValue()) omnirange::app::showProgress("frames", done, total);
		});
		if (!quiet.getValue())
			std::printf("%d frames (%.1f s of route) in %.1f s: %.1f ms per frame\n", s.frames,
						s.route_seconds, s.wall_seconds, 1000.0 * s.wall_seconds / std::max(1, s.frames));
		return 0;
	});
}
