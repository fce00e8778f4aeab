// Colour histogram: counting, eq. (4)/(5), the colour spaces, and the file.
#include <omnirange/core/ColourHistogram.h>
#include <omnirange/core/ColourModel.h>
#include <omnirange/core/FreeSpaceClassifier.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <opencv2/core.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace omnirange;

namespace
{
std::string tempPath(const std::string& name)
{
	return testing::TempDir() + "omnirange_" + name;
}

std::string readAll(const std::string& path)
{
	std::ifstream f(path, std::ios::binary);
	std::ostringstream s;
	s << f.rdbuf();
	return s.str();
}

void writeAll(const std::string& path, const std::string& bytes)
{
	std::ofstream(path, std::ios::binary) << bytes;
}

ColourHistogram sample()
{
	ColourHistogram h;
	const std::uint8_t green[3] = {60, 140, 70}, grey[3] = {128, 128, 128};
	for (int i = 0; i < 90; ++i) h.addPixel(green);
	for (int i = 0; i < 10; ++i) h.addPixel(grey);
	return h;
}
}  // namespace

TEST(ColourHistogram, BinsAndProbabilities)
{
	const ColourHistogram h = sample();
	EXPECT_EQ(h.total(), 100u);
	EXPECT_EQ(h.binner().binCount(), 13u * 13u * 13u);
	// R=70 -> bin 3, G=140 -> bin 7, B=60 -> bin 3 (x * 13 / 256).
	const std::uint32_t green_bin = 3 * 169 + 7 * 13 + 3;
	EXPECT_EQ(h.count(green_bin), 90u);
	EXPECT_DOUBLE_EQ(h.probability(green_bin), 0.9);  // eq. (4)
	const std::uint8_t grey[3] = {128, 128, 128};
	EXPECT_DOUBLE_EQ(h.probability(h.binner().binOf(grey)), 0.1);
}

TEST(ColourHistogram, AddImageCountsOnlyMaskedPixels)
{
	cv::Mat img(4, 5, CV_8UC3, cv::Scalar(10, 20, 30));
	cv::Mat mask = cv::Mat::zeros(4, 5, CV_8UC1);
	mask.at<std::uint8_t>(1, 1) = 255;
	mask.at<std::uint8_t>(2, 3) = 1;
	ColourHistogram h;
	h.addImage(img, mask);
	EXPECT_EQ(h.total(), 2u);
	EXPECT_THROW(h.addImage(img, cv::Mat::zeros(3, 5, CV_8UC1)), std::invalid_argument);
}

TEST(ColourHistogram, ThresholdDecidesFreeSpace)
{
	const ColourHistogram h = sample();
	const std::uint8_t green[3] = {60, 140, 70}, grey[3] = {128, 128, 128},
					   red[3] = {0, 0, 255};
	const FreeSpaceClassifier c05(h, 0.05);
	EXPECT_TRUE(c05.isFree(green));
	EXPECT_TRUE(c05.isFree(grey));  // P = 0.1 >= 0.05
	EXPECT_FALSE(c05.isFree(red));  // never seen
	const FreeSpaceClassifier c2(h, 0.2);
	EXPECT_TRUE(c2.isFree(green));
	EXPECT_FALSE(c2.isFree(grey));  // P = 0.1 < 0.2
	EXPECT_EQ(c2.freeBinCount(), 1u);
}

TEST(ColourHistogram, ClassifierRejectsBadInput)
{
	EXPECT_THROW(FreeSpaceClassifier(sample(), -0.1), std::invalid_argument);
	EXPECT_THROW(FreeSpaceClassifier(sample(), 1.5), std::invalid_argument);
	EXPECT_THROW(FreeSpaceClassifier(ColourHistogram{}, 0.05), std::invalid_argument);
	EXPECT_THROW(ColourHistogram(ColourSpace::RGB, 0), std::invalid_argument);
}

