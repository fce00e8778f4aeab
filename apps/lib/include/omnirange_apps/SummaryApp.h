#pragma once
// omnirange-summary: the experiments' metrics.ini files -> one CSV and one
// Markdown page of tables (eval/Summary.h); or, from such a CSV, the tables
// inside docs/results.md and README.md made again (--fill), or checked (--check).

#include <mrpt/system/COutputLogger.h>

#include <string>
#include <vector>

namespace omnirange::app
{
class SummaryApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		std::string suite{"ini/suite.txt"};  ///< the experiment list
		std::vector<std::string> groups;  ///< only these groups of it (empty: all)
		std::string results{"results"};  ///< the folder of the reports, RESULTS/NAME/metrics.ini
		std::string output;  ///< prefix: PREFIX.csv and PREFIX.md
		std::string csv;  ///< instead of the reports: a CSV this program wrote
		std::vector<std::string> fill;  ///< Markdown files whose table blocks are made again from the CSV
		bool check{false};  ///< with fill: change nothing, fail if a block differs
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);
	/** --fill files that are one file twice, or the --csv itself, are refused. */
	static void requireDistinctFiles(const Options& o);

	explicit SummaryApp(Options o);
	/** Throws std::runtime_error naming a missing report or a stale table. */
	void run();

   private:
	/** `file` with its tables filled from `csv`, or "" when they are already
	 * (--check: throws when they are not); `state`: the file's as it was read
	 * (fileStateOf()). */
	std::string filledOrChecked(const std::string& file, const std::string& csv, std::string& state);
	Options o_;
};

}  // namespace omnirange::app
