#pragma once
// omnirange-sim: world file + route + robot ini -> MRPT rawlog (omnicam,
// laser, odometry, ground truth) with external images, plus the world's
// true map.

#include <omnirange_sim/Simulator.h>

namespace omnirange::app
{
class SimApp
{
   public:
	struct Options
	{
		sim::SimOptions sim;
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit SimApp(Options o) : o_(std::move(o)) {}
	sim::SimSummary run();

   private:
	Options o_;
};

}  // namespace omnirange::app
