// The front end and its MRPT observation: orientation through MRPT's own
// geometry, validity, the observation's fields, parameters from an ini.
#include "SyntheticOmni.h"

#include <omnirange/core/Rangefinder.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CSimplePointsMap.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace omnirange;

namespace
{
constexpr double kPi = 3.14159265358979323846;

/** Points of the scan's valid rays in the robot frame, computed by MRPT. */
std::vector<mrpt::math::TPoint3D> mrptPoints(const mrpt::obs::CObservation2DRangeScan& obs)
{
	mrpt::maps::CSimplePointsMap map;
	map.insertObservation(obs);
	std::vector<mrpt::math::TPoint3D> pts;
	for (std::size_t i = 0; i < map.size(); ++i)
	{
		mrpt::math::TPoint3D p;
		map.getPoint(i, p);
		pts.push_back(p);
	}
	return pts;
}

mrpt::math::TPoint3D mean(const std::vector<mrpt::math::TPoint3D>& pts)
{
	mrpt::math::TPoint3D m{0, 0, 0};
	for (const auto& p : pts) m += p;
	return m * (1.0 / pts.size());
}

RangefinderParams noOutlierFilter()
{
	RangefinderParams p;
	p.outliers.outlier_filter = OutlierFilterKind::None;
	p.sensor_pose = {};
	return p;
}
}  // namespace

TEST(Rangefinder, ObstacleStraightAheadReadsAtBearingZero)
{
	const Rangefinder rf(noOutlierFilter(), test::floorHistogram());
	// A box 1.5 m to 2.5 m ahead, 0.6 m wide.
	const cv::Mat img = test::drawOmni(rf.camera(), [](const FloorPoint& f) {
		return f.x > 1.5 && f.x < 2.5 && std::abs(f.y) < 0.3;
	});
	// In the (mirrored) image it lies to the left of the centre.
	EXPECT_EQ(img.at<cv::Vec3b>(384, 512 - 110), test::kWall);
	EXPECT_EQ(img.at<cv::Vec3b>(384, 512 + 110), test::kFloor);

	const RangeScan scan = rf.process(img);
	EXPECT_EQ(scan.rays[179].status, RayStatus::Hit);
	EXPECT_EQ(scan.rays[180].status, RayStatus::Hit);
	EXPECT_EQ(scan.rays[0].status, RayStatus::NoHit);
	EXPECT_EQ(scan.rays[90].status, RayStatus::NoHit);

	const auto obs = rf.toObservation(scan, mrpt::Clock::now());
	const auto pts = mrptPoints(*obs);
	ASSERT_GE(pts.size(), 15u);  // 2 atan(0.3/1.5) = 22.6 degrees of rays
	const auto m = mean(pts);
	EXPECT_NEAR(m.y, 0.0, 0.02);
	EXPECT_NEAR(m.x, 1.5, 0.06);
	for (const auto& p : pts) EXPECT_GT(p.x, 1.4);
}

TEST(Rangefinder, ObstacleOnTheLeftReadsAtPlusNinetyDegrees)
{
	const Rangefinder rf(noOutlierFilter(), test::floorHistogram());
	const cv::Mat img = test::drawOmni(rf.camera(), [](const FloorPoint& f) {
		return f.y > 1.5 && f.y < 2.5 && std::abs(f.x) < 0.3;
	});
	EXPECT_EQ(img.at<cv::Vec3b>(384 - 110, 512), test::kWall);  // top of the image

	const RangeScan scan = rf.process(img);
	EXPECT_EQ(scan.rays[269].status, RayStatus::Hit);  // +89.5 degrees
	EXPECT_EQ(scan.rays[270].status, RayStatus::Hit);  // +90.5 degrees
	EXPECT_EQ(scan.rays[89].status, RayStatus::NoHit);  // -90.5: the right

	const auto pts = mrptPoints(*rf.toObservation(scan, mrpt::Clock::now()));
	ASSERT_GE(pts.size(), 15u);
	const auto m = mean(pts);
	EXPECT_NEAR(m.x, 0.0, 0.02);
	EXPECT_NEAR(m.y, 1.5, 0.06);
}

