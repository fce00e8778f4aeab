// Intrinsics from real images: ten photographs of a checkerboard through a
// real paraboloid mirror (../shared/data/real/mei-paraboloid, made by
// others). The board must be found in at least 9 of them (OpenCV's classic
// detector alone finds 8), the reprojection error must be at most 0.35 px,
// and the principal point must agree with the reference the data's README
// gives (measured with plain OpenCV: cx 643.7, cy 521.3, xi 1.443).
#include <omnirange/train/CheckerboardCalibration.h>
#include <omnirange/train/MirrorRim.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace omnirange;

TEST(CheckerboardCalibration, RealParaboloidImages)
{
	const std::string dir = std::string(OMNIRANGE_SOURCE_DIR) + "/../shared/data/real/mei-paraboloid";
	if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
	std::vector<std::string> files;
	for (int i = 1; i <= 10; ++i)
	{
		char name[32];
		std::snprintf(name, sizeof name, "/img_para_%03d.pgm", i);
		files.push_back(dir + name);
	}
	CheckerboardOptions o;  // 8 x 6 inner corners, 0.042 m squares (the data's README)
	const CheckerboardCalibration c = calibrateFromCheckerboards(files, o);
	EXPECT_GE(c.found(), 9);
	EXPECT_GE(c.used(), 6);
	EXPECT_LE(c.rms, 0.35);
	EXPECT_NEAR(c.K(0, 2), 643.7, 3.0);
	EXPECT_NEAR(c.K(1, 2), 521.3, 3.0);
	EXPECT_NEAR(c.xi, 1.443, 0.1);
	for (const auto& i : c.images)
	{
		if (!i.used) continue;
		EXPECT_LT(i.rms, 1.0) << i.file;
	}
	EXPECT_NE(c.yaml().find("camera_matrix"), std::string::npos);
}

TEST(MirrorRim, TheDiscsCentreIsThePrincipalPointWithin3Px)
{
	const std::string dir = std::string(OMNIRANGE_SOURCE_DIR) + "/../shared/data/real/mei-paraboloid";
	if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
	// Three images, no board needed: the reference principal point is the
	// data's README's (plain OpenCV's calibration).
	const MirrorRim rim =
		detectMirrorRim({dir + "/img_para_001.pgm", dir + "/img_para_004.pgm", dir + "/img_para_008.pgm"});
	EXPECT_NEAR(rim.cx, 643.7, 3.0);
	EXPECT_NEAR(rim.cy, 521.3, 3.0);
	EXPECT_GT(rim.radius, 300.0);  // the disc fills most of the 1024-px height
	EXPECT_LT(rim.radius, 420.0);
	EXPECT_LT(rim.ellipticity, 0.05);
	EXPECT_THROW(detectMirrorRim({"/nonexistent.png"}), std::runtime_error);
}

TEST(CheckerboardCalibration, TooFewBoardsOrAnUnreadableImageIsAnError)
{
	EXPECT_THROW(calibrateFromCheckerboards({"/nonexistent.pgm"}), std::runtime_error);
	const std::string dir = std::string(OMNIRANGE_SOURCE_DIR) + "/../shared/data/real/mei-paraboloid";
	if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
	EXPECT_THROW(calibrateFromCheckerboards({dir + "/img_para_001.pgm", dir + "/img_para_003.pgm"}), std::runtime_error);
}
