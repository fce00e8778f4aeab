#pragma once
// omnirange-experiment: one ini -> simulate, train, scan, accuracy, maps,
// icp-slam, and a report folder (Markdown with figures and tables).

#include <omnirange_eval/Experiment.h>

namespace omnirange::app
{
class ExperimentApp
{
   public:
	struct Options
	{
		std::string ini;
		std::string output;  ///< overrides the ini's report folder when not empty
		int max_frames{-1};  ///< overrides the ini's when >= 0
		std::string robot;  ///< overrides the ini's robot when not empty (e.g. the lossless camera)
		bool study_candidates{false};  ///< Experiment::setCandidateStudy
		bool force{false};  ///< replace a report folder this program did not write (config/Output.h)
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit ExperimentApp(Options o) : o_(std::move(o)) {}
	eval::Metrics run();

   private:
	Options o_;
};

}  // namespace omnirange::app
