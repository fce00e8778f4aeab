// The laser against the geometry, odometry drift, the true map.
#include "SimFixtures.h"

#include <omnirange_sim/SensorModels.h>
#include <omnirange_sim/Simulator.h>

#include <cmath>

using namespace omnirange::sim;

TEST(LaserSimulator, RangesMatchTheGeometry)
{
	const World w = loadWorld(test::writeFile("room.world", test::roomWorld()));
	LaserSimParams L;  // at x = 0.16, z = 0.30, 181 rays over 180 degrees, sigma 5 mm
	std::mt19937_64 rng(3);
	const auto scan = simulateLaser(w, L, {0, 0, 0}, rng);
	ASSERT_EQ(scan->getScanSize(), 181u);
	EXPECT_EQ(scan->sensorLabel, "LASER");
	EXPECT_NEAR(scan->aperture, 3.14159265, 1e-6);
	double worst = 0;
	for (int i = 70; i <= 110; ++i)  // -20 to +20 degrees: the red wall's face x = 2
	{
		const double a = -3.14159265 / 2 + i * 3.14159265 / 180;
		ASSERT_TRUE(scan->getScanRangeValidity(i)) << i;
		worst = std::max(worst, std::abs(scan->getScanRange(i) - (2.0 - 0.16) / std::cos(a)));
	}
	EXPECT_LT(worst, 5 * 0.005);
	EXPECT_GT(worst, 0.0);  // there is noise
	// Straight to the right (-90 degrees) nothing is within 6 m ... but the
	// room has no walls there at all: no return, invalid.
	EXPECT_FALSE(scan->getScanRangeValidity(0));
	EXPECT_FLOAT_EQ(scan->getScanRange(0), 19.8f);
}

TEST(LaserSimulator, SeesThroughAGapAtItsHeight)
{
	// A cabinet body on legs: the laser at 0.30 m passes under it.
	const auto path = test::writeFile(
		"cab.world",
		"omnirange-world 1\n"
		"box x=2 y=0 w=0.6 d=1.6 z0=0.55 z1=1.8 material=cabinet_grey\n"
		"box x=2 y=0 w=0.6 d=1.6 z1=0.12 material=cabinet_grey\n"
		"box x=5 y=0 w=0.5 d=8 z1=2 material=brick\n");
	const World w = loadWorld(path);
	LaserSimParams L;
	L.sigma = 0;
	std::mt19937_64 rng(3);
	const auto scan = simulateLaser(w, L, {0, 0, 0}, rng);
	EXPECT_NEAR(scan->getScanRange(90), 4.75 - 0.16, 1e-5);  // the wall behind
}

TEST(Odometry, DriftsButFollowsTheTruth)
{
	OdometrySimParams p;
	OdometrySimulator odo(p, 9);
	mrpt::poses::CPose2D last;
	for (int k = 0; k <= 100; ++k) last = odo.step({0.1 * k, 0, 0})->odometry;
	// 10 m straight: about 10 m forward, with the systematic yaw drift
	// (0.01 rad/m) bending the path to the left.
	EXPECT_NEAR(last.x(), 10.0, 0.5);
	EXPECT_GT(last.y(), 0.1);
	EXPECT_NEAR(last.phi(), 0.1, 0.05);
}

TEST(TrueMap, MarksSolidsOccupiedAndTheRestFree)
{
	const World w = loadWorld(test::writeFile("room.world", test::roomWorld()));
	const auto grid = trueMap(w, 0.05, 0.9);
	// getCell() is P(free): inside the red wall (x in [2, 3]) occupied, at the origin free.
	EXPECT_LT(grid.getCell(grid.x2idx(2.5), grid.y2idx(0.0)), 0.5);
	EXPECT_LT(grid.getCell(grid.x2idx(2.02), grid.y2idx(1.9)), 0.5);
	EXPECT_GT(grid.getCell(grid.x2idx(1.9), grid.y2idx(0.0)), 0.5);
	EXPECT_GT(grid.getCell(grid.x2idx(0.0), grid.y2idx(0.0)), 0.5);
	EXPECT_GT(grid.getCell(grid.x2idx(3.2), grid.y2idx(0.0)), 0.5);
}
