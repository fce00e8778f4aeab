#pragma once
// omnirange-train: rawlog with omnicam images and laser scans -> colour
// histogram of the free floor (paper §III-A1), and the images of Fig. 1.

#include <omnirange/train/ParameterLearning.h>
#include <omnirange/train/RawlogTraining.h>

#include <mrpt/system/COutputLogger.h>

namespace omnirange::app
{
class TrainApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		std::string output;  ///< histogram file to write
		std::string ini, section{kRangefinderSection};
		RawlogTrainingOptions training;  ///< run() reads its [training] keys from `ini` over these
		/** If not empty: learn the parameters too (ParameterLearning.h) and
		 * write them, as a [rangefinder] section, to this ini. */
		std::string learn_ini;
		std::string learn_candidates;  ///< with learn_ini: every candidate and its score, as CSV
		LearningOptions learning;  ///< run() reads its [learning] keys from `ini` over these
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit TrainApp(Options o);
	/** Trains and saves the histogram (and, with learn_ini, learns the
	 * parameters); throws on any bad input. */
	RawlogTrainingResult run();

   private:
	RawlogTrainingResult learn(const RangefinderParams& params);
	/** What no output may be: the rawlog, its images, the ini. */
	std::vector<std::string> inputs() const;
	void logSeparation(const ColourSeparation& s);

	Options o_;
};

}  // namespace omnirange::app
