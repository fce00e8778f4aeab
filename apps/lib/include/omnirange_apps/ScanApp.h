#pragma once
// omnirange-scan: rawlog + histogram + ini -> the same rawlog with a range
// scan right after every omnicam image.

#include <omnirange/io/RawlogScan.h>

#include <mrpt/system/COutputLogger.h>

namespace omnirange::app
{
class ScanApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		std::string ini, section{"rangefinder"}, histogram;
		RawlogScanOptions scan;
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit ScanApp(Options o);
	RawlogScanSummary run();

   private:
	Options o_;
};

}  // namespace omnirange::app
