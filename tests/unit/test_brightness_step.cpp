// The brightness-step cue: a face the floor's colour, lit unlike the floor,
// ends a ray the colour model sees through; exposure, noise and thin lines
// on the floor do not.
#include "SyntheticOmni.h"

#include <omnirange/core/BrightnessStep.h>
#include <omnirange/core/FreeSpaceClassifier.h>
#include <omnirange/core/PolarScanner.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

using namespace omnirange;

namespace
{
/** A 1-row scanline of `n` pixels, each channel `level(k)`. */
cv::Mat row(int n, const std::function<double(int)>& level)
{
	cv::Mat r(1, n, CV_8UC3);
	for (int k = 0; k < n; ++k) r.at<cv::Vec3b>(0, k) = cv::Vec3b::all(cv::saturate_cast<std::uint8_t>(level(k)));
	return r;
}

int step(const cv::Mat& r, double threshold, int from = 0, int to = 1000, int window = 4,
		 StepSign sign = StepSign::Either)
{
	std::vector<std::int32_t> pix(r.cols);
	std::iota(pix.begin(), pix.end(), 0);
	return findBrightnessStep(r.ptr<std::uint8_t>(), pix.data(), r.cols, from, std::min(to, r.cols - 1), threshold,
							  window, sign);
}
}  // namespace

TEST(BrightnessStep, AFacesFootIsFoundWhereItBegins)
{
	// Floor 150, a face 30 % brighter from pixel 60: ln(1.3) = 0.26.
	const cv::Mat r = row(100, [](int k) { return k < 60 ? 150.0 : 195.0; });
	// The windows' means first differ by the ratio a few pixels before the foot.
	const int found = step(r, 0.1);
	EXPECT_GE(found, 57);
	EXPECT_LE(found, 60);
	EXPECT_EQ(step(r, 0.25), 60);  // a step of nearly the whole contrast: only at the foot
	EXPECT_EQ(step(r, 0.3), -1);  // above the contrast: none
	EXPECT_EQ(step(r, 0.1, 0, 50), -1);  // not searched past `to`
	EXPECT_EQ(step(r, 0.1, 70), -1);  // nor before `from`
	EXPECT_EQ(step(r, 0.0), -1);  // 0 is off
}

TEST(BrightnessStep, ExposureDoesNotMoveItButADarkerFaceIsAStepToo)
{
	for (const double gain : {0.6, 1.0, 1.4})
	{
		const cv::Mat brighter = row(100, [&](int k) { return gain * (k < 60 ? 120.0 : 160.0); });
		const cv::Mat darker = row(100, [&](int k) { return gain * (k < 60 ? 160.0 : 120.0); });
		EXPECT_EQ(step(brighter, 0.25), 60) << gain;
		EXPECT_EQ(step(darker, 0.25), 60) << gain;
	}
}

TEST(BrightnessStep, ASignedStepCountsOnlyItsWay)
{
	// Floor 160, a shadow 40 % darker over pixels 30 to 49, the floor again,
	// then a face 30 % brighter from pixel 80.
	const cv::Mat r = row(120, [](int k) { return k >= 80 ? 208.0 : (k >= 30 && k < 50) ? 96.0 : 160.0; });
	EXPECT_EQ(step(r, 0.2), 30);  // either way: the shadow's edge
	EXPECT_EQ(step(r, 0.2, 0, 1000, 4, StepSign::Darker), 30);
	// Brighter only passes into the shadow, but leaving it is a step up too
	// (its limit: docs/method.md); past it, the face.
	EXPECT_EQ(step(r, 0.2, 0, 1000, 4, StepSign::Brighter), 50);
	EXPECT_EQ(step(r, 0.2, 55, 1000, 4, StepSign::Brighter), 80);
	EXPECT_EQ(step(r, 0.2, 55, 1000, 4, StepSign::Darker), -1);
	EXPECT_EQ(toString(stepSignFromString("brighter")), "brighter");
	EXPECT_THROW(stepSignFromString("up"), std::invalid_argument);
}

