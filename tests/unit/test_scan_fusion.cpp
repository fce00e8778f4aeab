// The fused scan (core/ScanFusion.h) against geometry worked out by hand: a
// laser 0.16 m ahead of the omnicam seeing a wall that the omnicam sees too,
// a body above the laser's plane that only the omnicam sees, an unsure ray
// where the laser's word stands, and the half circle behind the laser.
#include <omnirange/core/PolarScanner.h>
#include <omnirange/core/Rangefinder.h>
#include <omnirange/core/ScanFusion.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace omnirange;
using mrpt::obs::CObservation2DRangeScan;

namespace
{
constexpr int kRays = 360;

/** An omnicam scan at the robot's centre: every ray free to 3.8 m, confident. */
CObservation2DRangeScan omniScan()
{
	CObservation2DRangeScan s;
	s.aperture = static_cast<float>(scanAperture(kRays));
	s.rightToLeft = true;
	s.maxRange = 3.8f;
	s.resizeScan(kRays);
	s.setScanHasIntensity(true);
	for (int i = 0; i < kRays; ++i) s.setScanRange(i, 3.8f), s.setScanRangeValidity(i, false), s.setScanIntensity(i, 100);
	return s;
}

/** A 180-degree laser of `rays` rays 0.16 m ahead of the omnicam, reading a
 * wall across the robot's path at x = 3.0 m (robot frame) and nothing behind it. */
CObservation2DRangeScan laserScan(int rays = 181)
{
	CObservation2DRangeScan s;
	s.aperture = static_cast<float>(M_PI);
	s.rightToLeft = true;
	s.maxRange = 19.8f;
	s.sensorPose = mrpt::poses::CPose3D(0.16, 0, 0.30, 0, 0, 0);
	s.resizeScan(rays);
	for (int i = 0; i < rays; ++i)
	{
		const double a = s.getScanAngle(i);
		const double r = std::cos(a) > 0.05 ? (3.0 - 0.16) / std::cos(a) : 0;
		s.setScanRange(i, static_cast<float>(r));
		s.setScanRangeValidity(i, r > 0 && r < 19.8);
	}
	return s;
}

int rayAt(double bearing) { return nearestRay(omniScan(), bearing); }
}  // namespace

TEST(ScanFusion, TheLasersRaysAreSeenFromTheOmnicam)
{
	const auto laser = laserScan();
	const auto along = laserAlong(laser, omniScan());
	// Straight ahead the wall is 3.0 m from the omnicam (2.84 m from the laser).
	const int ahead = rayAt(0);
	ASSERT_EQ(along[ahead].kind, LaserReading::Kind::Return);
	EXPECT_NEAR(along[ahead].range, 3.0 / std::cos(scanlineBearing(ahead, kRays)), 2e-3);
	// 30 degrees left: the wall at x = 3.0 seen from the omnicam.
	const int left30 = rayAt(M_PI / 6);
	EXPECT_NEAR(along[left30].range, 3.0 / std::cos(scanlineBearing(left30, kRays)), 0.06);
	// Behind the robot the laser sees nothing: unseen, not free.
	EXPECT_EQ(along[rayAt(M_PI)].kind, LaserReading::Kind::Unseen);
	// Every ray from -80 to 80 degrees is seen, none left as a gap.
	for (int deg = -80; deg <= 80; ++deg) EXPECT_NE(along[rayAt(deg * M_PI / 180)].kind, LaserReading::Kind::Unseen) << deg;
}

TEST(ScanFusion, EachRayIsTheNearerOfTheLaserAndASureOmnicamHit)
{
	auto omni = omniScan();
	const auto laser = laserScan();
	const int ahead = rayAt(0), right = rayAt(-M_PI / 6), left = rayAt(M_PI / 6), behind = rayAt(M_PI),
			  behind_unsure = rayAt(M_PI - 0.2), far_hit = rayAt(0.2);
	omni.setScanRange(ahead, 1.0f), omni.setScanRangeValidity(ahead, true);  // a table top above the laser's plane
	omni.setScanRange(far_hit, 3.5f), omni.setScanRangeValidity(far_hit, true);  // beyond the wall: the laser is nearer
	omni.setScanRange(right, 0.8f), omni.setScanRangeValidity(right, true), omni.setScanIntensity(right, 40);  // unsure
	omni.setScanRange(behind, 1.5f), omni.setScanRangeValidity(behind, true);
	omni.setScanRange(behind_unsure, 0.9f), omni.setScanIntensity(behind_unsure, 30);
	omni.sensorLabel = "OMNISCAN";

	const auto fused = fuseScans(omni, laser);
	EXPECT_EQ(fused->sensorLabel, "FUSED");
	EXPECT_EQ(fused->getScanSize(), static_cast<std::size_t>(kRays));
	EXPECT_FLOAT_EQ(fused->maxRange, 19.8f);
	const auto from = [&](int i) { return fused->getScanIntensity(i); };
	// The table top: the omnicam's hit, nearer than the wall.
	EXPECT_TRUE(fused->getScanRangeValidity(ahead));
	EXPECT_FLOAT_EQ(fused->getScanRange(ahead), 1.0f);
	EXPECT_EQ(from(ahead), static_cast<int>(FusedSource::Omnicam));
	// A sure omnicam hit beyond the laser's return, and free floor, give the laser's wall.
	for (const int i : {far_hit, left})
	{
		EXPECT_TRUE(fused->getScanRangeValidity(i));
		EXPECT_NEAR(fused->getScanRange(i), 3.0 / std::cos(scanlineBearing(i, kRays)), 0.06) << i;
		EXPECT_EQ(from(i), static_cast<int>(FusedSource::Laser));
	}
	// Unsure: the laser's word stands, and the fused ray is not unsure.
	EXPECT_NEAR(fused->getScanRange(right), 3.0 / std::cos(scanlineBearing(right, kRays)), 0.06);
	EXPECT_FALSE(rayIsUnsure(*fused, right));
	// Behind: the omnicam alone, an unsure ray still unsure.
	EXPECT_FLOAT_EQ(fused->getScanRange(behind), 1.5f);
	EXPECT_EQ(from(behind), static_cast<int>(FusedSource::OmnicamAlone));
	EXPECT_TRUE(rayIsUnsure(*fused, behind_unsure));
	EXPECT_FALSE(fused->getScanRangeValidity(rayAt(M_PI + 0.4)));  // free to 3.8 m: invalid, as the omnicam wrote it
}

TEST(ScanFusion, ACoarseLaserSeesTheArcsBetweenItsRays)
{
	// 19 rays over 180 degrees, 10 degrees apart: every omnicam ray between two of them is in
	// the laser's view and takes the nearer of the two readings; behind it, none.
	const auto along = laserAlong(laserScan(19), omniScan());
	for (int deg = -85; deg <= 85; ++deg)
		EXPECT_NE(along[rayAt(deg * M_PI / 180)].kind, LaserReading::Kind::Unseen) << deg;
	for (int deg = 100; deg <= 260; deg += 10) EXPECT_EQ(along[rayAt(deg * M_PI / 180)].kind, LaserReading::Kind::Unseen) << deg;
	// Between the rays at 0 and 10 degrees, the nearer reading: the one at 0, 3.0 m.
	ASSERT_EQ(along[rayAt(5 * M_PI / 180)].kind, LaserReading::Kind::Return);
	EXPECT_NEAR(along[rayAt(5 * M_PI / 180)].range, 3.0, 0.01);
}
