#include "omnirange_eval/Experiment.h"

#include <omnirange/Config.h>
#include <omnirange_sim/Route.h>
#include <omnirange_sim/RobotParams.h>
#include <omnirange_sim/World.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

namespace omnirange::eval
{
std::vector<std::string> ExperimentConfig::keys()
{
	return {"name",		   "world",			"route",		 "robot",		  "output",
			"max_frames",  "train_every",	"map_resolution", "match_tolerance", "icp_laser_ini",
			"icp_omni_ini", "map_laser_ini", "map_omni_ini", "check_region"};
}

ExperimentConfig ExperimentConfig::load(const std::string& ini)
{
	if (!fs::is_regular_file(ini)) throw std::runtime_error("cannot open experiment ini '" + ini + "'");
	ExperimentConfig c;
	c.ini_file = ini;
	const fs::path dir = fs::absolute(ini).parent_path();
	const auto fail = [&](const std::string& what) { return std::runtime_error(ini + ": " + what); };
	try
	{
		const mrpt::config::CConfigFile cfg(ini);
		const std::string s = "experiment";
		requireParam(cfg.sectionExists(s), s, "section not found");
		requireKnownKeys(cfg, s, keys());
		const auto path = [&](const std::string& key, bool must_exist) {
			const std::string v = cfg.read_string(s, key, "", true);
			const std::string p = fs::path(v).is_absolute() ? v : (dir / v).lexically_normal().string();
			if (must_exist && !fs::is_regular_file(p)) throw std::invalid_argument(key + ": no file '" + p + "'");
			return p;
		};
		c.name = cfg.read_string(s, "name", c.name);
		c.world = path("world", true);
		c.route = path("route", true);
		c.robot = path("robot", true);
		c.output = path("output", false);
		c.icp_laser_ini = path("icp_laser_ini", true);
		c.icp_omni_ini = path("icp_omni_ini", true);
		c.map_laser_ini = path("map_laser_ini", true);
		c.map_omni_ini = path("map_omni_ini", true);
		c.max_frames = cfg.read_int(s, "max_frames", c.max_frames);
		c.train_every = cfg.read_int(s, "train_every", c.train_every);
		c.map_resolution = cfg.read_double(s, "map_resolution", c.map_resolution);
		c.match_tolerance = cfg.read_double(s, "match_tolerance", c.match_tolerance);
		const std::string region = cfg.read_string(s, "check_region", "");
		if (!region.empty())
		{
			std::istringstream in(region);
			for (auto& v : c.check_region)
				if (!(in >> v)) throw std::invalid_argument("check_region must be 'x y w d' in metres");
			c.has_check_region = true;
		}
		requireParam(c.max_frames >= 0, s, "max_frames must be >= 0");
		requireParam(c.train_every >= 1, s, "train_every must be >= 1");
		requireParam(c.map_resolution > 0 && c.map_resolution < 1, s, "map_resolution must be in (0, 1) m");
		requireParam(c.match_tolerance >= 0, s, "match_tolerance must be >= 0 m");
		c.rangefinder.loadFromConfig(cfg, "rangefinder");
		// The inputs of later stages, checked now.
		sim::RobotParams robot;
		try
		{
			robot.loadFromConfig(mrpt::config::CConfigFile(c.robot));
		}
		catch (const std::invalid_argument& e)
		{
			throw std::runtime_error(c.robot + ": " + e.what());
		}
		const auto world = sim::loadWorld(c.world);
		sim::checkRouteClear(sim::loadRoute(c.route), world, robot.robot.clearance, robot.omnicam.camera.h);
	}
	catch (const std::invalid_argument& e)
	{
		throw fail(e.what());
	}
	return c;
}

}  // namespace omnirange::eval