TEST(Rangefinder, ObservationFieldsAndValidity)
{
	RangefinderParams p = noOutlierFilter();
	p.sensor_pose = mrpt::poses::CPose3D(0.1, -0.05, 0.931, 0, 0, 0);
	const Rangefinder rf(p, test::floorHistogram());
	const OmniCameraModel& cam = rf.camera();
	// Half the scan sees a wall at 1 m (the robot's left half), the rest none.
	const cv::Mat img = test::drawOmni(cam, [](const FloorPoint& f) {
		return f.y > 0 && std::hypot(f.x, f.y) > 1.0;
	});
	const auto stamp = mrpt::Clock::now();
	const RangeScan scan = rf.process(img);
	const auto obs = rf.toObservation(scan, stamp);

	EXPECT_EQ(obs->sensorLabel, "OMNISCAN");
	EXPECT_EQ(obs->timestamp, stamp);
	EXPECT_EQ(obs->getScanSize(), 360u);
	EXPECT_NEAR(obs->aperture, 2 * kPi * 359 / 360, 1e-5);
	EXPECT_TRUE(obs->rightToLeft);
	EXPECT_FLOAT_EQ(obs->maxRange, 3.8f);
	EXPECT_FLOAT_EQ(obs->stdError, 0.10f);
	EXPECT_NEAR(obs->sensorPose.x(), 0.1, 1e-12);
	EXPECT_NEAR(obs->sensorPose.z(), 0.931, 1e-12);
	for (std::size_t i = 0; i < 360; ++i)
	{
		// MRPT's angle for ray i is our scanline i's bearing.
		ASSERT_NEAR(obs->getScanAngle(i), scanlineBearing(int(i), 360), 1e-5);
		const bool left = scanlineBearing(int(i), 360) > 0.05 &&
			scanlineBearing(int(i), 360) < kPi - 0.05;
		if (left)
		{
			ASSERT_TRUE(obs->getScanRangeValidity(i)) << i;
			ASSERT_NEAR(obs->getScanRange(i), 1.0, 0.02) << i;
		}
		else if (scanlineBearing(int(i), 360) < -0.05)
		{
			ASSERT_FALSE(obs->getScanRangeValidity(i)) << i;  // no hit: invalid
			ASSERT_FLOAT_EQ(obs->getScanRange(i), 3.8f);
		}
	}
}

TEST(Rangefinder, OutlierFilterMarksARayInvalid)
{
	RangefinderParams p = noOutlierFilter();
	p.outliers.outlier_filter = OutlierFilterKind::Spike;
	const Rangefinder rf(p, test::floorHistogram());
	cv::Mat img = test::drawFloorDisc(rf.camera(), 130.0);
	// A wall-coloured blotch, 3 px wide and 25 px long, on the forward ray.
	img(cv::Rect(512 - 80, 383, 25, 3)).setTo(test::kWall);
	const RangeScan scan = rf.process(img);
	EXPECT_EQ(scan.outliers, 2);  // rays 179 and 180 see the blotch
	EXPECT_EQ(scan.rays[179].status, RayStatus::Outlier);
	const auto obs = rf.toObservation(scan, mrpt::Clock::now());
	EXPECT_FALSE(obs->getScanRangeValidity(179));
	EXPECT_TRUE(obs->getScanRangeValidity(170));
}

TEST(Rangefinder, LoadsEveryKeyFromAnIniSection)
{
	mrpt::config::CConfigFileMemory ini(
		"[omni]\nN = 7\nK = 1\nthreshold = 0.2\nR = 180\nh = 1.1\n"
		"scanlines = 180\nmax_range = 3.0\nsensor_label = OMNI2\n"
		"pose_x = 0.2\npose_yaw = 90\noutlier_filter = none\n");
	RangefinderParams p;
	p.loadFromConfig(ini, "omni");
	EXPECT_EQ(p.scanner.filter.N, 7);
	EXPECT_EQ(p.scanner.filter.K, 1);
	EXPECT_DOUBLE_EQ(p.threshold, 0.2);
	EXPECT_DOUBLE_EQ(p.camera.R, 180);
	EXPECT_EQ(p.scanner.scanlines, 180);
	EXPECT_EQ(p.sensor_label, "OMNI2");
	EXPECT_NEAR(p.sensor_pose.yaw(), kPi / 2, 1e-12);  // degrees in the ini
	EXPECT_NEAR(p.sensor_pose.z(), 1.1, 1e-12);  // pose_z defaults to h
	EXPECT_EQ(p.outliers.outlier_filter, OutlierFilterKind::None);
}

TEST(Rangefinder, ImpossibleIniValuesAreRejectedNamingTheKey)
{
	const auto rejects = [](const std::string& body, const std::string& word) {
		mrpt::config::CConfigFileMemory ini("[omni]\n" + body + "\n");
		RangefinderParams p;
		try
		{
			p.loadFromConfig(ini, "omni");
			Rangefinder rf(p, test::floorHistogram());
			ADD_FAILURE() << "accepted: " << body;
		}
		catch (const std::invalid_argument& e)
		{
			EXPECT_NE(std::string(e.what()).find(word), std::string::npos)
				<< body << " -> " << e.what();
		}
	};
	rejects("N = 0", "N");
	rejects("K = -1", "K");
	rejects("threshold = 1.5", "threshold");
	rejects("threshold = -0.01", "threshold");
	rejects("R = 0", "R");
	rejects("h = 0", "h");
	rejects("mirror_model = conic", "mirror_model");
	rejects("Theta = 0.05", "Theta");  // unknown key
	rejects("image_width = 400\nimage_height = 300\ncx = 200\ncy = 150", "300");
	mrpt::config::CConfigFileMemory empty("[other]\nN = 3\n");
	RangefinderParams p;
	EXPECT_THROW(p.loadFromConfig(empty, "omni"), std::invalid_argument);
}

TEST(Rangefinder, DefaultsPrintAsIniAndLoadBack)
{
	const RangefinderParams defaults;
	mrpt::config::CConfigFileMemory ini("[x]\n" + defaults.asIni());
	RangefinderParams back;
	back.threshold = 0.9;  // must be overwritten from the text
	back.loadFromConfig(ini, "x");
	EXPECT_EQ(back.asIni(), defaults.asIni());
}
