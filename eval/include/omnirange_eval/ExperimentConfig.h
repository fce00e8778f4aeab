#pragma once
// An experiment's ini: [experiment] names the world, route, robot, MRPT
// configurations and the report folder; [rangefinder] the method's keys.

#include <omnirange/core/Rangefinder.h>
#include <omnirange/train/HistogramTrainer.h>
#include <omnirange/train/ParameterLearning.h>
#include <omnirange/config/OptionsTable.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace omnirange::eval
{
struct ExperimentConfig
{
	std::string ini_file;  ///< the experiment's own ini (not a key)
	std::string name{"experiment"};
	std::string world, route, robot;  ///< files, relative to the ini's folder
	std::vector<std::string> world_maps;  ///< the grid maps the world names (inputs too)
	std::string output;  ///< the report folder
	std::string icp_laser_ini, icp_omni_ini;  ///< icp-slam configurations
	/** rbpf-slam configurations (a particle filter); empty: rbpf-slam is not run for that sensor. */
	std::string rbpf_laser_ini, rbpf_omni_ini;
	std::string map_laser_ini, map_omni_ini;  ///< observations2map configurations
	/** The FUSED scan's icp-slam and observations2map configurations; both
	 * empty: no FUSED scan is made (core/ScanFusion.h). */
	std::string icp_fused_ini, map_fused_ini;
	bool fuses() const { return !icp_fused_ini.empty(); }
	int max_frames{0};  ///< 0: the whole route
	int train_every{3};  ///< train on every N-th image/scan pair
	/** Train on the route's first part, this fraction of its frames, and
	 * score on the rest (never on what was trained on). */
	double train_fraction{0.2};
	/** Learn colour space, bins, Theta, obstacle_ratio, N, K and the boundary model against the laser
	 * on held-aside training pairs (ParameterLearning.h) instead of taking
	 * [rangefinder]'s and [training]'s. */
	bool learn{false};
	TrainingParams training;  ///< [training], as omnirange-train reads it
	LearningOptions learning;  ///< [learning], with learn
	double match_tolerance{0.10};  ///< [m] a built map's cell within this of a true wall is correct
	/** "x y w d" [m]: a box whose occupied cells the report measures (empty: none). */
	std::string check_region;
	std::array<double, 4> check_box{};  ///< check_region parsed (not a key)
	RangefinderParams rangefinder;
	/** Each MRPT program's ini (icp-slam's, observations2map's, rbpf-slam's)
	 * as it was checked, by its path (not a key): the program is given a copy
	 * of these bytes, whatever the file holds by the time it runs. */
	std::map<std::string, std::string> mrpt_ini_text;

	bool hasCheckRegion() const { return !check_region.empty(); }
	/** The frames the simulation will make: the route's, at most max_frames. */
	int plannedFrames() const;
	/** The frames of `frames` trained on: the first train_fraction (one at least). */
	int trainingFrames(int frames) const;
	/** Throws std::runtime_error, before any stage, when the planned frames
	 * leave none to score after training, or (learn) too few pairs to train
	 * and validate on: max_frames (or -n) may be small. */
	void requireEnoughFrames() const;
	/** Throws std::runtime_error naming the first MRPT program's ini that
	 * holds other bytes now than when it was checked (edited meanwhile). */
	void requireMrptInisAsChecked() const;

	static const OptionsTable<ExperimentConfig>& table();
	/** Reads [experiment] and [rangefinder] of `ini` and checks everything
	 * (keys, files, values, the world, the route) before any stage runs.
	 * Throws std::runtime_error with one clear message. */
	static ExperimentConfig load(const std::string& ini);
};

}  // namespace omnirange::eval
