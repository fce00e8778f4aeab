#pragma once
// omnirange-experiment as a class: one ini describes a whole experiment;
// run() simulates, trains, scans, measures the accuracy, builds maps with
// ground-truth poses, with MRPT's icp-slam and with the odometry-guarded
// matcher (GuardedIcp.h), and writes a report folder.
// One method per stage; the report is written from ExperimentResults.

#include <omnirange_eval/Accuracy.h>
#include <omnirange_eval/ExperimentConfig.h>
#include <omnirange_eval/GridMaps.h>
#include <omnirange_eval/Trajectory.h>
#include <omnirange_sim/Simulator.h>

#include <omnirange/train/ParameterLearning.h>
#include <omnirange/train/RawlogTraining.h>

#include <mrpt/system/COutputLogger.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace omnirange::eval
{
/** The numbers of a run, also written to the report folder's metrics.ini. */
using Metrics = std::map<std::string, double>;

/** One range sensor's maps: the laser's or the omnicam's. */
struct SensorMaps
{
	std::string label;  ///< its scans' sensor label
	std::string tag;  ///< lower-case name in file names ("laser", "omniscan")
	std::string map_ini, icp_ini;  ///< observations2map and icp-slam configurations
	bool invalid_is_free{true};  ///< see emptyLike()
	std::string rbpf_ini;  ///< rbpf-slam configuration; empty: not run
	MapMetrics gt, icp, guarded, rbpf;
	PathError icp_path, guarded_path, rbpf_path;
	int guarded_loops{0};  ///< loops the guarded matcher closed
	double gt_check_marked{0}, icp_check_marked{0};  ///< [m] in the check region
};

/** Everything a run measured: what the report and metrics.ini are made of. */
struct ExperimentResults
{
	sim::SimSummary simulated;
	int training_pairs{0};
	int training_until{0};  ///< pairs before this one trained on, the rest scored
	std::string learned;  ///< what learning chose, for the report (empty: not learned)
	/** The keys of the robot's camera (what made the images) that [rangefinder]'s
	 * camera (what reads them) gives otherwise; empty: the two agree. */
	std::vector<std::string> camera_mismatch;
	double omni_hit_fraction{0};
	ColourSeparation separation;  ///< of the colour model the scans ran with (ColourSeparation.h)
	AccuracyResult accuracy;
	std::vector<SensorMaps> sensors;  ///< the laser, then the omnicam
	PathError odometry_path;  ///< dead reckoning alone: what a scan matcher must beat
	bool has_check_region{false};  ///< the ini named one: the sensors' *_check_marked are measured
	double seconds{0};
};

/** The camera keys whose values differ between the camera that made the
 * images (the simulator's robot) and the one that reads them. */
std::vector<std::string> cameraMismatch(const CameraParams& made_by, const CameraParams& read_by);

/** The metrics.ini keys and values of a run. */
Metrics metricsOf(const ExperimentResults& r);
/** Whether `key` is one metricsOf() can write (a sensor's keys with any label
 * of letters, digits and '_'). */
bool isMetricKey(const std::string& key);
/** The report (Markdown; its figures are files beside it). */
std::string reportMarkdown(const ExperimentConfig& c, const ExperimentResults& r);

class Experiment : public mrpt::system::COutputLogger
{
   public:
	explicit Experiment(ExperimentConfig config);
	/** Runs every stage into a staging folder beside the report folder, and
	 * replaces the report folder with it when all succeeded; a failed stage
	 * throws std::runtime_error naming it, leaving the report folder as it was. */
	Metrics run();
	/** With learning on, also score every candidate it tried on the rest of
	 * the route against the truth, into `candidates_on_route.csv` in the
	 * report folder (CandidateStudy.h; a minute or more per run). */
	void setCandidateStudy(bool on) { study_candidates_ = on; }
	/** Replace a report folder this program did not write (never an input; config/Output.h). */
	void setForce(bool on) { force_ = on; }
	/** Progress lines within the long stages: only at INFO and below. */
	bool showsProgress() const { return getMinLoggingLevel() <= mrpt::system::LVL_INFO; }

   private:
	void setFolder(const std::string& dir);
	Metrics runStages();
	void stage(const std::string& name, const std::function<void()>& body);
	void simulate();
	void train();
	/** Learns the parameters on the training part; the scan stage then uses them. */
	void learn(const RawlogTrainingOptions& o);
	void scan();
	void measureAccuracy();
	void mapWithGroundTruth();
	void runIcpSlam();
	void runGuardedIcp();
	void runRbpfSlam();
	void writeReport();
	/** A built map against the true map: its figure, check region and metrics. */
	MapMetrics assess(const mrpt::maps::COccupancyGridMap2D& map, const std::string& title, double& check_marked,
					  std::vector<std::pair<std::string, cv::Mat>>& figures) const;
	/** The report's folder of `engine`'s run for the sensor `tag` ("icp_slam_omniscan"):
	 * where an MRPT program's ini must send its logOutput_dir. */
	static std::string slamFolder(const std::string& engine, const std::string& tag);
	/** Writes the MRPT program's `ini` as it was checked (ExperimentConfig::mrpt_ini_text) into the
	 * report as `name`, and returns `name`: the program is given this copy, not the file. */
	std::string mrptIni(const std::string& ini, const std::string& name) const;
	/** A SLAM engine's final map and path for one sensor, against the truth:
	 * the map in `dir`/_finalmap_.simplemap of the report. */
	void scoreSlam(const std::string& engine, const std::string& dir, const SensorMaps& s, MapMetrics& map,
				   PathError& path, double& check_marked, std::vector<std::pair<std::string, cv::Mat>>& figures) const;

	ExperimentConfig c_;
	std::string out_, dataset_, histogram_, scanned_;  // absolute paths
	ColourModel histogram_data_;
	mrpt::maps::COccupancyGridMap2D truth_;
	std::vector<StampedPose> gt_path_;
	ExperimentResults r_;
	int stage_{0}, stages_{0};
	bool study_candidates_{false}, force_{false};
};

}  // namespace omnirange::eval
