// The edge bias: the hit's contrast with the floor before it, its bins, the
// correction the scanner adds by bin, and learning it from laser differences.
#include "SyntheticOmni.h"

#include <omnirange/core/EdgeBias.h>
#include <omnirange/core/FreeSpaceClassifier.h>
#include <omnirange/core/PolarScanner.h>
#include <omnirange/train/EdgeBiasLearning.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace omnirange;

namespace
{
/** ln((a + 12) / (b + 12)): the contrast of brightness a over b, with the dark offset. */
double contrastOf(double a, double b) { return std::log((a + 12.0) / (b + 12.0)); }

int brightness(const cv::Vec3b& c) { return c[0] + c[1] + c[2]; }
}  // namespace

TEST(EdgeBias, TheContrastComparesTheHitWithTheFloorFourToEightPixelsBefore)
{
	// Pixels 0-19: 10 * k grey (B = G = R); the hit at 15 is 40 per channel.
	cv::Mat r(1, 20, CV_8UC3);
	for (int k = 0; k < 20; ++k) r.at<cv::Vec3b>(0, k) = cv::Vec3b::all(static_cast<std::uint8_t>(10 * k));
	r.at<cv::Vec3b>(0, 15) = cv::Vec3b::all(40);
	std::vector<std::int32_t> pix(20);
	std::iota(pix.begin(), pix.end(), 0);
	// Pixels 7 to 11 before it: mean grey 90, brightness 270; the hit's is 120.
	EXPECT_NEAR(edgeContrast(r.ptr<std::uint8_t>(), pix.data(), 15), contrastOf(120, 270), 1e-6);
	EXPECT_TRUE(std::isnan(edgeContrast(r.ptr<std::uint8_t>(), pix.data(), 7)));  // no floor 8 px before
	EXPECT_FALSE(std::isnan(edgeContrast(r.ptr<std::uint8_t>(), pix.data(), 8)));
}

TEST(EdgeBias, BinsAreFiveHundredthsWideFromMinusAHalf)
{
	EXPECT_EQ(edgeContrastBin(-0.5), 0);
	EXPECT_EQ(edgeContrastBin(-0.46), 0);
	EXPECT_EQ(edgeContrastBin(-0.44), 1);
	EXPECT_EQ(edgeContrastBin(0.01), 10);
	EXPECT_EQ(edgeContrastBin(0.49), 19);
	EXPECT_EQ(edgeContrastBin(0.51), -1);
	EXPECT_EQ(edgeContrastBin(-0.51), -1);  // darker than a shadow: the obstacle's face
	EXPECT_EQ(edgeContrastBin(std::nan("")), -1);
}

TEST(EdgeBias, TheBiasIsLinearBetweenBinCentres)
{
	// Bin 0's centre is at -0.475, bin 1's at -0.425; the list stops at bin 1.
	const std::vector<double> bias{0.1, 0.2};
	EXPECT_NEAR(edgeBiasAt(bias, -0.475), 0.1, 1e-12);
	EXPECT_NEAR(edgeBiasAt(bias, -0.49), 0.1, 1e-12);  // before the first centre: its value
	EXPECT_NEAR(edgeBiasAt(bias, -0.46), 0.13, 1e-12);
	EXPECT_NEAR(edgeBiasAt(bias, -0.45), 0.15, 1e-12);  // a bin edge: no jump
	EXPECT_NEAR(edgeBiasAt(bias, -0.425), 0.2, 1e-12);
	EXPECT_NEAR(edgeBiasAt(bias, -0.4), 0.1, 1e-12);  // halfway to bin 2, past the list (0)
	EXPECT_EQ(edgeBiasAt(bias, 0.0), 0.0);
	EXPECT_EQ(edgeBiasAt(bias, -0.7), 0.0);  // outside the bins
	EXPECT_EQ(edgeBiasAt(bias, std::nan("")), 0.0);
	EXPECT_EQ(edgeBiasAt({}, -0.45), 0.0);
}

