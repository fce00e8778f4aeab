#pragma once
// omnirange-sim as a class: world + route + robot ini -> rawlog with OMNICAM,
// LASER, ODOMETRY and GT, the images beside it, and the world's true map.

#include <omnirange_sim/RobotParams.h>
#include <omnirange_sim/World.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/system/COutputLogger.h>

#include <functional>
#include <string>

namespace omnirange::sim
{
struct SimOptions
{
	std::string world_file;
	std::string route_file;
	std::string robot_ini;  ///< empty: the built-in robot defaults
	std::string output;  ///< the rawlog to write, NAME.rawlog
	int max_frames{0};  ///< 0: the whole route
	int threads{2};
	std::string image_format;  ///< png or jpg; empty: the robot ini's
	double map_resolution{0.05};  ///< [m] of the true grid map
	/** Replace an output (or NAME_Images) no program of ours wrote (never an input; config/Output.h). */
	bool force{false};
};

struct SimSummary
{
	int frames{0};
	double route_seconds{0};
	double wall_seconds{0};
};

/** The world's true map: cells covered by a solid that reaches below
 * `below` [m] are occupied, the rest free. */
mrpt::maps::COccupancyGridMap2D trueMap(const World& world, double resolution, double below);

class Simulator : public mrpt::system::COutputLogger
{
   public:
	Simulator();
	/** Writes options.output, NAME_Images/, NAME_truemap.png and
	 * NAME_truemap.gridmap.gz. Throws with a message naming the bad file. */
	SimSummary run(const SimOptions& options,
				   const std::function<void(int done, int total)>& progress = {});
};

}  // namespace omnirange::sim