TEST(ColourHistogram, HsvSeparatesBrightnessFromHue)
{
	// Two greens of one hue and saturation, one dark and one bright, share an
	// HSV hue/saturation bin but differ in RGB bins.
	const std::uint8_t dark[3] = {20, 60, 30}, bright[3] = {60, 180, 90};
	std::uint8_t a[3], b[3];
	bgrToHsv(dark, a);
	bgrToHsv(bright, b);
	EXPECT_EQ(a[0], b[0]);
	EXPECT_EQ(a[1], b[1]);
	EXPECT_EQ(a[2], 60);
	EXPECT_EQ(b[2], 180);
	// Pure hues land where the full-range hue circle puts them.
	const std::uint8_t red[3] = {0, 0, 255}, green[3] = {0, 255, 0}, blue[3] = {255, 0, 0};
	bgrToHsv(red, a);
	EXPECT_EQ(a[0], 0);
	bgrToHsv(green, a);
	EXPECT_EQ(a[0], 85);  // 256 / 3
	bgrToHsv(blue, a);
	EXPECT_EQ(a[0], 170);
	const ColourBinner hsv(ColourSpace::HSV, 4), rgb(ColourSpace::RGB, 4);
	EXPECT_EQ(hsv.binOf(dark) / 4, hsv.binOf(bright) / 4);  // same H, S bins
	EXPECT_NE(rgb.binOf(dark), rgb.binOf(bright));
}

TEST(ColourHistogram, SaveLoadRoundTrip)
{
	for (const ColourSpace space : {ColourSpace::RGB, ColourSpace::HSV})
	{
		ColourHistogram h(space, 7);
		const std::uint8_t px[3] = {1, 200, 33}, qx[3] = {90, 90, 10};
		for (int i = 0; i < 5; ++i) h.addPixel(px);
		h.addPixel(qx);
		const std::string path = tempPath("roundtrip.hist");
		h.save(path);
		const ColourHistogram back = ColourHistogram::load(path);
		EXPECT_EQ(back.space(), space);
		EXPECT_EQ(back.binsPerChannel(), 7);
		EXPECT_EQ(back.total(), 6u);
		for (std::uint32_t b = 0; b < h.binner().binCount(); ++b)
			ASSERT_EQ(back.count(b), h.count(b)) << "bin " << b;
		std::remove(path.c_str());
	}
}

TEST(ColourHistogram, CorruptFilesAreRejectedWithTheirName)
{
	const std::string path = tempPath("corrupt.hist");
	sample().save(path);
	const std::string good = readAll(path);

	const auto expectRejected = [&](const std::string& bytes, const std::string& why) {
		writeAll(path, bytes);
		try
		{
			ColourHistogram::load(path);
			ADD_FAILURE() << "accepted: " << why;
		}
		catch (const std::runtime_error& e)
		{
			EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
		}
	};
	std::string flipped = good;
	flipped[good.size() / 2] ^= 0x10;
	expectRejected(flipped, "a flipped bit in the counts");
	expectRejected(good.substr(0, good.size() - 9), "a truncated file");
	expectRejected("", "an empty file");
	expectRejected("P6\n640 480\n255\n" + std::string(100, 'x'), "another format");
	std::string version = good;
	version[8] = 9;
	expectRejected(version, "a future version");
	EXPECT_THROW(ColourHistogram::load(tempPath("no_such_file.hist")), std::runtime_error);
	std::remove(path.c_str());
}

TEST(ColourHistogram, SaveFailureLeavesTheOldFileWhole)
{
	const std::string path = tempPath("keep.hist");
	sample().save(path);
	const std::string before = readAll(path);
	// A folder that does not exist: the save fails and nothing changes.
	EXPECT_THROW(sample().save(tempPath("missing_dir/x.hist")), std::runtime_error);
	EXPECT_EQ(readAll(path), before);
	std::remove(path.c_str());
}

TEST(ColourSpace, ChromaKeepsAColourThroughAnExposureChange)
{
	const ColourBinner chroma(ColourSpace::Chroma, 13), rgb(ColourSpace::RGB, 13);
	const std::uint8_t floor[3] = {60, 140, 70};  // B, G, R
	const std::uint8_t brighter[3] = {69, 161, 81};  // the same, 15 % more light
	const std::uint8_t wall[3] = {40, 60, 150};
	EXPECT_EQ(chroma.binOf(floor), chroma.binOf(brighter));
	EXPECT_NE(rgb.binOf(floor), rgb.binOf(brighter));
	EXPECT_NE(chroma.binOf(floor), chroma.binOf(wall));
	std::uint8_t c[3];
	bgrToChroma(floor, c);
	EXPECT_NEAR(c[0], 255.0 * 70 / 270, 1.0);  // r
	EXPECT_NEAR(c[1], 255.0 * 140 / 270, 1.0);  // g
	EXPECT_NEAR(c[2], 255.0 * std::log1p(90) / std::log(256.0), 1.0);
	EXPECT_EQ(colourSpaceFromString("chroma"), ColourSpace::Chroma);
	EXPECT_EQ(toString(ColourSpace::Chroma), "CHROMA");
}

