#pragma once
// omnirange-accuracy: a rawlog with laser and omnicam scans -> the paper's
// accuracy test: every pair in a CSV, a histogram like Fig. 9, a table like
// Table II (Markdown), with the exclusions counted.

#include <omnirange_eval/Accuracy.h>

#include <mrpt/system/COutputLogger.h>

namespace omnirange::app
{
class AccuracyApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		std::string input;
		std::string output;  ///< prefix: PREFIX_pairs.csv, PREFIX_histogram.png, PREFIX_table.md
		std::string title;  ///< of the histogram (default: the input's name)
		eval::AccuracyOptions accuracy;
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit AccuracyApp(Options o);
	/** Writes the three outputs; prints the table at INFO. */
	eval::AccuracyResult run();

   private:
	Options o_;
};

}  // namespace omnirange::app
