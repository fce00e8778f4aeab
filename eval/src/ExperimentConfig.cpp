#include "omnirange_eval/ExperimentConfig.h"
#include <omnirange_slam/IcpSlamIni.h>
#include <omnirange_slam/MrptMapSections.h>

#include <omnirange_sim/Route.h>
#include <omnirange_sim/RobotParams.h>
#include <omnirange_sim/World.h>

#include <omnirange/config/LayeredIni.h>
#include <omnirange/train/ParameterLearning.h>
#include <omnirange/train/RawlogTraining.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace omnirange::eval
{
const OptionsTable<ExperimentConfig>& ExperimentConfig::table()
{
	using C = ExperimentConfig;
	static const auto t = OptionsTable<C>()
		.add("name", "-", "the experiment's name: the dataset's file name and the report's title", [](C& c) -> auto& { return c.name; })
		.add("world", "file", "world file (docs/worlds.md)", [](C& c) -> auto& { return c.world; })
		.add("route", "file", "route file: one 'x y' waypoint per line", [](C& c) -> auto& { return c.route; })
		.add("robot", "file", "robot ini for the simulator", [](C& c) -> auto& { return c.robot; })
		.add("output", "folder", "report folder", [](C& c) -> auto& { return c.output; })
		.add("max_frames", "-", "simulate at most this many frames (0: the whole route)", [](C& c) -> auto& { return c.max_frames; })
		.add("train_every", "-", "train on every N-th image/scan pair", [](C& c) -> auto& { return c.train_every; })
		.add("train_fraction", "-", "train on this first fraction of the route, score on the rest",
			 [](C& c) -> auto& { return c.train_fraction; })
		.add("learn", "bool", "learn colour space, bins, threshold, obstacle_ratio, N, K and the boundary model against the laser",
			 [](C& c) -> auto& { return c.learn; })
		.renamed("colour_space", "set colour_space in [training], as omnirange-train reads it")
		.renamed("bins", "set bins in [training], as omnirange-train reads it")
		.renamed("obstacle_band", "set obstacle_band in [training], as omnirange-train reads it")
		.add("match_tolerance", "m", "a map's occupied cell within this of a true wall counts as correct",
			 [](C& c) -> auto& { return c.match_tolerance; })
		.add("icp_laser_ini", "file", "icp-slam configuration for the laser", [](C& c) -> auto& { return c.icp_laser_ini; })
		.add("icp_omni_ini", "file", "icp-slam configuration for the omnicam", [](C& c) -> auto& { return c.icp_omni_ini; })
		.add("rbpf_laser_ini", "file", "rbpf-slam configuration for the laser (empty: not run)",
			 [](C& c) -> auto& { return c.rbpf_laser_ini; })
		.add("rbpf_omni_ini", "file", "rbpf-slam configuration for the omnicam (empty: not run)",
			 [](C& c) -> auto& { return c.rbpf_omni_ini; })
		.add("map_laser_ini", "file", "observations2map configuration for the laser", [](C& c) -> auto& { return c.map_laser_ini; })
		.add("map_omni_ini", "file", "observations2map configuration for the omnicam", [](C& c) -> auto& { return c.map_omni_ini; })
		.add("icp_fused_ini", "file", "icp-slam configuration for the FUSED scan (empty, with map_fused_ini: no FUSED scan)",
			 [](C& c) -> auto& { return c.icp_fused_ini; })
		.add("map_fused_ini", "file", "observations2map configuration for the FUSED scan",
			 [](C& c) -> auto& { return c.map_fused_ini; })
		.add("check_region", "m", "'x y w d': a box whose marked wall length the report gives", [](C& c) -> auto& { return c.check_region; })
		.renamed("map_resolution", "remove it: the maps take the resolution of the world's true map");
	return t;
}

namespace
{
/** The bytes of `path` ("" if it cannot be read: its checks say why). */
std::string textOf(const std::string& path)
{
	// Not a FIFO (it would block) nor more than an ini can be: those its checks refuse.
	std::error_code ec;
	if (!fs::is_regular_file(path, ec) || fs::file_size(path, ec) > (1u << 20)) return "";
	std::ifstream f(path, std::ios::binary);
	std::ostringstream text;
	text << f.rdbuf();
	return text.str();
}
/** Resolves the files the [experiment] section names, each against the
 * folder of the ini that names it (the experiment's own, or a base's). */
void resolvePaths(ExperimentConfig& c, const LayeredIni& layers)
{
	const auto resolve = [&](std::string& v, const std::string& key, bool must_exist) {
		if (v.empty()) throw std::invalid_argument("[experiment] " + key + " is missing");
		const std::string from = layers.originOf("experiment", key);
		const fs::path dir = iniFolderOf(from.empty() ? layers.files.back() : from);
		v = fs::path(v).is_absolute() ? v : (dir / v).lexically_normal().string();
		if (must_exist && !fs::is_regular_file(v))
			throw std::invalid_argument("[experiment] " + key + ": " + (fs::exists(v) ? "not a regular file" : "no file") +
										" '" + v + "'");
	};
	resolve(c.world, "world", true), resolve(c.route, "route", true), resolve(c.robot, "robot", true);
	resolve(c.output, "output", false);
	resolve(c.icp_laser_ini, "icp_laser_ini", true), resolve(c.icp_omni_ini, "icp_omni_ini", true);
	resolve(c.map_laser_ini, "map_laser_ini", true), resolve(c.map_omni_ini, "map_omni_ini", true);
	if (!c.icp_fused_ini.empty() || !c.map_fused_ini.empty())
		resolve(c.icp_fused_ini, "icp_fused_ini", true), resolve(c.map_fused_ini, "map_fused_ini", true);
	if (!c.rbpf_laser_ini.empty()) resolve(c.rbpf_laser_ini, "rbpf_laser_ini", true);
	if (!c.rbpf_omni_ini.empty()) resolve(c.rbpf_omni_ini, "rbpf_omni_ini", true);
}

void validate(ExperimentConfig& c)
{
	// The name becomes file names inside the report folder: it may not lead out of it.
	require(!c.name.empty() && c.name != "." && c.name != ".." && c.name.find('/') == std::string::npos,
			"[experiment] name must be a plain name (no '/'), not '" + c.name + "'");
	require(c.max_frames >= 0, "[experiment] max_frames must be >= 0");
	require(c.train_every >= 1, "[experiment] train_every must be >= 1");
	require(c.train_fraction > 0 && c.train_fraction < 1, "[experiment] train_fraction must be within (0, 1)");
	// Learning tries bins and twice as many: within what a report's histograms hold.
	require(c.training.bins <= 64, "[training] bins must be within [1, 64] in an experiment");
	require(c.match_tolerance >= 0, "[experiment] match_tolerance must be >= 0 m");
	if (!c.hasCheckRegion()) return;
	std::istringstream in(c.check_region);
	for (auto& v : c.check_box)
		if (!(in >> v)) throw std::invalid_argument("[experiment] check_region must be 'x y w d' in metres");
}

/** The inputs of later stages, checked now: the robot, the world, the route. */
void checkSimulatorInputs(ExperimentConfig& c)
{
	const auto robot = sim::RobotParams::loadFile(c.robot);
	const auto world = sim::loadWorld(c.world);
	c.world_maps = world.maps;
	sim::checkRouteClear(sim::loadRoute(c.route), world, robot.robot.clearance, robot.omnicam.camera.h);
}
}  // namespace

int ExperimentConfig::plannedFrames() const
{
	const auto r = sim::RobotParams::loadFile(robot).robot;
	const auto legs = sim::loadRoute(route);
	try
	{
		return static_cast<int>(sim::sampleTrajectory(legs, r.speed, r.turn_rate, 1.0 / r.frame_rate, max_frames).size());
	}
	catch (const std::runtime_error& e)
	{
		throw std::runtime_error("'" + route + "': " + e.what());
	}
}

int ExperimentConfig::trainingFrames(int frames) const
{
	return std::max(1, static_cast<int>(std::lround(train_fraction * frames)));
}

void ExperimentConfig::requireEnoughFrames() const
{
	const int frames = plannedFrames(), trained_on = trainingFrames(frames);
	const std::string planned = std::to_string(frames) + " frames (" + (max_frames > 0 ? "max_frames or -n" : "the route's") + ")";
	if (trained_on >= frames)
		throw std::runtime_error(planned + " leave none to score after training on the first " +
								 std::to_string(trained_on) + " (train_fraction " + formatDouble(train_fraction) + ")");
	RawlogTrainingOptions training;
	training.every = train_every, training.until = trained_on;
	int selected = 0;
	for (int k = 0; k < trained_on; ++k) selected += training.selects(k);
	if (learn && !enoughToLearn(learning, selected))
		throw std::runtime_error(planned + " give " + std::to_string(selected) +
								 (selected == 1 ? " training pair" : " training pairs") + " (train_fraction " + formatDouble(train_fraction) + ", train_every " +
								 std::to_string(train_every) + "): too few for learn = true to train on some and validate on others");
}

void ExperimentConfig::requireMrptInisAsChecked() const
{
	for (const auto& [ini, text] : mrpt_ini_text)
		if (textOf(ini) != text)
			throw std::runtime_error("'" + ini + "' changed while the experiment checked it (an edit meanwhile): run it " +
									 "again");
}

ExperimentConfig ExperimentConfig::load(const std::string& ini)
{
	if (!fs::is_regular_file(ini)) throw std::runtime_error("cannot open experiment ini '" + ini + "'");
	ExperimentConfig c;
	c.ini_file = ini;
	const LayeredIni layers = readLayeredIni(ini);
	try
	{
		const auto& cfg = *layers.merged;
		table().load(c, cfg, "experiment");
		// Loaded with their ranges checked: a bad value fails before the simulation, not after it.
		if (cfg.sectionExists(kTrainingSection)) TrainingParams::table().load(c.training, cfg, kTrainingSection);
		if (cfg.sectionExists(kLearningSection)) LearningOptions::table().load(c.learning, cfg, kLearningSection);
		resolvePaths(c, layers);
		// What is checked is what the programs get: their inis' bytes, taken first (requireMrptInisAsChecked()).
		for (const auto* mrpt_ini : {&c.icp_laser_ini, &c.icp_omni_ini, &c.icp_fused_ini, &c.map_laser_ini,
									 &c.map_omni_ini, &c.map_fused_ini, &c.rbpf_laser_ini, &c.rbpf_omni_ini})
			if (!mrpt_ini->empty()) c.mrpt_ini_text[*mrpt_ini] = textOf(*mrpt_ini);
		// Every ini handed to an MRPT program read as strictly as MRPT's own keys allow, before any work.
		slam::requireStrictIcpSection(c.icp_laser_ini), slam::requireStrictIcpSection(c.icp_omni_ini);
		slam::requireStrictObservationsToMapIni(c.map_laser_ini), slam::requireStrictObservationsToMapIni(c.map_omni_ini);
		if (c.fuses()) slam::requireStrictIcpSection(c.icp_fused_ini), slam::requireStrictObservationsToMapIni(c.map_fused_ini);
		for (const auto* rbpf : {&c.rbpf_laser_ini, &c.rbpf_omni_ini})
			if (!rbpf->empty()) slam::requireStrictRbpfIni(*rbpf);
		validate(c);
		c.rangefinder.loadFromConfig(cfg, kRangefinderSection);
		checkSimulatorInputs(c);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(namingItsFile(layers, ini, e));
	}
	return c;
}

}  // namespace omnirange::eval
