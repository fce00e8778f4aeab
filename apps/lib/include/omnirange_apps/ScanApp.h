#pragma once
// omnirange-scan: rawlog + histogram + ini -> the same rawlog with a range
// scan right after every omnicam image.

#include <omnirange/io/RawlogScan.h>

#include <mrpt/system/COutputLogger.h>

#include <string>
#include <vector>

namespace omnirange::app
{
class ScanApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		std::string ini, section{kRangefinderSection}, histogram;
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

/** What a scan's summary should warn a user of, a line each: grey images
 * scanned with a histogram `trained_on_colour` (ColourModel); almost no hit
 * at all (a histogram of another floor, light or camera), or else many rays
 * ended at the base (the floor just beyond it not seen as free). */
std::vector<std::string> scanWarnings(const RawlogScanSummary& s, const std::string& histogram,
									  bool trained_on_colour = false);

}  // namespace omnirange::app
