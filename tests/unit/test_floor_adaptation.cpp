// Floor adaptation (Rangefinder::learnFloor): a floor that darkened after
// training is learned from the ring around the base, image after image,
// without a laser; a wall that touches part of the ring is not learned; what
// was learned fades.
#include "SyntheticOmni.h"

#include <omnirange/core/Rangefinder.h>

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

using namespace omnirange;

namespace
{
RangefinderParams params(double memory = 50.0)
{
	RangefinderParams p;
	p.threshold = 0.05;
	p.floor_adaptation = true;
	p.adaptation_memory = memory;
	p.walls.wall_fit = false;  // the disc's edge is a circle: each ray's own range is checked
	return p;
}
}  // namespace

TEST(FloorAdaptation, ADarkerFloorIsLearnedFromTheRingAndScannedAgain)
{
	const OmniCameraModel cam{CameraParams{}};
	const double rho = 100.0;
	cv::Mat dark;
	test::drawFloorDisc(cam, rho).convertTo(dark, -1, 0.7);  // the light dropped by 30 %
	Rangefinder rf(params(), ColourModel(test::floorHistogram()));
	ASSERT_EQ(rf.process(dark).count(RayStatus::TooClose), 360);  // trained light only: nothing is floor

	const FreeSpaceClassifier adapted = *rf.learnFloor(dark);
	const RangeScan s = rf.process(dark, &adapted);
	EXPECT_EQ(s.count(RayStatus::Hit), 360);
	EXPECT_EQ(rf.processNext(dark).count(RayStatus::Hit), 360);  // learning and scanning in one call
	const double truth = cam.distanceFromRho(rho);
	for (const Ray& r : s.rays) EXPECT_NEAR(r.range, truth, cam.distanceFromRho(rho + 1) - truth);
	// The wall's colour was never on the ring: still not free.
	EXPECT_FALSE(adapted.isFree(&test::kWall[0]));
	EXPECT_EQ(adapted.freeBinCount(), rf.classifier().freeBinCount() + 1);
}

TEST(FloorAdaptation, AWallOnAFewDirectionsOfTheRingIsNotLearned)
{
	const OmniCameraModel cam{CameraParams{}};
	cv::Mat img = test::drawFloorDisc(cam, 100.0);
	// A wall right against the robot on one side: a tenth of the ring.
	cv::rectangle(img, cv::Rect(512 + 40, 384 - 8, 30, 16), cv::Scalar(test::kWall), cv::FILLED);
	Rangefinder rf(params(), ColourModel(test::floorHistogram()));
	for (int i = 0; i < 19; ++i) rf.learnFloor(img);
	const FreeSpaceClassifier adapted = *rf.learnFloor(img);
	EXPECT_FALSE(adapted.isFree(&test::kWall[0]));
	EXPECT_EQ(adapted.freeBinCount(), rf.classifier().freeBinCount());
}

TEST(FloorAdaptation, WhatWasLearnedFadesWithTheMemory)
{
	const OmniCameraModel cam{CameraParams{}};
	cv::Mat dark;
	test::drawFloorDisc(cam, 100.0).convertTo(dark, -1, 0.7);
	const cv::Mat bright = test::drawFloorDisc(cam, 100.0);
	Rangefinder rf(params(5.0), ColourModel(test::floorHistogram()));
	cv::Vec3b dark_floor = dark.at<cv::Vec3b>(384, 512 + 60);
	ASSERT_TRUE(rf.learnFloor(dark)->isFree(&dark_floor[0]));
	// Back in the trained light, the dark colour's share of the recent floor
	// after n images is k^n / (k^n + (1 - k^n) / (1 - k)), k = exp(-1/5):
	// 0.056 at n = 7, 0.044 at n = 8, when it falls below Theta (0.05).
	int n = 1;
	while (rf.learnFloor(bright)->isFree(&dark_floor[0]) && n < 100) ++n;
	EXPECT_EQ(n, 8);
	EXPECT_THROW(Rangefinder(params(0.5), ColourModel(test::floorHistogram())), std::invalid_argument);
}

TEST(FloorAdaptation, OffByDefault)
{
	RangefinderParams p = params();
	p.floor_adaptation = false;
	Rangefinder rf(p, ColourModel(test::floorHistogram()));
	EXPECT_FALSE(rf.adaptsToFloor());
	EXPECT_FALSE(rf.learnFloor(test::drawFloorDisc(rf.camera(), 100.0)).has_value());
}
