#pragma once
// omnirange-slam: a rawlog with scans and odometry -> a path and the keyframes
// of a map, by the odometry-guarded matcher (omnirange_slam/GuardedIcp.h),
// configured by an icp-slam ini. Its outputs are icp-slam's kind:
// DIR/_finalmap_.simplemap (for observations2map, RawLogViewer) and
// DIR/log_estimated_path.txt.

#include <omnirange_slam/GuardedIcp.h>

#include <mrpt/system/COutputLogger.h>

#include <string>

namespace omnirange::app
{
class SlamApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		std::string input;
		std::string ini;  ///< an icp-slam ini, with optional [odometry_guard] and [loop_closure] sections
		std::string output;  ///< folder
		std::string scan_label{"OMNISCAN"};
		std::string odometry_label{"ODOMETRY"};
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit SlamApp(Options o);
	slam::GuardedIcpResult run();

   private:
	Options o_;
};

}  // namespace omnirange::app
