#pragma once
// Where the floor really ends, seen from the omnicam: along each bearing the
// first floor point the camera cannot see (a solid standing on the floor
// hides it from its foot on; one that floats, like a shelf, from where the
// sight line first grazes its underside). The simulator writes it into the
// dataset as a CObservation2DRangeScan labelled TRUTH, so every stage can
// score against the truth as well as against the laser.
//
// Beside it, what the robot would strike: along each bearing the nearest
// solid below the robot's strike height, whatever the camera sees of it
// (labelled BODY). A floating body is struck at its face, t_in, where the
// floor truth puts it farther, at t_in h / (h - z0).

#include <omnirange_sim/RobotParams.h>
#include <omnirange_sim/Route.h>
#include <omnirange_sim/World.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace omnirange::sim
{
/** The distance [m] along a ray from the camera's foot at which the floor
 * first hides behind one of `crossings` (sorted by entry, as castRay gives
 * them), seen from height h [m]; +inf if none hides it. */
double hiddenFloorDistance(const World& world, const std::vector<SolidCrossing>& crossings, double h);

/** The distance [m] along a ray at which it first meets one of `crossings`
 * that has some part between the floor and `strike_height` [m]; +inf if none. */
double struckDistance(const World& world, const std::vector<SolidCrossing>& crossings, double strike_height);

/** The truth scan at robot pose `robot`: `rays` rays laid out like the
 * rangefinder's scanlines (over 2 pi (S-1)/S, ray i at scanlineBearing(i, S)),
 * sensorPose the omnicam's, valid where the floor ends within `max_range`. */
mrpt::obs::CObservation2DRangeScan::Ptr floorTruth(const World& world, const OmnicamSimParams& omnicam,
												   const Pose2& robot, int rays, double max_range);

/** The BODY scan: laid out as floorTruth(), each ray the struckDistance()
 * below `strike_height`, valid within `max_range`. */
mrpt::obs::CObservation2DRangeScan::Ptr bodyTruth(const World& world, const OmnicamSimParams& omnicam,
												  const Pose2& robot, int rays, double max_range, double strike_height);

}  // namespace omnirange::sim
