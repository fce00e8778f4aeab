// Intrinsics from real images: ten photographs of a checkerboard through a
// real paraboloid mirror (../shared/data/real/mei-paraboloid, made by
// others). The board must be found in at least 9 of them (OpenCV's classic
// detector alone finds 8), the reprojection error must be at most 0.35 px,
// and the principal point must agree with the reference the data's README
// gives (measured with plain OpenCV: cx 643.7, cy 521.3, xi 1.443).
#include <omnirange_apps/CalibrateApp.h>
#include <omnirange/train/CheckerboardCalibration.h>
#include <omnirange/train/MirrorRim.h>

#include "../common/FactorySample.h"
#include "../common/RenderedCheckerboard.h"

#include <gtest/gtest.h>

#include <opencv2/ccalib/omnidir.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace omnirange;

namespace
{
const std::string kRealDir = std::string(OMNIRANGE_SOURCE_DIR) + "/../shared/data/real/mei-paraboloid";

/** The real images with these numbers (1..10). */
std::vector<std::string> realImages(const std::vector<int>& numbers)
{
	std::vector<std::string> files;
	for (const int i : numbers)
	{
		char name[32];
		std::snprintf(name, sizeof name, "/img_para_%03d.pgm", i);
		files.push_back(kRealDir + name);
	}
	return files;
}

/** omnirange-calibrate with these arguments after the program's name; its exception's text, or "". */
std::string calibrateFails(std::vector<std::string> args)
{
	using omnirange::app::CalibrateApp;
	args.insert(args.begin(), "omnirange-calibrate");
	std::vector<const char*> argv;
	for (const auto& a : args) argv.push_back(a.c_str());
	try
	{
		CalibrateApp app(CalibrateApp::parse(static_cast<int>(argv.size()), argv.data()));
		if (!app.options().rim_images.empty()) app.runRim();
		else app.runIntrinsics();
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "";
}

/** The ten real images calibrated once for every test here. */
class RealParaboloid : public ::testing::Test
{
   protected:
	static void SetUpTestSuite()
	{
		if (!std::filesystem::exists(kRealDir)) return;
		// 8 x 6 inner corners, 0.042 m squares (the data's README)
		calibration_ = new CheckerboardCalibration(
			calibrateFromCheckerboards(realImages({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}), CheckerboardOptions{}));
	}
	static void TearDownTestSuite() { delete calibration_, calibration_ = nullptr; }
	void SetUp() override
	{
		if (!calibration_) GTEST_SKIP() << "no " << kRealDir;
	}
	static CheckerboardCalibration* calibration_;
};
CheckerboardCalibration* RealParaboloid::calibration_ = nullptr;
}  // namespace

TEST_F(RealParaboloid, TheBoardIsFoundAndTheErrorIsSmall)
{
	const CheckerboardCalibration& c = *calibration_;
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

TEST_F(RealParaboloid, TheRangefindersMeiModelProjectsAsOpenCVDoes)
{
	// The rangefinder's Mei model, whole (skew, fx != fy, p1, p2 included),
	// against cv::omnidir::projectPoints: directions from the axis out past
	// the horizon, all round.
	const CheckerboardCalibration& c = *calibration_;
	const OmniCameraModel model(meiCamera(c));
	EXPECT_EQ(model.params().mirror_model, MirrorModel::Mei);
	EXPECT_EQ(model.params().image_width, 1280);
	EXPECT_FALSE(model.radial());  // the fitted skew and tangential terms are not zero
	std::vector<cv::Vec3d> directions;
	for (double deg = 10; deg <= 110; deg += 10)
		for (double az = 0; az < 360; az += 45)
		{
			const double t = deg * M_PI / 180, a = az * M_PI / 180;
			directions.push_back({std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)});
		}
	std::vector<cv::Vec2d> pixels;
	cv::omnidir::projectPoints(directions, pixels, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), c.K, c.xi, c.D);
	double radial_only = 0;
	for (std::size_t i = 0; i < pixels.size(); ++i)
	{
		const cv::Vec3d& d = directions[i];
		const double theta = std::acos(d[2]);
		// OpenCV's y runs down the image; on screen the angle is counter-clockwise.
		const double bearing = model.bearingFromScreenAzimuth(std::atan2(-d[1], d[0]));
		const Pixel p = model.pixelFromPolar(bearing, model.rhoFromTheta(theta));
		EXPECT_NEAR(p.u, pixels[i][0], 1e-6) << theta << " " << bearing;
		EXPECT_NEAR(p.v, pixels[i][1], 1e-6) << theta << " " << bearing;
		// ...and back: OpenCV's pixel gives the direction.
		const auto [b, rho] = model.polarFromPixel({pixels[i][0], pixels[i][1]});
		EXPECT_NEAR(model.thetaFromRho(rho), theta, 1e-9);
		EXPECT_NEAR(std::remainder(b - bearing, 2 * M_PI), 0.0, 1e-9);
		radial_only = std::max(radial_only, std::hypot(pixels[i][0] - c.K(0, 2), pixels[i][1] - c.K(1, 2)) - rho);
	}
	// What a radial model would have missed on these images (mostly the
	// fitted skew, -1.7 px), for the record.
	std::printf("largest radius difference a radial model would make: %.3f px\n", radial_only);
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

TEST_F(RealParaboloid, TheCentreMovesLittleWhenAGroupOfBoardsIsLeftOut)
{
	const CheckerboardCalibration& c = *calibration_;
	EXPECT_EQ(c.centre_subsets, std::min(c.used(), kCentreSubsets));  // each left-out group converged
	EXPECT_GT(c.centre_spread, 0.0);
	EXPECT_LT(c.centre_spread, 3.0);  // the README's reference agrees within 3 px too
}

TEST(RealParaboloidFewBoards, BoardsThatDoNotPinTheCentreAreDoubtedAndNothingIsSaved)
{
	if (!std::filesystem::exists(kRealDir)) GTEST_SKIP() << "no " << kRealDir;
	const std::string dir = std::filesystem::temp_directory_path() / "omnirange_calib_spread";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	const std::string ini = dir + "/cam.ini";
	std::ofstream(ini) << "[rangefinder]\nthreshold = 0.05\n";
	// The five odd-numbered images: 4 used boards, RMS 0.34 px, and yet the
	// centre moves 3.1 px without one of them.
	std::vector<std::string> args{"--save-to", ini};
	for (const auto& f : realImages({1, 3, 5, 7, 9})) args.insert(args.end(), {"--checkerboard", f});
	const std::string why = calibrateFails(args);
	EXPECT_NE(why.find("may be wrong"), std::string::npos) << why;
	EXPECT_EQ(test::readText(ini), "[rangefinder]\nthreshold = 0.05\n");  // nothing saved
	// Three used boards: the spread cannot be measured, which is itself a
	// doubt; --accept saves all the same.
	args = {"--save-to", ini, "--accept"};
	for (const auto& f : realImages({1, 2, 3, 4})) args.insert(args.end(), {"--checkerboard", f});
	testing::internal::CaptureStderr();
	EXPECT_EQ(calibrateFails(args), "");
	const std::string warnings = testing::internal::GetCapturedStderr();
	EXPECT_NE(warnings.find("only 3 boards were used"), std::string::npos) << warnings;
	EXPECT_NE(test::readText(ini).find("mirror_model = mei"), std::string::npos);
}

TEST(RealParaboloidFewBoards, CopiesOfOneViewCountOnceAndSaveNothing)
{
	if (!std::filesystem::exists(kRealDir)) GTEST_SKIP() << "no " << kRealDir;
	const std::string dir = std::filesystem::temp_directory_path() / "omnirange_calib_copies";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	// Two views, each copied three times under other names (a still camera's
	// burst): a fit of two views with a small RMS and a centre that "moves 0 px".
	std::vector<std::string> args{"-o", dir + "/intr.yaml"};
	for (const auto& f : realImages({1, 2}))
		for (int copy = 0; copy < 3; ++copy)
		{
			const std::string name = dir + "/" + std::filesystem::path(f).stem().string() + "_" + std::to_string(copy) + ".pgm";
			std::filesystem::copy_file(f, name);
			args.insert(args.end(), {"--checkerboard", name});
		}
	const std::string why = calibrateFails(args);
	EXPECT_NE(why.find("found in 2 of 6 images (views of the same board position counted once)"), std::string::npos)
		<< why;
	EXPECT_FALSE(std::filesystem::exists(dir + "/intr.yaml"));
}

TEST(MirrorRim, ADiscFarFromTheCalibratedCentreIsDoubted)
{
	if (!std::filesystem::exists(kRealDir)) GTEST_SKIP() << "no " << kRealDir;
	const std::string dir = std::filesystem::temp_directory_path() / "omnirange_rim_offset";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	const auto rimWith = [&](double cx, double cy) {
		const std::string ini = dir + "/cam.ini";
		std::ofstream(ini, std::ios::trunc) << "[rangefinder]\nimage_width = 1280\nimage_height = 1024\nmirror_model = mei\n"
											   "xi = 1.44\ngamma = 365\ncx = " << cx << "\ncy = " << cy << "\n";
		std::vector<std::string> args{"-c", ini};
		for (const auto& f : realImages({1, 4, 8})) args.insert(args.end(), {"--rim", f});
		return calibrateFails(args);
	};
	EXPECT_EQ(rimWith(643.5, 521.1), "");  // the checkerboards' centre: the disc agrees
	const std::string why = rimWith(600.0, 521.1);
	EXPECT_NE(why.find("may be wrong"), std::string::npos) << why;
}

TEST(CheckerboardCalibration, RimImagesOfACameraThatMovedBetweenThemAreDoubted)
{
	// The real images' own discs agree; one of them shifted 80 px (the camera moved) gives a centre of neither.
	const auto real = realImages({1, 4, 8});
	if (!std::filesystem::exists(real[0])) GTEST_SKIP() << "no " << real[0];
	const MirrorRim still = detectMirrorRim(real);
	EXPECT_LT(still.centre_spread, 3.0);
	const std::string dir = std::filesystem::temp_directory_path() / "omnirange_rim_moved";
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	const cv::Mat first = cv::imread(real[0], cv::IMREAD_UNCHANGED);
	cv::Mat moved = cv::Mat::zeros(first.size(), first.type());
	first.colRange(0, first.cols - 80).copyTo(moved.colRange(80, first.cols));
	cv::imwrite(dir + "/moved.pgm", moved);
	const MirrorRim both = detectMirrorRim({real[0], dir + "/moved.pgm"});
	EXPECT_GT(both.centre_spread, 30.0);
	const std::string why = calibrateFails({"--rim", real[0], "--rim", dir + "/moved.pgm"});
	EXPECT_NE(why.find("moved between the images"), std::string::npos) << why;
}

TEST(CheckerboardCalibration, TooFewBoardsOrAnUnreadableImageIsAnError)
{
	EXPECT_THROW(calibrateFromCheckerboards({"/nonexistent.pgm"}), std::runtime_error);
	const std::string dir = std::string(OMNIRANGE_SOURCE_DIR) + "/../shared/data/real/mei-paraboloid";
	if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
	EXPECT_THROW(calibrateFromCheckerboards({dir + "/img_para_001.pgm", dir + "/img_para_003.pgm"}), std::runtime_error);
}

TEST(CheckerboardCalibration, MrptsScaramuzzaDetectorFindsTheCornersOpenCVFinds)
{
	// MRPT's OCamCalib-based detector, the last fallback, on its own: on these
	// images it finds few boards (measured: 1 of 10; OpenCV's two find all
	// ten), and where it finds one, its corners are OpenCV's within a pixel.
	const std::string dir = std::string(OMNIRANGE_SOURCE_DIR) + "/../shared/data/real/mei-paraboloid";
	if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no " << dir;
	const cv::Size pattern(8, 6);
	int found = 0;
	for (int i = 1; i <= 10; ++i)
	{
		char name[32];
		std::snprintf(name, sizeof name, "/img_para_%03d.pgm", i);
		const cv::Mat gray = cv::imread(dir + name, cv::IMREAD_GRAYSCALE);
		std::vector<cv::Point2f> mrpt_corners, cv_corners;
		if (!findCheckerboardCorners(gray, pattern, "mrpt-scaramuzza", mrpt_corners)) continue;
		++found;
		ASSERT_EQ(mrpt_corners.size(), 48u) << name;
		ASSERT_TRUE(findCheckerboardCorners(gray, pattern, "classic", cv_corners) ||
					findCheckerboardCorners(gray, pattern, "sector-based", cv_corners))
			<< name;
		// The same corners, in the same order or the board turned half round.
		double same = 0, turned = 0;
		for (std::size_t k = 0; k < 48; ++k)
		{
			same = std::max(same, static_cast<double>(cv::norm(mrpt_corners[k] - cv_corners[k])));
			turned = std::max(turned, static_cast<double>(cv::norm(mrpt_corners[k] - cv_corners[47 - k])));
		}
		EXPECT_LT(std::min(same, turned), 1.0) << name;
	}
	std::printf("MRPT's Scaramuzza detector found the board in %d of 10 images\n", found);
	EXPECT_GE(found, 1);
	std::vector<cv::Point2f> none;
	EXPECT_THROW(findCheckerboardCorners(cv::Mat::zeros(10, 10, CV_8UC1), pattern, "no-such-detector", none),
				 std::invalid_argument);
}

TEST(RealParaboloidMiscount, ABoardGivenOneCornerShortIsFoundAsPartOfTheLargerOne)
{
	// 7 x 5 for the 8 x 6 board: OCamCalib and MATLAB count squares, so a
	// user coming from them gives one less... or one more; the smaller is
	// found inside the real board, and the calibration must say so: on each
	// board where a column or row of corners lies past its edge (here 2 and
	// most of the others).
	if (!std::filesystem::exists(kRealDir)) GTEST_SKIP() << "no " << kRealDir;
	const std::vector<std::string> files = realImages({5, 4, 7, 9, 10, 2});
	CheckerboardOptions o;
	o.columns = 7, o.rows = 5;
	const CheckerboardCalibration c = calibrateFromCheckerboards(files, o);
	int larger = 0;
	for (const auto& i : c.images) larger += i.part_of_larger;
	EXPECT_GE(larger, 1);
	EXPECT_TRUE(c.images.back().part_of_larger) << c.images.back().file;
}

TEST_F(RealParaboloid, TheRightCountIsNotTakenForPartOfALargerBoard)
{
	for (const auto& i : calibration_->images) EXPECT_FALSE(i.part_of_larger) << i.file;
}

namespace
{
/** Twelve views of a board of 9 x 7 squares (8 x 6 inner corners) with a
 * white margin, rendered round a hyperbolic mirror (xi 0.9), the room's
 * grey past the margin. */
class RenderedHyperboloid : public ::testing::Test
{
   protected:
	static void SetUpTestSuite()
	{
		const std::string dir = test::freshDir("omnirange_checkerboards", "hyperboloid");
		const test::MirrorCamera camera;
		const test::RenderedBoard board;
		for (int k = 0; k < 12; ++k)
		{
			const test::BoardPose pose =
				test::facingPose(board, k * M_PI / 6, (15 + 7 * (k % 3)) * M_PI / 180, 0.45 + 0.03 * (k % 2),
								 0.2 * ((k % 4) - 1.5), 0.12 * ((k % 5) - 2));
			const std::string file = dir + "/board_" + std::to_string(10 + k) + ".png";
			cv::imwrite(file, test::renderBoard(camera, board, pose));
			files_.push_back(file);
		}
	}
	static CheckerboardOptions board(int columns, int rows)
	{
		CheckerboardOptions o;
		o.columns = columns, o.rows = rows, o.square = 0.04;
		return o;
	}
	static std::vector<std::string> files_;
};
std::vector<std::string> RenderedHyperboloid::files_;
}  // namespace

TEST_F(RenderedHyperboloid, TheRightCountOnAWhiteMarginIsNotTakenForPartOfALargerBoard)
{
	// 8 x 6, the board's own count: each board is found and fits, and none
	// is doubted. (These views do not make a detector complete a larger grid
	// on the margin, so this holds without the corner check too; that check
	// is pinned by the test below.)
	const CheckerboardCalibration c = calibrateFromCheckerboards(files_, board(8, 6));
	EXPECT_GE(c.found(), 10);
	EXPECT_LT(c.rms, 0.5);
	EXPECT_NEAR(c.K(0, 2), 400.0, 3.0);
	EXPECT_NEAR(c.K(1, 2), 400.0, 3.0);
	for (const auto& i : c.images) EXPECT_FALSE(i.part_of_larger) << i.file << " (" << i.detector << ")";
}

TEST_F(RenderedHyperboloid, ARowOnTheBoardsEdgeIsNoGridOfCornersAndTheBoardsOwnGridIs)
{
	const cv::Mat gray = cv::imread(files_.front(), cv::IMREAD_GRAYSCALE);
	const cv::Size pattern(8, 6);
	std::vector<cv::Point2f> corners;
	ASSERT_TRUE(findCheckerboardCorners(gray, pattern, "classic", corners) ||
				findCheckerboardCorners(gray, pattern, "sector-based", corners));
	const double contrast = saddleContrast(gray, pattern, corners);
	EXPECT_GT(contrast, 50.0);  // ink 25, paper 235: the squares differ by far more
	// The board's own grid: what a board given one corner short (7 x 6) finds as the larger one.
	EXPECT_TRUE(isCheckerboardGrid(gray, pattern, corners, contrast));
	// One column or row more, on the squares' outer edge where the margin
	// begins: margin on both of its outer squares, no corner.
	const auto at = [&](int c, int r) { return corners[static_cast<std::size_t>(r * pattern.width + c)]; };
	std::vector<cv::Point2f> left, right, below = corners;
	for (int r = 0; r < pattern.height; ++r)
	{
		left.push_back(2.f * at(0, r) - at(1, r));
		for (int c = 0; c < pattern.width; ++c)
		{
			left.push_back(at(c, r));
			right.push_back(at(c, r));
		}
		right.push_back(2.f * at(7, r) - at(6, r));
	}
	for (int c = 0; c < pattern.width; ++c) below.push_back(2.f * at(c, 5) - at(c, 4));
	EXPECT_FALSE(isCheckerboardGrid(gray, {9, 6}, left, contrast));
	EXPECT_FALSE(isCheckerboardGrid(gray, {9, 6}, right, contrast));
	EXPECT_FALSE(isCheckerboardGrid(gray, {8, 7}, below, contrast));
	// A grid of the wrong size is none at all.
	EXPECT_FALSE(isCheckerboardGrid(gray, {9, 6}, corners, contrast));
}

TEST_F(RenderedHyperboloid, ABoardGivenOneCornerShortIsStillFoundAsPartOfTheLargerOne)
{
	// 7 x 5 for the 8 x 6 board, the white margin and all: the larger grid the
	// detector finds inside the real board is all corners, and is told.
	const CheckerboardCalibration c = calibrateFromCheckerboards(files_, board(7, 5));
	int larger = 0;
	for (const auto& i : c.images) larger += i.part_of_larger;
	EXPECT_GE(larger, 1);
}

TEST(CheckerboardCalibration, ACheckerboardFolderGivesItsImagesInNameOrder)
{
	using omnirange::app::CalibrateApp;
	if (!std::filesystem::exists(kRealDir)) GTEST_SKIP() << "no " << kRealDir;
	const std::string dir = kRealDir;
	const char* argv[] = {"omnirange-calibrate", "--checkerboard-dir", dir.c_str()};
	const CalibrateApp::Options o = CalibrateApp::parse(3, argv);
	ASSERT_EQ(o.checkerboards.size(), 10u);  // the ten PGMs; the README is not an image
	EXPECT_EQ(o.checkerboards.front(), dir + "/img_para_001.pgm");
	EXPECT_EQ(o.checkerboards.back(), dir + "/img_para_010.pgm");
	const char* none[] = {"omnirange-calibrate", "--checkerboard-dir", "/nonexistent/boards"};
	EXPECT_THROW(CalibrateApp::parse(3, none), std::runtime_error);
}