TEST(EdgeBias, TheScannerAddsTheHitsBinsAndNoOthers)
{
	const OmniCameraModel cam{CameraParams{}};
	const FreeSpaceClassifier classifier{test::floorHistogram(), 0.05};
	const cv::Mat img = test::drawFloorDisc(cam, 100.0);
	const PolarScanner plain(cam, PolarScannerParams{});
	const auto before = plain.scan(img, classifier);
	// Every hit is floor green into brick red: one contrast, one bin.
	const double contrast = contrastOf(brightness(test::kWall), brightness(test::kFloor));
	const int bin = edgeContrastBin(contrast);
	ASSERT_GE(bin, 0);
	PolarScannerParams p;
	p.edge_bias.assign(kEdgeContrastBins, -0.2);  // the bins two or more away would shorten the rays
	for (int k = bin - 1; k <= bin + 1; ++k) p.edge_bias.at(k) = 0.1;
	const auto after = PolarScanner(cam, p).scan(img, classifier);
	ASSERT_EQ(after.size(), before.size());
	for (std::size_t i = 0; i < after.size(); ++i)
	{
		ASSERT_EQ(after[i].status, RayStatus::Hit);
		EXPECT_NEAR(after[i].edge_contrast, contrast, 1e-5);
		EXPECT_NEAR(after[i].range, before[i].range + 0.1, 1e-5);
		EXPECT_NEAR(after[i].hit_rho, cam.rhoFromDistance(after[i].range), 1e-3);
	}
	p.edge_bias.assign(kEdgeContrastBins, 0.0);
	for (int k = 0; k < kEdgeContrastBins; ++k)
		if (std::abs(k - bin) >= 2) p.edge_bias[k] = 0.3;
	const auto unchanged = PolarScanner(cam, p).scan(img, classifier);
	for (std::size_t i = 0; i < after.size(); ++i) EXPECT_EQ(unchanged[i].range, before[i].range);
	p.edge_bias.assign(21, 0.0);
	EXPECT_THROW(PolarScanner(cam, p), std::invalid_argument);
	p.edge_bias = {0.6};
	EXPECT_THROW(PolarScanner(cam, p), std::invalid_argument);
}

TEST(EdgeBias, LearningTakesEachWellSampledBinsMedianDifference)
{
	std::vector<EdgeSample> samples;
	// Bin 3 (contrast -0.33): 40 samples, differences 0.005 .. 0.395 of which
	// those above 0.3 are another object and left out: the median of 0.005 .. 0.295.
	for (int k = 1; k <= 40; ++k) samples.push_back({-0.33f, 0.01 * k - 0.005});
	// Bin 5 (contrast -0.23): 9 samples, too few to learn from.
	for (int k = 0; k < 9; ++k) samples.push_back({-0.23f, 0.2});
	// Bin 1 (contrast -0.43): 30 samples at -0.05.
	for (int k = 0; k < 30; ++k) samples.push_back({-0.43f, -0.05});
	// No contrast (a hit by the base), or darker than a shadow: never learned from.
	for (int k = 0; k < 50; ++k) samples.push_back({std::nanf(""), 0.1}), samples.push_back({-0.8f, 0.1});
	const std::vector<double> bias = learnEdgeBias(samples, 30);
	ASSERT_EQ(bias.size(), 4u);  // up to the last learned bin
	EXPECT_EQ(bias[0], 0.0);
	EXPECT_DOUBLE_EQ(bias[1], -0.05);
	EXPECT_EQ(bias[2], 0.0);
	EXPECT_NEAR(bias[3], 0.155, 1e-9);  // 30 values 0.005 .. 0.295: the upper median
	EXPECT_TRUE(learnEdgeBias(samples, 100).empty());
	EXPECT_THROW(learnEdgeBias(samples, 0), std::invalid_argument);
}
