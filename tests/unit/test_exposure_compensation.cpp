// Exposure compensation: the floor ring's median colour, the gains that
// bring it back to training's, and a classifier that then recognises a
// floor seen in other light.
#include "SyntheticOmni.h"

#include <omnirange/core/ExposureCompensation.h>
#include <omnirange/core/FreeSpaceClassifier.h>
#include <omnirange/core/Rangefinder.h>

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

using namespace omnirange;

TEST(ExposureCompensation, TheRingSeesTheFloorAroundTheBase)
{
	const OmniCameraModel cam{CameraParams{}};
	cv::Mat img = test::drawFloorDisc(cam, 120.0);
	// A wall patch covering a tenth of the ring does not move the median.
	cv::rectangle(img, cv::Rect(512 + 40, 384 - 8, 30, 16), cv::Scalar(test::kWall), cv::FILLED);
	const FloorRing ring(cam, 0.45);
	const auto m = ring.medianColour(img);
	EXPECT_EQ(m[0], test::kFloor[0]);
	EXPECT_EQ(m[1], test::kFloor[1]);
	EXPECT_EQ(m[2], test::kFloor[2]);
}

TEST(ExposureCompensation, GainsBringTheColourBackAndAreBounded)
{
	const auto g = compensatingGains({100, 150, 200}, {80, 150, 250});
	EXPECT_DOUBLE_EQ(g[0], 1.25);
	EXPECT_DOUBLE_EQ(g[1], 1.0);
	EXPECT_DOUBLE_EQ(g[2], 0.8);
	EXPECT_DOUBLE_EQ(compensatingGains({200, 200, 200}, {10, 200, 200})[0], 2.0);
}

TEST(ExposureCompensation, ChangesWithinTheDeadbandAreLeftAlone)
{
	// 2 % darker on every channel: within a 3 % band, no gain at all.
	const auto small = compensatingGains({100, 100, 100}, {98, 98, 98}, 0.03);
	for (double g : small) EXPECT_DOUBLE_EQ(g, 1.0);
	// One channel 10 % off: all three gains as computed, the small ones too.
	const auto large = compensatingGains({100, 100, 110}, {98, 98, 100}, 0.03);
	EXPECT_DOUBLE_EQ(large[0], 100.0 / 98);
	EXPECT_DOUBLE_EQ(large[1], 100.0 / 98);
	EXPECT_DOUBLE_EQ(large[2], 1.1);
	// A dark channel one grey level off (3.4 %) and a black reference are
	// not changes of light either.
	for (double g : compensatingGains({30, 60, 90}, {29, 60, 90}, 0.03)) EXPECT_DOUBLE_EQ(g, 1.0);
	for (double g : compensatingGains({0, 60, 90}, {1, 60, 90}, 0.03)) EXPECT_DOUBLE_EQ(g, 1.0);
}

TEST(ExposureCompensation, ADarkerImageOfTheFloorIsStillFloor)
{
	const OmniCameraModel cam{CameraParams{}};
	const double rho = 100.0;
	const cv::Mat bright = test::drawFloorDisc(cam, rho);
	cv::Mat dark;
	bright.convertTo(dark, -1, 0.7);  // the same scene with 30 % less light
	ColourModel model(test::floorHistogram());
	RangefinderParams p;
	p.exposure_compensation = true;
	p.walls.wall_fit = false;  // the disc's edge is a circle: each ray's own range is checked
	const Rangefinder plain(p, model);
	model.reference = FloorRing(cam, cam.distanceFromRho(p.scanner.base_radius) + 0.05).medianColour(bright);
	const Rangefinder compensated(p, model);
	const double truth = cam.distanceFromRho(rho);
	// Without compensation the darker floor is not floor: every ray is "too close".
	EXPECT_EQ(plain.process(dark).count(RayStatus::TooClose), 360);
	const RangeScan s = compensated.process(dark);
	EXPECT_EQ(s.count(RayStatus::Hit), 360);
	for (const Ray& r : s.rays) EXPECT_NEAR(r.range, truth, cam.distanceFromRho(rho + 1) - truth);
	p.exposure_compensation = false;
	EXPECT_EQ(Rangefinder(p, model).process(dark).count(RayStatus::TooClose), 360);  // the switch
}

TEST(ExposureCompensation, AShadowOnTheRingIsNotAChangeOfLight)
{
	// The floor is seen lit and in shade in training; now the robot stands in
	// a shadow that covers the ring and reaches 20 px past it, and the rest
	// of the floor is lit. Gains from the ring would brighten the lit floor
	// out of its colours; the check keeps the image as it is.
	const OmniCameraModel cam{CameraParams{}};
	const double rho = 110.0;
	const cv::Mat lit = test::drawFloorDisc(cam, rho);
	RangefinderParams p;
	p.walls.wall_fit = false;
	const double ring_rho = cam.rhoFromDistance(cam.distanceFromRho(p.scanner.base_radius) + 0.05);
	const double shadow_rho = ring_rho + 10.0 + 20.0;
	const cv::Vec3b shade = test::kFloor * 0.7;
	cv::Mat img = lit.clone();
	const auto& c = cam.params();
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
			if (std::hypot(u - c.cx, v - c.cy) <= shadow_rho) img.at<cv::Vec3b>(v, u) = shade;
	ColourHistogram h = test::floorHistogram();
	for (int i = 0; i < 100; ++i) h.addPixel(&shade[0]);
	ColourModel model(h);
	model.reference = FloorRing(cam, cam.distanceFromRho(p.scanner.base_radius) + 0.05).medianColour(lit);
	const double truth = cam.distanceFromRho(rho), pixel = cam.distanceFromRho(rho + 1) - truth;

	const RangeScan checked = Rangefinder(p, model).process(img);
	EXPECT_EQ(checked.count(RayStatus::Hit), 360);
	for (const Ray& r : checked.rays) EXPECT_NEAR(r.range, truth, pixel);

	p.exposure_check = false;  // the gains taken as they come: the lit floor ends at the shadow's edge
	const RangeScan unchecked = Rangefinder(p, model).process(img);
	int short_rays = 0;
	for (const Ray& r : unchecked.rays) short_rays += r.status == RayStatus::Hit && r.range < cam.distanceFromRho(shadow_rho + 2);
	EXPECT_EQ(short_rays, 360);
}
