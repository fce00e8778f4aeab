#pragma once
// omnirange-experiment as a class: one ini describes a whole experiment;
// run() simulates, trains, scans, measures the accuracy, builds maps with
// ground-truth poses and with MRPT's icp-slam, and writes a report folder.

#include <omnirange/Rangefinder.h>

#include <mrpt/system/COutputLogger.h>

#include <array>
#include <map>
#include <string>

namespace omnirange::eval
{
struct ExperimentConfig
{
	std::string ini_file;  ///< the experiment's own ini
	std::string name{"experiment"};
	std::string world, route, robot;  ///< files, relative to the ini's folder
	std::string output;  ///< the report folder
	std::string icp_laser_ini, icp_omni_ini;  ///< icp-slam configurations
	std::string map_laser_ini, map_omni_ini;  ///< observations2map configurations
	int max_frames{0};  ///< 0: the whole route
	int train_every{3};
	double map_resolution{0.05};  ///< [m]
	double match_tolerance{0.10};  ///< [m]
	bool has_check_region{false};
	std::array<double, 4> check_region{};  ///< x y w d [m]
	RangefinderParams rangefinder;

	/** Reads [experiment] and [rangefinder] of `ini` and checks everything
	 * (keys, files, values, the world, the route) before any stage runs.
	 * Throws std::runtime_error with one clear message. */
	static ExperimentConfig load(const std::string& ini);
	static std::vector<std::string> keys();
};

/** The numbers of a run, also written to the report folder's metrics.ini. */
using Metrics = std::map<std::string, double>;

class Experiment : public mrpt::system::COutputLogger
{
   public:
	Experiment();
	/** Runs every stage; a failed stage throws std::runtime_error naming it. */
	Metrics run(const ExperimentConfig& config);
};

}  // namespace omnirange::eval
