// The TRUTH scan: where the floor really ends, pinned by geometry worked out
// by hand: a wall's foot, a floating cabinet body whose underside hides the
// floor only from where the sight line grazes it, nothing within range.
#include "SimFixtures.h"

#include <omnirange_sim/FloorTruth.h>

#include <omnirange/core/PolarScanner.h>

#include <cmath>

using namespace omnirange::sim;

namespace
{
constexpr double kPi = 3.14159265358979323846;

/** The ray of a 360-ray truth scan nearest to `bearing` [rad] (rays sit
 * half a degree off the whole degrees: scanlineBearing()). */
int rayAt(double bearing)
{
	return static_cast<int>(std::floor((bearing + kPi * 359.0 / 360.0) / (2 * kPi / 360))) % 360;
}
}  // namespace

TEST(FloorTruth, TheFloorEndsAtAWallsFoot)
{
	const World w = loadWorld(test::writeFile("room.world", test::roomWorld()));
	OmnicamSimParams cam;  // on the robot's axis, h = 0.931 m
	const auto t = floorTruth(w, cam, {0, 0, 0}, 360, 10.0);
	ASSERT_EQ(t->getScanSize(), 360u);
	EXPECT_EQ(t->sensorLabel, "TRUTH");
	// Ahead the red box's face is at x = 2.0: a ray at bearing a reads 2 / cos(a).
	for (const double deg : {0.0, 10.0, -10.0})
	{
		const int i = rayAt(deg * kPi / 180);
		const double a = omnirange::scanlineBearing(i, 360);
		ASSERT_LT(std::abs(a - deg * kPi / 180), kPi / 360 + 1e-9);
		ASSERT_TRUE(t->getScanRangeValidity(i)) << deg;
		EXPECT_NEAR(t->getScanRange(i), 2.0 / std::cos(a), 1e-4) << deg;
	}
	// To the left the blue box's face is at y = 1.5.
	const int left = rayAt(kPi / 2);
	EXPECT_NEAR(t->getScanRange(left), 1.5 / std::sin(omnirange::scanlineBearing(left, 360)), 1e-4);
	// Behind: nothing at all within 10 m.
	EXPECT_FALSE(t->getScanRangeValidity(rayAt(kPi)));
	// The robot turned by 90 degrees sees the red box on its right.
	const auto turned = floorTruth(w, cam, {0, 0, kPi / 2}, 360, 10.0);
	const int right = rayAt(-kPi / 2);
	EXPECT_NEAR(turned->getScanRange(right), 2.0 / std::cos(omnirange::scanlineBearing(right, 360) + kPi / 2), 1e-4);
}

TEST(FloorTruth, AFloatingBodyHidesTheFloorFromWhereTheSightLineGrazesIt)
{
	// A cabinet body from z = 0.30 to 1.80 m whose front face is 1.0 m ahead,
	// on no plinth: the camera at h = 0.931 sees the floor under it up to
	// d = 1.0 * 0.931 / (0.931 - 0.30) = 1.4754 m.
	const auto path = test::writeFile("float.world",
									  "omnirange-world 1\n"
									  "box x=1.5 y=0 w=1.0 d=1.0 z0=0.30 z1=1.8 material=cabinet_grey\n");
	const World w = loadWorld(path);
	OmnicamSimParams cam;
	const auto t = floorTruth(w, cam, {0, 0, 0}, 360, 10.0);
	const int ahead = rayAt(0);
	const double c = std::cos(omnirange::scanlineBearing(ahead, 360));  // the face is 1.0 m ahead, along x
	EXPECT_NEAR(t->getScanRange(ahead), 1.0 / c * 0.931 / (0.931 - 0.30), 1e-4);
	// With a plinth from the floor up, the floor ends at the plinth's face.
	const auto plinth = test::writeFile("plinth.world",
										"omnirange-world 1\n"
										"box x=1.5 y=0 w=1.0 d=1.0 z0=0.30 z1=1.8 material=cabinet_grey\n"
										"box x=1.6 y=0 w=0.8 d=1.0 z1=0.12 material=cabinet_grey\n");
	EXPECT_NEAR(floorTruth(loadWorld(plinth), cam, {0, 0, 0}, 360, 10.0)->getScanRange(ahead), 1.2 / c, 1e-4);
	// A shelf above the camera hides nothing.
	const auto high = test::writeFile("high.world",
									  "omnirange-world 1\nbox x=1.5 y=0 w=1.0 d=1.0 z0=1.2 z1=1.8 material=cabinet_grey\n");
	EXPECT_FALSE(floorTruth(loadWorld(high), cam, {0, 0, 0}, 360, 10.0)->getScanRangeValidity(rayAt(0)));
}

