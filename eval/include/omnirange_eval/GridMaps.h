#pragma once
// Occupancy grid maps built from range scans at known poses, drawn in the
// paper's style, and compared with the world's true map by numbers.

#include <omnirange_eval/Trajectory.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>

#include <string>

namespace omnirange::eval
{
/** An empty grid with the true map's extent and resolution. `invalid_is_free`:
 * rays without a return clear the cells up to max range (right for a laser;
 * for the omnicam a "no hit" also covers obstacles too thin in pixels at
 * long range, and clearing would erase what nearer scans saw). */
mrpt::maps::COccupancyGridMap2D emptyLike(const mrpt::maps::COccupancyGridMap2D& truth, bool invalid_is_free);

/** The `label` scans of a rawlog, each at the ground-truth pose of its time,
 * as a simplemap (what MRPT's observations2map turns into a map). */
mrpt::maps::CSimpleMap simplemapWithGroundTruth(const std::string& rawlog, const std::string& label,
												const std::vector<StampedPose>& truth);
void saveSimplemap(const mrpt::maps::CSimpleMap& sm, const std::string& file);

/** `map` resampled onto the cells of `like` (unknown where it has none). */
mrpt::maps::COccupancyGridMap2D resampledLike(const mrpt::maps::COccupancyGridMap2D& map,
											   const mrpt::maps::COccupancyGridMap2D& like);

/** The scans of an icp-slam simplemap inserted at its poses moved by `alignment`. */
mrpt::maps::COccupancyGridMap2D mapFromSimplemap(const mrpt::maps::CSimpleMap& sm,
												  const mrpt::poses::CPose2D& alignment,
												  const mrpt::maps::COccupancyGridMap2D& like, bool invalid_is_free);

/** Paper style (Figs. 10-13): obstacles black, well-explored free grey,
 * less-explored free white, unknown pale blue; north up. */
cv::Mat paperStyle(const mrpt::maps::COccupancyGridMap2D& map);

struct MapMetrics
{
	std::size_t occupied{0};  ///< occupied cells of the built map
	double precision{0};  ///< its occupied cells within tolerance of a true wall
	double recall{0};  ///< true wall cells near the path (within reach) with a built cell within tolerance
	double thickness{0};  ///< [m] mean thickness of its walls: area / centre-line length
};

/** `reach` [m]: true wall cells farther than this from every path pose are
 * not counted in the recall (no sensor could see them). */
MapMetrics compareWithTruth(const mrpt::maps::COccupancyGridMap2D& built,
							const mrpt::maps::COccupancyGridMap2D& truth, double tolerance,
							const std::vector<StampedPose>& path, double reach);

/** Occupied cells within `margin` of the box (centre x y, size w d, axis
 * aligned), as a length [m]: cells times the resolution. A wall along the
 * box's side that faces the robot gives about that side's length. */
double occupiedLengthAt(const mrpt::maps::COccupancyGridMap2D& map, double x, double y, double w, double d,
						double margin);

}  // namespace omnirange::eval