TEST(BrightnessStep, NoiseGradualLightAndThinJointsAreNotSteps)
{
	std::mt19937 rng(7);
	std::normal_distribution<double> noise(0, 4);
	// Vignetting: 40 % darker over 200 px; noise of 4 grey levels; a dark
	// joint of one pixel every 25 (tiles), 30 % darker than the tile.
	const cv::Mat floor = row(200, [&](int k) {
		const double tile = k % 25 == 0 ? 0.7 : 1.0;
		return 170.0 * (1.0 - 0.4 * k / 200.0) * tile + noise(rng);
	});
	EXPECT_EQ(step(floor, 0.15), -1);
	// A step of ln 1.3 past pixel 150 on the same floor is still found.
	const cv::Mat walled = row(200, [&](int k) {
		const double tile = k % 25 == 0 ? 0.7 : 1.0;
		return 170.0 * (1.0 - 0.4 * k / 200.0) * (k < 150 ? tile : 1.3) + noise(rng);
	});
	const int found = step(walled, 0.15);
	EXPECT_GE(found, 146);
	EXPECT_LE(found, 151);
}

TEST(BrightnessStep, TheScannerStopsAtAFaceTheColourModelSeesThrough)
{
	// A wall of the floor's very colour, 40 % brighter, beyond floor radius 120 px.
	const OmniCameraModel cam{CameraParams{}};
	cv::Mat img = test::drawFloorDisc(cam, 120.0);
	const auto& p = cam.params();
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
			img.at<cv::Vec3b>(v, u) = std::hypot(u - p.cx, v - p.cy) <= 120.0 ? test::kFloor : test::kFloor * 1.4;
	// The wall's colour is the floor's, brighter: a chromaticity histogram would
	// take it for floor. Here the histogram has seen both, so colour sees through.
	ColourHistogram h = test::floorHistogram();
	const cv::Vec3b wall = test::kFloor * 1.4;
	for (int i = 0; i < 100; ++i) h.addPixel(&wall[0]);
	const FreeSpaceClassifier classifier{h, 0.05};

	PolarScannerParams off, on;
	on.step_threshold = 0.2;
	const auto colour_only = PolarScanner(cam, off).scan(img, classifier);
	const auto with_step = PolarScanner(cam, on).scan(img, classifier);
	const double truth = cam.distanceFromRho(120.0);
	const double pixel = cam.distanceFromRho(121.0) - truth;  // the drawn disc's edge is pixel-sharp
	for (std::size_t i = 0; i < with_step.size(); ++i)
	{
		EXPECT_EQ(colour_only[i].status, RayStatus::NoHit) << i;
		ASSERT_EQ(with_step[i].status, RayStatus::Hit) << i;
		EXPECT_TRUE(with_step[i].by_step);
		EXPECT_NEAR(with_step[i].range, truth, pixel) << i;
	}
}

TEST(BrightnessStep, AColourHitAtAFacesFootStaysTheColours)
{
	// A wall of another colour and 50 % brighter than the floor: colour and
	// step agree on the edge, and the colour places it, with either
	// boundary model, exactly as with the cue off.
	const OmniCameraModel cam{CameraParams{}};
	const auto& p = cam.params();
	const cv::Vec3b wall = test::kWall * 1.5;
	cv::Mat img(p.image_height, p.image_width, CV_8UC3);
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
			img.at<cv::Vec3b>(v, u) = std::hypot(u - p.cx, v - p.cy) <= 120.0 ? test::kFloor : wall;
	const FreeSpaceClassifier classifier{test::floorHistogram(), 0.05};
	for (const BoundaryModel model : {BoundaryModel::Midpoint, BoundaryModel::Subpixel})
	{
		PolarScannerParams off, on;
		off.boundary_model = on.boundary_model = model;
		on.step_threshold = 0.1;  // the wall is ln(1.5) = 0.4 brighter
		const auto a = PolarScanner(cam, off).scan(img, classifier);
		const auto b = PolarScanner(cam, on).scan(img, classifier);
		for (std::size_t i = 0; i < a.size(); ++i)
		{
			ASSERT_EQ(a[i].status, RayStatus::Hit);
			EXPECT_EQ(b[i].status, RayStatus::Hit);
			EXPECT_FALSE(b[i].by_step) << i;
			EXPECT_FLOAT_EQ(b[i].range, a[i].range) << i;
		}
	}
}

TEST(BrightnessStep, TheFootIsAtMostAWindowPastWhereTheRatioIsReached)
{
	// Light falling faster and faster outwards from pixel 50: the windows'
	// ratio first reaches e^0.2 at pixel 57 and keeps growing until about
	// pixel 75; the foot is taken at most a window (4) past 57.
	const cv::Mat r = row(120, [](int k) { return k < 50 ? 200.0 : 200.0 * std::exp(-0.004 * (k - 50) * (k - 50)); });
	const int found = step(r, 0.2);
	EXPECT_GE(found, 57);
	EXPECT_LE(found, 57 + 4);
}