TEST(BodyTruth, AFloatingBodyIsStruckAtItsFaceNotWhereTheFloorHides)
{
	// The cabinet body of the test above (z 0.30 to 1.80 m, face 1.0 m ahead):
	// the floor truth reads 1.4754 m, the robot strikes the face at 1.0 m.
	const auto path = test::writeFile("float.world",
									  "omnirange-world 1\n"
									  "box x=1.5 y=0 w=1.0 d=1.0 z0=0.30 z1=1.8 material=cabinet_grey\n");
	const World w = loadWorld(path);
	OmnicamSimParams cam;
	const auto body = bodyTruth(w, cam, {0, 0, 0}, 360, 10.0, 1.0);
	EXPECT_EQ(body->sensorLabel, "BODY");
	const int ahead = rayAt(0);
	const double c = std::cos(omnirange::scanlineBearing(ahead, 360));
	ASSERT_TRUE(body->getScanRangeValidity(ahead));
	EXPECT_NEAR(body->getScanRange(ahead), 1.0 / c, 1e-4);
	EXPECT_NEAR(floorTruth(w, cam, {0, 0, 0}, 360, 10.0)->getScanRange(ahead), 1.4754 / c, 1e-4);
	// A robot 0.25 m tall passes under it: nothing struck ahead within 10 m.
	EXPECT_FALSE(bodyTruth(w, cam, {0, 0, 0}, 360, 10.0, 0.25)->getScanRangeValidity(ahead));
}

TEST(BodyTruth, ARackWithAGapIsStruckAtItsLowestBoard)
{
	// A rack 1.0 m ahead: a board from z 0.05 to 0.10 m, a gap past the laser's
	// plane (0.30 m), a board from 0.60 to 0.65 m; a wall 3.0 m ahead. The body
	// truth is the rack's face; the floor truth where the sight line grazes the
	// low board's underside, 1.0 * 0.931 / (0.931 - 0.05) = 1.0568 m.
	const auto path = test::writeFile("rack.world",
									  "omnirange-world 1\n"
									  "box x=1.2 y=0 w=0.4 d=1.0 z0=0.05 z1=0.10 material=cabinet_grey\n"
									  "box x=1.2 y=0 w=0.4 d=1.0 z0=0.60 z1=0.65 material=cabinet_grey\n"
									  "box x=3.1 y=0 w=0.2 d=4.0 z1=2.0 material=cabinet_grey\n");
	const World w = loadWorld(path);
	OmnicamSimParams cam;
	const int ahead = rayAt(0);
	const double c = std::cos(omnirange::scanlineBearing(ahead, 360));
	EXPECT_NEAR(bodyTruth(w, cam, {0, 0, 0}, 360, 10.0, 1.0)->getScanRange(ahead), 1.0 / c, 1e-4);
	EXPECT_NEAR(floorTruth(w, cam, {0, 0, 0}, 360, 10.0)->getScanRange(ahead), 1.0568 / c, 1e-4);
	// Only the board above the strike height is no longer struck: the wall is.
	const auto upper = test::writeFile("upper.world",
									   "omnirange-world 1\n"
									   "box x=1.2 y=0 w=0.4 d=1.0 z0=1.10 z1=1.15 material=cabinet_grey\n"
									   "box x=3.1 y=0 w=0.2 d=4.0 z1=2.0 material=cabinet_grey\n");
	EXPECT_NEAR(bodyTruth(loadWorld(upper), cam, {0, 0, 0}, 360, 10.0, 1.0)->getScanRange(ahead), 3.0 / c, 1e-4);
}
