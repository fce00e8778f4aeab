#pragma once
// One scan from the laser and the omnicam of one robot (docs/method.md,
// "The fused scan"). A planar laser misses what is above or below its plane
// (a table top, a rack's low board); the omnicam sees where the floor ends in
// front of them, but not an obstacle of the floor's colour. Each ray of the
// fused scan is the nearer of the laser's return at that bearing and a
// confident omnicam hit; where the omnicam is unsure the laser's word stands;
// outside the laser's field of view the omnicam's ray stands alone.

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace omnirange
{
/** A laser ray seen from another sensor of the robot: its bearing [rad] and
 * range [m] from there, in that sensor's frame. */
struct RaySeenFrom
{
	double bearing;
	double range;
};

/** Ray i of `laser` seen from a sensor at pose `from` on the robot (a ray
 * without a return is taken at the laser's max range: its direction). */
RaySeenFrom laserRaySeenFrom(const mrpt::obs::CObservation2DRangeScan& laser, std::size_t i,
							 const mrpt::poses::CPose3D& from);

/** The ray of a scan over the full circle (S rays, aperture 2 pi (S-1)/S)
 * nearest to `bearing` [rad]. */
int nearestRay(const mrpt::obs::CObservation2DRangeScan& scan, double bearing);

/** What the laser says along one ray of the omnicam's scan. */
struct LaserReading
{
	enum class Kind
	{
		Unseen,  ///< outside the laser's field of view
		Return,  ///< a return at `range` [m] from the omnicam
		NoReturn  ///< nothing within the laser's max range
	};
	Kind kind{Kind::Unseen};
	double range{0};
};

/** Along every ray of `omni`, the nearest laser return whose bearing from the
 * omnicam falls on it. A ray between two neighbouring laser rays that no laser
 * ray falls on (the sensors' offset spreads the rays; a coarse laser) takes the
 * nearer reading of those two. */
std::vector<LaserReading> laserAlong(const mrpt::obs::CObservation2DRangeScan& laser,
									 const mrpt::obs::CObservation2DRangeScan& omni);

/** The intensity of a fused ray: which sensor it came from. Every value is at
 * least kFullConfidence, so rayIsUnsure() holds only for an unsure omnicam ray
 * outside the laser's view, which keeps its confidence. */
enum class FusedSource : int
{
	Laser = 101,  ///< the laser's return, or its no-return (invalid: free to its max range)
	Omnicam = 102,  ///< a confident omnicam hit nearer than the laser's
	OmnicamAlone = 103  ///< outside the laser's field of view: the omnicam's ray as it was
};

/** The fused scan: `omni`'s rays, frame, pose and time, maxRange the larger of
 * the two sensors', labelled kFusedLabel. `laser` is taken at the same moment. */
mrpt::obs::CObservation2DRangeScan::Ptr fuseScans(const mrpt::obs::CObservation2DRangeScan& omni,
												  const mrpt::obs::CObservation2DRangeScan& laser);

}  // namespace omnirange
