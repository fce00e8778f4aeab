#pragma once
// omnirange-import: a folder of timestamped omnicam images, a laser log
// (CSV) and odometry (CSV) -> an observations-only rawlog with labels,
// sensor poses and external images (io/LogImport.h has the formats).

#include <omnirange/core/Rangefinder.h>
#include <omnirange/io/LogImport.h>

#include <mrpt/system/COutputLogger.h>

namespace omnirange::app
{
class ImportApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		LogImportOptions import;
		std::string ini, section{kRangefinderSection};  ///< if given: the omnicam's pose (pose_* keys) from it
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit ImportApp(Options o);
	/** Writes the rawlog; throws on any bad input, naming the file and line. */
	LogImportSummary run();

   private:
	Options o_;
};

/** The value of `option`, "x y z yaw_deg [pitch_deg roll_deg]" (offsets within
 * kMaxMountOffset, angles within kMaxMountAngle) -> a pose; throws
 * std::invalid_argument naming the option. */
mrpt::poses::CPose3D poseFromText(const std::string& option, const std::string& text);

}  // namespace omnirange::app
