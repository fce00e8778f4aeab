#pragma once
// omnirange-calibrate: fit the mirror's R (paraboloid) or alpha (first-order
// model) against a laser (paper §IV-D), and say where the boundary sits.

#include <omnirange/train/MirrorCalibration.h>

#include <mrpt/system/COutputLogger.h>

namespace omnirange::app
{
class CalibrateApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		std::string ini, section{"rangefinder"}, histogram;
		MirrorCalibrationOptions calibration;
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit CalibrateApp(Options o);
	/** Fits and prints the result on stdout. */
	MirrorCalibration run();

   private:
	Options o_;
};

}  // namespace omnirange::app
