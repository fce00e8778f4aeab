#pragma once
// A route: waypoints the robot drives through, straight between them, turning
// on the spot at each. Read from a route file (docs/worlds.md).

#include <omnirange_sim/World.h>

#include <string>
#include <vector>

namespace omnirange::sim
{
struct Pose2
{
	double x{0}, y{0}, yaw{0};
};

struct Route
{
	std::string file;
	std::vector<Vec2> waypoints;
	std::vector<int> lines;  ///< file line of each waypoint
};

/** Reads "x y" lines (metres); '#' starts a comment. Throws
 * std::runtime_error "FILE:LINE: message". */
Route loadRoute(const std::string& path);

/** Throws std::runtime_error naming the route's line and the world's line if
 * a leg passes closer than `clearance` [m] to a solid that reaches below
 * `robot_height` [m]. */
void checkRouteClear(const Route& route, const World& world, double clearance, double robot_height);

/** The most frames one route may give: each is an image of 0.1 to 1 MB and
 * a fraction of a second's rendering, so this is hours of driving and tens
 * of GB; a route past it is a slip (a speed or coordinates off by powers of
 * ten), found before anything is written. */
constexpr int kMaxRouteFrames = 100000;

/** Poses every `dt` seconds driving at `speed` [m/s], turning at `turn_rate`
 * [rad/s]; the first pose faces the first leg. Stops after `max_frames`
 * poses (0: the whole route); throws std::runtime_error, before sampling,
 * when that would be more than kMaxRouteFrames. */
std::vector<Pose2> sampleTrajectory(
	const Route& route, double speed, double turn_rate, double dt, int max_frames = 0);

}  // namespace omnirange::sim