TEST(ColourModel, AColourTheObstaclesExplainBetterIsNotFree)
{
	const std::uint8_t green[3] = {60, 140, 70}, grey[3] = {128, 128, 128};
	ColourHistogram obstacles;
	for (int i = 0; i < 10; ++i) obstacles.addPixel(grey);
	const ColourModel model(sample(), obstacles);  // the floor: 90 % green, 10 % grey
	EXPECT_TRUE(model.hasObstacles());
	const FreeSpaceClassifier one_class(model, 0.05, 0.0), two_class(model, 0.05, 1.0);
	EXPECT_TRUE(one_class.isFree(grey));  // the paper's model: P(grey | floor) = 0.1 >= 0.05
	EXPECT_FALSE(two_class.isFree(grey));  // but P(grey | obstacle) = 1 > 0.1
	EXPECT_TRUE(two_class.isFree(green));
	EXPECT_THROW(FreeSpaceClassifier(model, 0.05, -1.0), std::invalid_argument);
	EXPECT_THROW(ColourModel(sample(), ColourHistogram(ColourSpace::HSV)), std::invalid_argument);
}

TEST(ColourModel, SavesBothHistogramsAndReadsAPlainHistogramFile)
{
	const std::uint8_t grey[3] = {128, 128, 128};
	ColourHistogram obstacles;
	obstacles.addPixel(grey);
	const std::string both = tempPath("model.hist"), plain = tempPath("plain.hist");
	ColourModel(sample(), obstacles).save(both);
	sample().save(plain);
	const ColourModel a = ColourModel::load(both), b = ColourModel::load(plain);
	EXPECT_EQ(a.floor.total(), sample().total());
	EXPECT_EQ(a.obstacles.total(), 1u);
	EXPECT_EQ(b.floor.total(), sample().total());
	EXPECT_FALSE(b.hasObstacles());
	EXPECT_THROW(ColourModel::load("/dev/zero"), std::runtime_error);  // not a regular file: refused, not read forever
}

TEST(ColourHistogram, SmoothingSpreadsABinOverItsNeighboursAsAGaussian)
{
	// One colour, in bin (6, 6, 6) of 13 per channel. With sigma = 1 bin the
	// kernel is exp(-k^2 / 2) for k in -3..3, normalised (sum 2.505950): 0.399050 at the
	// centre, 0.242036 one bin away (worked by hand).
	ColourHistogram h(ColourSpace::RGB, 13);
	const std::uint8_t grey[3] = {128, 128, 128};
	for (int i = 0; i < 10; ++i) h.addPixel(grey);
	const std::uint32_t centre = h.binner().binOf(grey);
	EXPECT_EQ(h.smoothedProbabilities(0.0)[centre], 1.0);
	const std::vector<double> p = h.smoothedProbabilities(1.0);
	const double k0 = 0.399050, k1 = 0.242036;
	EXPECT_NEAR(p[centre], k0 * k0 * k0, 1e-5);
	EXPECT_NEAR(p[centre + 1], k0 * k0 * k1, 1e-5);  // one bin along one channel
	EXPECT_NEAR(p[centre + 13 * 13], k0 * k0 * k1, 1e-5);
	EXPECT_NEAR(p[centre + 13 + 1], k0 * k1 * k1, 1e-5);
	double sum = 0;
	for (const double v : p) sum += v;
	EXPECT_NEAR(sum, 1.0, 1e-9);  // nothing reaches past the first or last bin from the middle
	// The classifier: at Theta 0.03 the centre and its six face neighbours are free.
	EXPECT_EQ(FreeSpaceClassifier(ColourModel(h), 0.03, 0.0, 0.0).freeBinCount(), 1u);
	EXPECT_EQ(FreeSpaceClassifier(ColourModel(h), 0.03, 0.0, 1.0).freeBinCount(), 7u);
	EXPECT_THROW(h.smoothedProbabilities(-1.0), std::invalid_argument);
}

