// Unsure rays in maps: a box the camera cannot see (the floor's colour) stands
// ahead of a robot driving through a room; every ray that faces it is unsure,
// its confident extent 0.3 m short of the box, written as a navigator wants
// it (a valid return at the extent). omnirange-slam and then MRPT's
// observations2map with our ini must neither clear a cell past an extent nor
// mark a wall at one.
#include "Programs.h"

#include "../common/DrawnScans.h"

#include <omnirange/core/Rangefinder.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>

using namespace omnirange::e2e;
namespace t = omnirange::test;

namespace
{
// The drive starts at the map's origin (a SLAM path starts there).
constexpr double kBoxX0 = 2.5, kBoxX1 = 2.9, kBoxY = 0.2, kShort = 0.3, kFarWall = 3.5;
const std::vector<t::Wall> kRoom{{-0.5, -2, kFarWall, -2}, {kFarWall, -2, kFarWall, 2}, {kFarWall, 2, -0.5, 2}, {-0.5, 2, -0.5, -2}};

/** The room's scan from `pose`, with every ray that meets the box first made
 * unsure at kShort before it (a valid return there, intensity below full). */
mrpt::obs::CObservation2DRangeScan::Ptr scanPastAnUnseenBox(const mrpt::poses::CPose2D& pose, double time)
{
	const std::vector<t::Wall> box{{kBoxX0, -kBoxY, kBoxX0, kBoxY}, {kBoxX0, kBoxY, kBoxX1, kBoxY},
								   {kBoxX1, kBoxY, kBoxX1, -kBoxY}, {kBoxX1, -kBoxY, kBoxX0, -kBoxY}};
	auto room = t::drawScan(kRoom, pose, time, omnirange::scanAperture(360));
	const auto with_box = t::drawScan(box, pose, time, omnirange::scanAperture(360));
	room->setScanHasIntensity(true);
	for (std::size_t i = 0; i < room->getScanSize(); ++i)
	{
		room->setScanIntensity(i, omnirange::kFullConfidence);
		if (!with_box->getScanRangeValidity(i) || with_box->getScanRange(i) >= room->getScanRange(i)) continue;
		const float extent = with_box->getScanRange(i) - static_cast<float>(kShort);
		room->setScanRange(i, extent);
		room->setScanRangeValidity(i, true);  // unsure_rays = obstacle
		room->setScanIntensity(i, static_cast<int>(omnirange::kFullConfidence * extent / with_box->getScanRange(i)));
	}
	return room;
}
}  // namespace

TEST(UnsureRaysInMaps, NoCellIsClearedPastAnUnsureRaysExtentNorMarkedAtIt)
{
	const std::string dir = workDir("unsure_in_maps");
	// 30 steps of 3 cm along the room's axis, facing the box.
	const auto pose = [](int k) { return mrpt::poses::CPose2D(0.03 * k, 0, 0); };
	t::writeDrive(dir + "/drive.rawlog", 30, pose, [&](int k, double time) { return scanPastAnUnseenBox(pose(k), time); },
				  0.4);
	const RunResult slam = run(app("omnirange-slam") + " -i drive.rawlog -c " + q(kSource + "/ini/icp-slam-omniscan.ini") +
								   " -o slam",
							   dir);
	ASSERT_EQ(slam.code, 0) << slam.out;
	const RunResult map = run("observations2map " + q(kSource + "/ini/observations2map-omniscan.ini") +
								  " slam/_finalmap_.simplemap slam/map",
							  dir);
	ASSERT_EQ(map.code, 0) << map.out;
	mrpt::maps::COccupancyGridMap2D grid;
	mrpt::io::CFileGZInputStream in(dir + "/slam/map_gridmap_no00.gridmap");
	mrpt::serialization::archiveFrom(in) >> grid;

	// The room's walls beside the box are mapped and the floor before the extents cleared: the map is no blank.
	int wall = 0;
	for (double x = 0; x < 1.5; x += grid.getResolution())
		for (double y = 1.9; y < 2.1; y += grid.getResolution()) wall += grid.getPos(x, y) < 0.4f;
	EXPECT_GT(wall, 10);
	EXPECT_GT(grid.getPos(0.5, 1.0), 0.6f);
	// In the box's shadow: no wall from just before the extents (kBoxX0 - kShort) to the far wall, and no cell
	// cleared past them.
	int looked = 0;
	for (double x = kBoxX0 - kShort - 0.15; x < kFarWall - 0.1; x += grid.getResolution())
		for (double y = -0.08; y <= 0.08; y += grid.getResolution())
		{
			const float p = grid.getPos(x, y);  // probability of free
			EXPECT_GE(p, 0.45f) << "a wall where an unsure ray's extent ends, at (" << x << ", " << y << ")";
			if (x > kBoxX0 - kShort + 0.05)
			{
				EXPECT_LE(p, 0.55f) << "cleared past an unsure extent at (" << x << ", " << y << ")";
			}
			++looked;
		}
	EXPECT_GT(looked, 20);
}