TEST(ColourBinner, ADarkerBinKeepsTheBinAtGainOneAndMovesOnlyBrightness)
{
	for (const ColourSpace space : {ColourSpace::RGB, ColourSpace::HSV, ColourSpace::Chroma})
	{
		SCOPED_TRACE(toString(space));
		const std::uint32_t n = 13;
		const ColourBinner binner(space, n);
		const auto channels = [n](std::uint32_t b) {
			return std::array<int, 3>{int(b / (n * n)), int(b / n % n), int(b % n)};
		};
		for (std::uint32_t b = 0; b < binner.binCount(); ++b)
		{
			ASSERT_EQ(binner.darkerBin(b, 1.0), b);
			const auto lit = channels(b), dim = channels(binner.darkerBin(b, 0.6));
			for (int c = 0; c < 3; ++c)
			{
				if (space == ColourSpace::RGB || c == 2)
					ASSERT_LE(dim[c], lit[c]);  // darker, never brighter
				else
					ASSERT_EQ(dim[c], lit[c]);  // hue and saturation, chromaticity: unchanged
			}
			if (space == ColourSpace::RGB)  // the bin's centre times 0.6, in bins
			{
				for (int c = 0; c < 3; ++c) ASSERT_EQ(dim[c], int((lit[c] + 0.5) * 0.6));
			}
		}
		// A colour and the same colour in 60 % of the light (away from bin edges).
		const std::uint8_t lit[3] = {167, 187, 206}, dim[3] = {100, 112, 124};
		EXPECT_EQ(binner.darkerBin(binner.binOf(lit), 0.6), binner.binOf(dim));
	}
}

TEST(FreeSpaceClassifier, ShadowDepthFreesTheFloorInShadowAndNothingElse)
{
	const std::uint8_t floor[3] = {160, 188, 206};  // B, G, R: beige stone
	const std::uint8_t shaded[3] = {112, 132, 144};  // in 70 % of the light
	const std::uint8_t deep[3] = {56, 66, 72};  // in 35 %
	const std::uint8_t brighter[3] = {192, 226, 247};  // in 120 %
	const std::uint8_t other_hue[3] = {150, 120, 100};  // a blue-grey as dark as the shade
	for (const ColourSpace space : {ColourSpace::RGB, ColourSpace::HSV, ColourSpace::Chroma})
	{
		ColourHistogram h(space, 13);
		for (int i = 0; i < 90; ++i) h.addPixel(floor);
		for (int i = 0; i < 10; ++i) h.addPixel(other_hue);
		const FreeSpaceClassifier as_trained(h, 0.2), in_shadow(h, 0.2, 0.0, 0.0, 0.5);
		SCOPED_TRACE(toString(space));
		EXPECT_TRUE(as_trained.isFree(floor));
		EXPECT_FALSE(as_trained.isFree(shaded));
		EXPECT_TRUE(in_shadow.isFree(floor));
		EXPECT_TRUE(in_shadow.isFree(shaded));
		EXPECT_FALSE(in_shadow.isFree(deep));  // darker than the depth
		EXPECT_EQ(in_shadow.isFree(brighter), as_trained.isFree(brighter));  // nothing brighter is added
		EXPECT_FALSE(in_shadow.isFree(other_hue));  // P = 0.1, and its darker self is not the floor's
		// A colour training saw on an obstacle, even once in a hundred obstacle
		// pixels (the floor explaining it ninety times better), is no shadow.
		ColourHistogram obstacles(space, 13);
		obstacles.addPixel(shaded);
		for (int i = 0; i < 99; ++i) obstacles.addPixel(other_hue);
		EXPECT_FALSE(FreeSpaceClassifier(ColourModel(h, obstacles), 0.2, 1.0, 0.0, 0.5).isFree(shaded));
		// ...even in the one-class model, which ignores the obstacles for the colours trained as floor.
		EXPECT_FALSE(FreeSpaceClassifier(ColourModel(h, obstacles), 0.2, 0.0, 0.0, 0.5).isFree(shaded));
		EXPECT_TRUE(FreeSpaceClassifier(ColourModel(h, obstacles), 0.2, 0.0, 0.0, 0.5).isFree(floor));
	}
	EXPECT_THROW(FreeSpaceClassifier(sample(), 0.05, 0.0, 0.0, 0.95), std::invalid_argument);
	EXPECT_THROW(FreeSpaceClassifier(sample(), 0.05, 0.0, 0.0, -0.1), std::invalid_argument);
}
