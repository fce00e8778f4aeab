// The apps run in-process as classes: train, scan, accuracy and calibrate
// on the factory sample, each result checked against what the sample holds;
// the command-line parsing fills the same options.
#include <omnirange_apps/AccuracyApp.h>
#include <omnirange_eval/TruthComparison.h>
#include <omnirange_apps/CalibrateApp.h>
#include <omnirange_apps/CommandLine.h>
#include <omnirange_apps/ScanApp.h>
#include <omnirange_apps/TrainApp.h>
#include <omnirange_eval/Experiment.h>
#include <omnirange_eval/ExperimentConfig.h>
#include <omnirange_eval/Suite.h>
#include <omnirange/config/ErrorText.h>
#include <omnirange/config/LayeredIni.h>

#include <omnirange/core/ColourModel.h>
#include <omnirange/core/ScanFusion.h>
#include <omnirange/io/RawlogProcessor.h>
#include <omnirange/io/RawlogReader.h>
#include <omnirange/io/RawlogWriter.h>
#include <omnirange/config/Activity.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CSensoryFrame.h>

#include "../common/FactorySample.h"
#include "ScanAndScore.h"
#include <omnirange_eval/SensoryFrameFormat.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <mrpt/core/exceptions.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

using namespace omnirange;
using namespace omnirange::app;
namespace fs = std::filesystem;

namespace
{
using test::kIni;
using test::kSample;
using test::kSource;
using test::readText;

std::string workDir(const std::string& name) { return test::freshDir("omnirange_apps", name); }

std::string trainHistogram(const std::string& dir)
{
	TrainApp::Options o;
	o.ini = kIni;
	o.output = dir + "/f.hist";
	o.training.input = kSample;
	o.verbosity = mrpt::system::LVL_ERROR;
	const RawlogTrainingResult r = TrainApp(o).run();
	EXPECT_EQ(r.pairs, 20);  // the sample's 20 image/laser pairs
	EXPECT_EQ(r.used, 20);
	EXPECT_GT(r.pixels, 20u * 10000);
	return o.output;
}

/** A scan of `input` into DIR/scanned.rawlog with the factory ini and a histogram trained in `dir`. */
ScanApp::Options scanOf(const std::string& dir, const std::string& input)
{
	ScanApp::Options s;
	s.ini = kIni;
	s.histogram = trainHistogram(dir);
	s.scan.input = input;
	s.scan.output = dir + "/scanned.rawlog";
	s.verbosity = mrpt::system::LVL_ERROR;
	return s;
}

/** Runs omnirange-scan's class; its summary, and every warning it logged. */
std::pair<RawlogScanSummary, std::string> scanWithWarnings(ScanApp::Options s)
{
	s.verbosity = mrpt::system::LVL_WARN;
	ScanApp app(s);
	std::string warned;
	app.logRegisterCallback([&](std::string_view msg, mrpt::system::VerbosityLevel level, std::string_view,
								mrpt::Clock::time_point) {
		if (level == mrpt::system::LVL_WARN) warned += std::string(msg);
	});
	const RawlogScanSummary summary = app.run();
	return {summary, warned};
}
}  // namespace

TEST(AppClasses, TrainScanAndAccuracyOfTheFactorySample)
{
	const std::string dir = workDir("pipeline");
	const ScanApp::Options s = scanOf(dir, kSample);
	const RawlogScanSummary scanned = ScanApp(s).run();
	EXPECT_EQ(scanned.images, 20u);
	EXPECT_EQ(scanned.rays, 20u * 360);
	EXPECT_GT(scanned.hits, scanned.rays / 4);  // much of the factory is open beyond 3.8 m
	// Every ray is a hit or one of the three kinds of miss; open floor beyond
	// 3.8 m is most of the misses, and with the robot's base masked right
	// almost none end at the base, so the scan has nothing to warn of.
	EXPECT_EQ(scanned.hits + scanned.no_hit + scanned.too_close + scanned.outliers + scanned.unsure, scanned.rays);
	EXPECT_GT(scanned.no_hit, scanned.rays / 4);
	EXPECT_LT(scanned.too_close, scanned.rays / 20);
	EXPECT_TRUE(scanWarnings(scanned, s.histogram).empty());
	EXPECT_EQ(scanned.grey_images, 0u);

	AccuracyApp::Options a;
	a.input = s.scan.output;
	a.output = dir + "/acc";
	a.verbosity = mrpt::system::LVL_ERROR;
	const eval::AccuracyResult acc = AccuracyApp(a).run();
	EXPECT_EQ(acc.frames, 20);
	EXPECT_GT(acc.stats.compared, 20u * 40);
	// Within the paper's worst Table II figure (0.1375 m) on these 20 frames.
	EXPECT_LT(acc.stats.meanAbs(), 0.1375);
	for (const std::string f : {"_pairs.csv", "_histogram.png", "_table.md"}) EXPECT_TRUE(fs::exists(a.output + f)) << f;
	// Run again on a log without the truth: an earlier run's truth table is not left beside the new files.
	std::ofstream(a.output + "_truth.md") << eval::kTruthTableBegins << " an earlier run's |\n";
	a.accuracy.truth_label = "NOSUCH";
	EXPECT_EQ(AccuracyApp(a).run().truth.frames, 0);
	EXPECT_FALSE(fs::exists(a.output + "_truth.md"));
}

TEST(AppClasses, ScanWarnsWhenTheRobotsBodyIsInsideTheScanCircle)
{
	// base_radius 10 px where the robot's body covers about 40: every
	// scanline starts on the body, which is not floor. As the paper scans
	// (base_shadow 0) each ray ends there at once, and the scan warns.
	const std::string dir = workDir("small_base");
	std::string ini = test::factoryIniText();
	const std::string key = "\nbase_radius = 40\n";
	ASSERT_NE(ini.find(key), std::string::npos);
	ini.replace(ini.find(key), key.size(), "\nbase_radius = 10\n");
	const std::string histogram = trainHistogram(dir);
	const auto scan = [&](const std::string& name, const std::string& text) {
		ScanApp::Options s;
		s.ini = dir + "/" + name + ".ini";
		std::ofstream(s.ini) << text;
		s.histogram = histogram;
		s.scan.input = kSample;
		s.scan.output = dir + "/" + name + ".rawlog";
		return scanWithWarnings(s);
	};
	std::string paper = ini;
	const std::string shadow = "\nbase_shadow = 1\n";
	ASSERT_NE(paper.find(shadow), std::string::npos);
	paper.replace(paper.find(shadow), shadow.size(), "\nbase_shadow = 0\n");
	const auto [ended, warned] = scan("paper", paper);
	EXPECT_GT(ended.too_close, ended.rays / 2);
	EXPECT_NE(warned.find("too close): check base_radius"), std::string::npos) << warned;
	// With the default base_shadow the body is passed as the robot's own, and the floor
	// past it scanned: too few rays end at the base to warn of (10 %).
	const auto [passed, quiet] = scan("default", ini);
	EXPECT_LT(passed.too_close, passed.rays / 10);
	EXPECT_GT(passed.hits, passed.rays / 4);
	EXPECT_TRUE(quiet.empty()) << quiet;
}

TEST(AppClasses, GreyImagesScannedWithAHistogramOfColoursAreWarnedOf)
{
	// The factory sample as a grey camera would give it (or a log converted to grey), scanned with the colour one's histogram.
	const std::string dir = workDir("grey");
	const std::string rawlog = dir + "/" + fs::path(kSample).filename().string();
	fs::copy_file(kSample, rawlog);
	const std::string images = imagesDirToRead(rawlog);
	fs::copy(imagesDirToRead(kSample), images);
	for (const auto& e : fs::directory_iterator(images))
		if (e.path().extension() == ".jpg")
		{
			cv::Mat grey;
			cv::cvtColor(cv::imread(e.path().string()), grey, cv::COLOR_BGR2GRAY);
			ASSERT_TRUE(cv::imwrite(e.path().string(), grey));
		}
	const ScanApp::Options s = scanOf(dir, rawlog);
	EXPECT_TRUE(ColourModel::load(s.histogram).trainedOnColour());
	const auto [summary, warned] = scanWithWarnings(s);
	EXPECT_EQ(summary.grey_images, 20u);
	EXPECT_NE(warned.find("20 of 20 images are grey (three equal channels)"), std::string::npos) << warned;
}

TEST(AppClasses, ScanWarningsFollowTheSharesOfTheRays)
{
	RawlogScanSummary s;
	s.rays = 1000, s.hits = 600, s.no_hit = 305, s.too_close = 95;  // 9.5 % too close: quiet
	EXPECT_TRUE(scanWarnings(s, "f.hist").empty());
	s.no_hit = 300, s.too_close = 100;  // 10 %
	ASSERT_EQ(scanWarnings(s, "f.hist").size(), 1u);
	s.hits = 19, s.no_hit = 881;  // 1.9 % hit, and still 10 % too close: the histogram is what to doubt
	const auto one = scanWarnings(s, "f.hist");
	ASSERT_EQ(one.size(), 1u);
	EXPECT_NE(one[0].find("'f.hist' trained on this floor"), std::string::npos) << one[0];
	EXPECT_TRUE(scanWarnings(RawlogScanSummary{}, "f.hist").empty());  // nothing scanned: nothing to say
	// Grey images: said with a histogram of colours, with either of the others; not with a grey camera's histogram.
	s.images = 20, s.grey_images = 3;
	EXPECT_EQ(scanWarnings(s, "f.hist", true).size(), 2u);
	EXPECT_NE(scanWarnings(s, "f.hist", true)[0].find("3 of 20 images are grey"), std::string::npos);
	EXPECT_EQ(scanWarnings(s, "f.hist", false).size(), 1u);
}

namespace
{
/** Calibration against the sample's laser, every pair, from an ini holding `keys`. */
CalibrateApp::Options calibrationOf(const std::string& dir, const std::string& keys)
{
	CalibrateApp::Options o;
	o.histogram = trainHistogram(dir);
	o.ini = dir + "/start.ini";
	std::ofstream(o.ini) << "[rangefinder]\n" << keys << "threshold = 0.075\n";
	o.calibration.input = kSample;
	o.calibration.every = 1;
	o.verbosity = mrpt::system::LVL_ERROR;
	return o;
}
}  // namespace

TEST(AppClasses, AScanOfImagesStoredInsideTheRawlogLinksNoImagesFolder)
{
	// The sample's first two images stored inside a rawlog of their own, as some grabbers write them.
	const std::string dir = workDir("embedded");
	const std::string in = dir + "/emb.rawlog";
	{
		RawlogWriter w(in, "omnirange-test");
		for (int k = 0; k < 2; ++k)
		{
			mrpt::obs::CObservationImage image;
			image.sensorLabel = "OMNICAM";
			image.timestamp = mrpt::Clock::fromDouble(100.0 + k);
			char name[128];
			std::snprintf(name, sizeof name, "/rawlogs/factory-sample_Images/factory-sample_OMNICAM_%06d.jpg", k);
			image.image = mrpt::img::CImage(cv::imread(kSource + name), mrpt::img::DEEP_COPY);
			w.write(image);
		}
		w.commit();
	}
	ASSERT_FALSE(fs::exists(dir + "/emb_Images"));
	EXPECT_EQ(ScanApp(scanOf(dir, in)).run().images, 2u);
	EXPECT_FALSE(fs::exists(fs::symlink_status(dir + "/scanned_Images"))) << "a link to a folder that does not exist";
}

TEST(AppClasses, CalibrateRecoversTheMirrorRadius)
{
	// Start from a wrong R: the fit must come back near the simulator's 192 px.
	const CalibrateApp::Options o = calibrationOf(workDir("calibrate"), "R = 205\n");
	const MirrorCalibration c = CalibrateApp(o).run();
	EXPECT_NEAR(c.R, 192.0, 5.0);
	EXPECT_LT(c.rms_R, c.rms_given);  // the fit explains the laser better than R = 205
	EXPECT_GE(c.suggested_boundary_offset, -1.0);  // what the scanner accepts
	EXPECT_LE(c.suggested_boundary_offset, 1.0);
	EXPECT_GE(c.kept, c.pairs / 2);
}

TEST(AppClasses, CalibrateSavesTheCheckerboardsMeiModelIntoTheIni)
{
	// Four real images through a paraboloid (../shared/data/real, made by
	// others); the ini's other keys stay as they were.
	const std::string real = kSource + "/../shared/data/real/mei-paraboloid";
	if (!fs::exists(real)) GTEST_SKIP() << "no " << real;
	const std::string dir = workDir("checkerboard_save");
	CalibrateApp::Options o;
	for (const char* n : {"001", "003", "004", "006"}) o.checkerboards.push_back(real + "/img_para_" + n + ".pgm");
	o.save_to = dir + "/my.ini";
	o.intrinsics_output = dir + "/intrinsics.yaml";  // with the keys, as one set
	std::ofstream(o.save_to) << "[rangefinder]\n; [-] kept\nthreshold = 0.075\nR = 192\n";
	o.verbosity = mrpt::system::LVL_ERROR;
	o.accept = true;  // two of the four boards are used: too few to measure the centre's spread
	testing::internal::CaptureStderr();
	const CheckerboardCalibration c = CalibrateApp(o).runIntrinsics();
	EXPECT_NE(testing::internal::GetCapturedStderr().find("only 2 boards were used"), std::string::npos);
	mrpt::system::COutputLogger quiet("test");
	quiet.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	const RangefinderParams saved = loadRangefinderIni(o.save_to, "rangefinder", quiet);
	EXPECT_EQ(saved.camera.mirror_model, MirrorModel::Mei);
	EXPECT_NEAR(saved.camera.xi, c.xi, 1e-6);
	EXPECT_NEAR(saved.camera.gamma, c.K(0, 0), 1e-6);
	EXPECT_NEAR(saved.camera.aspect, c.K(1, 1) / c.K(0, 0), 1e-9);
	EXPECT_NEAR(saved.camera.skew, c.K(0, 1), 1e-6);
	EXPECT_NEAR(saved.camera.k1, c.D[0], 1e-9);
	EXPECT_NEAR(saved.camera.p1, c.D[2], 1e-9);
	EXPECT_NEAR(saved.camera.p2, c.D[3], 1e-9);
	EXPECT_NEAR(saved.camera.cx, 643.7, 3.0);  // the data's reference principal point
	EXPECT_NEAR(saved.camera.cy, 521.3, 5.0);
	EXPECT_EQ(saved.camera.image_width, 1280);
	EXPECT_EQ(saved.camera.image_height, 1024);
	EXPECT_DOUBLE_EQ(saved.threshold, 0.075);
	EXPECT_NE(readText(o.save_to).find("; [-] kept"), std::string::npos);
	EXPECT_EQ(readText(o.intrinsics_output).rfind("%YAML:1.0", 0), 0u);
	EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);  // no journal or old file left
}

namespace
{
/** A calibration from a calib_results.txt in `dir` for the stock paraboloid
 * (R 192: z = -96 + rho^2 / 384), centre row 380, column 515, with the
 * affine terms `affine` ("c d e"). */
CalibrateApp::Options ocamCalibrationIn(const std::string& dir, const std::string& affine)
{
	CalibrateApp::Options o;
	o.ocamcalib = dir + "/calib_results.txt";
	std::ofstream(o.ocamcalib) << "#direct\n\n3 -96 0 0.0026041666666666665\n\n#inverse\n\n2 1 1\n\n#center\n\n"
								  "380 515\n\n#affine\n\n" << affine << "\n\n#size\n\n768 1024\n";
	o.verbosity = mrpt::system::LVL_ERROR;
	return o;
}
}  // namespace

TEST(AppClasses, CalibrateSavesAnOCamCalibModelIntoTheIni)
{
	// The saved ini reads floor distances as R 192 does.
	const std::string dir = workDir("ocamcalib_save");
	CalibrateApp::Options o = ocamCalibrationIn(dir, "1.001 0.0005 -0.0002");
	o.save_to = dir + "/my.ini";
	std::ofstream(o.save_to) << "[rangefinder]\n; [-] kept\nthreshold = 0.075\n";
	testing::internal::CaptureStdout();
	CalibrateApp(o).runOCamCalib();
	EXPECT_EQ(testing::internal::GetCapturedStdout(), "");  // -q: errors only, no summary
	mrpt::system::COutputLogger quiet("test");
	quiet.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	const RangefinderParams saved = loadRangefinderIni(o.save_to, "rangefinder", quiet);
	EXPECT_EQ(saved.camera.mirror_model, MirrorModel::OCamCalib);
	ASSERT_EQ(saved.camera.ocam_poly.size(), 3u);
	EXPECT_EQ(saved.camera.ocam_affine, (std::vector<double>{1.001, 0.0005, -0.0002}));
	EXPECT_DOUBLE_EQ(saved.camera.cx, 515);
	EXPECT_DOUBLE_EQ(saved.camera.cy, 380);
	EXPECT_DOUBLE_EQ(saved.threshold, 0.075);
	const OmniCameraModel model(saved.camera);
	CameraParams para;
	EXPECT_NEAR(model.distanceFromRho(150), OmniCameraModel(para).distanceFromRho(150), 1e-9);
}

TEST(AppClasses, CalibrateDoesNotSaveIntoABaseIniItsIniWasReplacedByALinkToMeanwhile)
{
	const std::string dir = workDir("ocamcalib_swapped");
	CalibrateApp::Options o = ocamCalibrationIn(dir, "1 0 0");
	std::ofstream(dir + "/base.ini") << "[rangefinder]\nthreshold = 0.075\n";
	o.ini = o.save_to = dir + "/c.ini";
	std::ofstream(o.ini) << "base = base.ini\n[rangefinder]\nK = 4\n";
	CalibrateApp app(o);
	// While it runs, the ini becomes a link to the base under it (which other inis build on too).
	fs::rename(o.ini, dir + "/c.ini.mine");
	fs::create_symlink("base.ini", o.ini);
	EXPECT_THROW(app.runOCamCalib(), std::runtime_error);
	EXPECT_EQ(readText(dir + "/base.ini"), "[rangefinder]\nthreshold = 0.075\n");
	// Nor into another camera's ini (no input of this run) it was re-pointed to.
	fs::remove(o.ini);
	fs::rename(dir + "/c.ini.mine", o.ini);
	CalibrateApp again(o);
	std::ofstream(dir + "/other.ini") << "[rangefinder]\nK = 2\n";
	fs::rename(o.ini, dir + "/c.ini.mine");
	fs::create_symlink("other.ini", o.ini);
	EXPECT_THROW(again.runOCamCalib(), std::runtime_error);
	EXPECT_EQ(readText(dir + "/other.ini"), "[rangefinder]\nK = 2\n");
}

TEST(AppClasses, CalibrateFindsTheCamerasOrientation)
{
	// The ini says 150 degrees, not mirrored; the simulator's camera is at
	// 180 degrees, mirrored (docs/worlds.md).
	CalibrateApp::Options o = calibrationOf(workDir("orientation"), "forward_azimuth_deg = 150\nmirrored = false\n");
	CalibrateApp app(o);
	app.run();
	const OrientationFit& f = app.orientation();
	EXPECT_TRUE(f.mirrored);
	EXPECT_NEAR(std::abs(f.forward_azimuth), M_PI, 1.5 * M_PI / 180);  // 180 deg within 1.5
	EXPECT_LT(f.error, f.error_as_given);
	EXPECT_TRUE(pinnedDown(f)) << f.agreeing << " of " << f.frames;
	EXPECT_EQ(f.frames, 20);

	// Saved into the ini: the orientation only (R was fitted with the wrong
	// one); a second run with it saves R too, near the simulator's 192 px.
	o.save_to = o.ini;
	CalibrateApp(o).run();
	mrpt::system::COutputLogger quiet("test");
	quiet.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	RangefinderParams saved = loadRangefinderIni(o.ini, "rangefinder", quiet);
	EXPECT_NEAR(saved.camera.forward_azimuth, M_PI, 1e-9);
	EXPECT_TRUE(saved.camera.mirrored);
	std::ifstream first(o.ini);
	EXPECT_EQ(std::string((std::istreambuf_iterator<char>(first)), {}).find("\nR = "), std::string::npos);
	CalibrateApp(o).run();
	saved = loadRangefinderIni(o.ini, "rangefinder", quiet);
	EXPECT_NEAR(saved.camera.R, 192.0, 5.0);
}

TEST(AppClasses, CalibrateFindsTheOrientationThroughAWrongScale)
{
	// R far off alone: the orientation is searched at the fitted R too and found.
	CalibrateApp wrong_scale(calibrationOf(workDir("orientation_scale"), "R = 150\n"));
	wrong_scale.run();
	EXPECT_TRUE(wrong_scale.orientation().mirrored);
	EXPECT_NEAR(std::abs(wrong_scale.orientation().forward_azimuth), M_PI, 1.5 * M_PI / 180);
	EXPECT_TRUE(pinnedDown(wrong_scale.orientation()));
	// R and the reversal both wrong: R fitted with the wrong reversal is wrong too,
	// so the turns are searched over scales around the ini's as well; only the
	// orientation is saved, R having been fitted with the wrong one.
	CalibrateApp::Options both = calibrationOf(workDir("orientation_both"), "R = 260\nmirrored = false\n");
	both.save_to = both.ini;
	CalibrateApp both_wrong(both);
	both_wrong.run();
	EXPECT_TRUE(both_wrong.orientation().mirrored);
	EXPECT_NEAR(std::abs(both_wrong.orientation().forward_azimuth), M_PI, 3 * M_PI / 180);
	mrpt::system::COutputLogger quiet("test");
	quiet.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	const RangefinderParams saved = loadRangefinderIni(both.ini, "rangefinder", quiet);
	EXPECT_TRUE(saved.camera.mirrored);
	EXPECT_EQ(saved.camera.R, 260.0);
}

TEST(AppClasses, CommandLinesFillTheOptions)
{
	const char* argv[] = {"omnirange-train", "-i", "in.rawlog", "-o", "out.hist", "-c", "x.ini", "--every", "3", "-q"};
	const TrainApp::Options o = TrainApp::parse(10, argv);
	EXPECT_EQ(o.training.input, "in.rawlog");
	EXPECT_EQ(o.output, "out.hist");
	EXPECT_EQ(o.training.every, 3);
	EXPECT_EQ(o.training.laser_label, "LASER");  // the default, from the options struct
	EXPECT_EQ(o.verbosity, mrpt::system::LVL_ERROR);
	EXPECT_TRUE(o.learning.chroma_on_tie);  // the default
	const char* learn[] = {"omnirange-train", "-i", "in.rawlog", "-o", "out.hist", "-c", "x.ini", "--learn", "l.ini",
						   "--learn-candidates", "c.csv"};
	const TrainApp::Options l = TrainApp::parse(11, learn);
	EXPECT_EQ(l.learn_candidates, "c.csv");
	// The training's and learning's knobs are the ini's, not the command line's.
	const char* knob[] = {"omnirange-train", "-i", "in.rawlog", "-o", "out.hist", "-c", "x.ini", "--bins", "8"};
	try
	{
		TrainApp::parse(9, knob);
		FAIL() << "--bins is an ini key now";
	}
	catch (const ExitRequest& e)
	{
		EXPECT_EQ(e.code, 2);
	}
	const char* candidates_alone[] = {"omnirange-train", "-i", "in.rawlog", "-o", "out.hist", "-c", "x.ini",
									  "--learn-candidates", "c.csv"};
	EXPECT_THROW(TrainApp::parse(9, candidates_alone), std::invalid_argument);

	const char* bad[] = {"omnirange-scan", "--bogus"};
	try
	{
		ScanApp::parse(2, bad);
		FAIL() << "a bad command line must end the program";
	}
	catch (const ExitRequest& e)
	{
		EXPECT_EQ(e.code, 2);
	}
}

TEST(AppClasses, TrainingReadsItsKeysFromTheIni)
{
	const std::string dir = workDir("training_section");
	std::ofstream(dir + "/t.ini") << "base = " << kIni << "\n[training]\ncolour_space = HSV\nbins = 8\nobstacle_band = 0\n";
	TrainApp::Options o;
	o.ini = dir + "/t.ini";
	o.output = dir + "/t.hist";
	o.training.input = kSample;
	o.verbosity = mrpt::system::LVL_ERROR;
	TrainApp(o).run();
	const ColourModel model = ColourModel::load(o.output);
	EXPECT_EQ(model.floor.space(), ColourSpace::HSV);
	EXPECT_EQ(model.floor.binsPerChannel(), 8);
	EXPECT_EQ(model.obstacles.total(), 0u);  // obstacle_band 0: the floor only
	// A bad key names its file; nothing is written.
	std::ofstream(dir + "/bad.ini") << "base = " << kIni << "\n[learning]\nhold_out_every = 1\n";
	o.ini = dir + "/bad.ini";
	o.output = dir + "/bad.hist";
	o.learn_ini = dir + "/bad-learned.ini";
	EXPECT_EQ(test::errorOf([&] { TrainApp(o).run(); }).rfind(dir + "/bad.ini: [learning] hold_out_every = '1': must be within [2, 1000]", 0), 0u)
		<< test::errorOf([&] { TrainApp(o).run(); });
	EXPECT_FALSE(fs::exists(o.output));
}

TEST(AppClasses, ATrainingThatFailsLeavesTheOldHistogramAndItsFiguresAsTheyWere)
{
	// The figures are of an early pair; an image cut later ends the run: the figures are not replaced without the histogram.
	const std::string dir = workDir("figures_all_or_none");
	fs::copy_file(kSample, dir + "/log.rawlog");
	fs::copy(test::kSource + "/rawlogs/factory-sample_Images", dir + "/log_Images");
	TrainApp::Options o;
	o.ini = kIni;
	o.output = dir + "/f.hist";
	o.training.input = dir + "/log.rawlog";
	o.training.figures_prefix = dir + "/fig";
	o.verbosity = mrpt::system::LVL_ERROR;
	TrainApp(o).run();
	for (const std::string f : {"_birdseye.png", "_laser.png", "_fused.png"}) ASSERT_TRUE(fs::exists(o.training.figures_prefix + f)) << f;
	const std::string old_fig = test::readText(o.training.figures_prefix + "_fused.png"), old_hist = test::readText(o.output);
	const std::string cut = dir + "/log_Images/factory-sample_OMNICAM_000010.jpg";
	const std::string bytes = test::readText(cut);
	std::ofstream(cut, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);
	o.training.figures_frame = 1;  // other figures than the ones there
	EXPECT_THROW(TrainApp(o).run(), std::runtime_error);
	EXPECT_EQ(test::readText(o.training.figures_prefix + "_fused.png"), old_fig);
	EXPECT_EQ(test::readText(o.output), old_hist);
}

TEST(AppClasses, LearnedParametersLoadAndScoreOnFramesTheyNeverSaw)
{
	const std::string dir = workDir("learn");
	TrainApp::Options t;
	t.ini = kIni;
	t.output = dir + "/learned.hist";
	t.learn_ini = dir + "/learned.ini";
	t.learn_candidates = dir + "/candidates.csv";
	t.training.input = kSample;
	t.training.until = 12;  // learn on the first 12 pairs (9 to train, 3 held aside)
	t.verbosity = mrpt::system::LVL_ERROR;
	TrainApp(t).run();
	{
		// Every candidate a row after the header, with its three frames' errors.
		std::ifstream csv(t.learn_candidates);
		std::string line;
		int rows = 0;
		std::getline(csv, line);
		EXPECT_EQ(line.rfind("colour_space,", 0), 0u) << line;
		while (std::getline(csv, line))
		{
			++rows;
			const std::string frames = line.substr(line.rfind(',') + 1);
			ASSERT_EQ(std::count(frames.begin(), frames.end(), ' '), 2) << line;
		}
		EXPECT_EQ(rows, 1408);
	}
	// The written ini is a [rangefinder] section a user (and omnirange-scan) can load.
	mrpt::system::COutputLogger quiet("test");
	quiet.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	const RangefinderParams learned = loadRangefinderIni(t.learn_ini, "rangefinder", quiet);
	// A value of the grid (LearningOptions::thresholds).
	const std::vector<double> grid = LearningOptions{}.thresholds;
	EXPECT_NE(std::find(grid.begin(), grid.end(), learned.threshold), grid.end()) << learned.threshold;
	// The histogram written is the winner's: its bins are the ones the ini's
	// comment names (13 or 26: the training's and twice as many).
	const ColourModel model = ColourModel::load(t.output);
	const int bins = model.floor.binsPerChannel();
	EXPECT_TRUE(bins == 13 || bins == 26) << bins;
	std::ifstream comment(t.learn_ini);
	std::string head((std::istreambuf_iterator<char>(comment)), {});
	EXPECT_NE(head.find(", " + std::to_string(bins) + " bins,"), std::string::npos) << head.substr(0, 400);
	// The grid of 1024, then its 32 best with each of 4 brightness-step thresholds and 3 signs.
	EXPECT_NE(head.find("1408 candidates"), std::string::npos) << head.substr(0, 400);
	// Scored only on the 8 frames learning never saw.
	const eval::AccuracyResult acc = test::scanAndScore(t.learn_ini, t.output, kSample, dir, 12);
	EXPECT_EQ(acc.frames, 8);
	EXPECT_LT(acc.stats.meanAbs(), 0.1375);  // within the paper's worst Table II figure
}

TEST(AppClasses, AnExperimentReadsTrainingAndLearningAsOmnirangeTrainDoes)
{
	const std::string ini = kSource + "/ini/tmp-training.ini", factory = readText(kSource + "/ini/factory.ini");
	const auto load = [&](const std::string& extra) {
		std::ofstream(ini) << factory << extra;
		const auto cleanup = [&] { fs::remove(ini); };
		try
		{
			auto c = eval::ExperimentConfig::load(ini);
			cleanup();
			return c;
		}
		catch (...)
		{
			cleanup();
			throw;
		}
	};
	const auto c = load("\n[training]\nbins = 8\ncolour_space = CHROMA\n[learning]\nhold_out_every = 3\n");
	EXPECT_EQ(c.training.bins, 8);
	EXPECT_EQ(c.training.space, ColourSpace::Chroma);
	EXPECT_EQ(c.learning.hold_out_every, 3);
	EXPECT_NE(test::errorOf([&] { load("\n[training]\nbins = 100\n"); }).find("[training] bins must be within [1, 64] in an experiment"),
			  std::string::npos);
	EXPECT_NE(test::errorOf([&] { load("bins = 8\n"); }).find("set bins in [training]"), std::string::npos)
		<< test::errorOf([&] { load("bins = 8\n"); });
}

TEST(AppClasses, AnMrptProgramsIniEditedAfterItWasCheckedIsNotRun)
{
	// The factory's experiment with its omnicam icp-slam ini in a copy of the user's, edited once checked.
	const std::string dir = workDir("mrpt_ini_edited"), icp = dir + "/icp.ini", ini = kSource + "/ini/tmp-edited.ini";
	fs::copy_file(kSource + "/ini/icp-slam-omniscan.ini", icp);
	std::ofstream(ini) << readText(kSource + "/ini/factory.ini") << "icp_omni_ini = " << icp << "\n";
	const auto config = eval::ExperimentConfig::load(ini);
	fs::remove(ini);
	std::ofstream(icp, std::ios::app) << "\n; an edit while the experiment starts\n";
	try
	{
		eval::Experiment run(config);
		ADD_FAILURE() << "an ini other than the one checked would be run";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("changed while the experiment checked it"), std::string::npos) << e.what();
	}
	EXPECT_EQ(config.mrpt_ini_text.at(icp), readText(kSource + "/ini/icp-slam-omniscan.ini"));  // what it would give
}

TEST(AppClasses, EveryListedExperimentLoads)
{
	// Each ini of the suite names its world, route, robot and MRPT
	// configurations (through its base); load() checks them all, and that the
	// route keeps clear of the world's solids.
	const auto suite = eval::loadSuite(kSource + "/ini/suite.txt");
	ASSERT_GE(suite.size(), 2u);
	EXPECT_EQ(suite[0].name, "maze");
	EXPECT_EQ(suite[1].name, "factory");
	for (const auto& e : suite)
	{
		const auto c = eval::ExperimentConfig::load(kSource + "/ini/" + e.name + ".ini");
		EXPECT_EQ(c.name, e.name);
		EXPECT_TRUE(c.learn) << e.name;  // the stock experiments learn their parameters
		EXPECT_DOUBLE_EQ(c.train_fraction, 0.2) << e.name;
		EXPECT_EQ(c.train_every, 1) << e.name;
		EXPECT_EQ(fs::path(c.output).filename(), e.name);
	}
	// The base sets no [experiment] key to the code's default (one fact, one place).
	const mrpt::config::CConfigFile base(kSource + "/ini/experiment-base.ini");
	std::vector<std::string> keys;
	base.getAllKeys("experiment", keys);
	const eval::ExperimentConfig defaults;
	for (const auto& f : eval::ExperimentConfig::table().fields())
	{
		if (std::find(keys.begin(), keys.end(), f.info.key) == keys.end()) continue;
		EXPECT_NE(base.read_string("experiment", f.info.key, ""), f.print(defaults)) << f.info.key;
	}
	// Every experiment ini in ini/ is listed: nothing is run by one script and forgotten by another.
	for (const auto& f : fs::directory_iterator(kSource + "/ini"))
		if (omnirange::iniBaseOf(f.path().string()) != "")
		{
			const std::string name = f.path().stem().string();
			EXPECT_TRUE(std::any_of(suite.begin(), suite.end(), [&](const auto& e) { return e.name == name; }))
				<< name << " is not in ini/suite.txt";
		}
}

TEST(AppClasses, AnOutputOntoAnInputIsRefusedAndTheInputKept)
{
	const std::string dir = workDir("overwrite");
	const std::string rawlog = dir + "/in.rawlog", ini = dir + "/in.ini";
	fs::copy_file(kSample, rawlog);
	fs::create_directory_symlink(kSource + "/rawlogs/factory-sample_Images", dir + "/in_Images");
	const std::string ini_text = test::factoryIniText();
	std::ofstream(ini) << ini_text;
	fs::create_symlink(ini, dir + "/link.ini");
	const auto size = fs::file_size(rawlog);

	TrainApp::Options t;
	t.ini = ini;
	t.training.input = rawlog;
	t.verbosity = mrpt::system::LVL_ERROR;
	for (const std::string& out : std::vector<std::string>{rawlog, ini, dir + "/./in.rawlog", dir + "/link.ini"})
	{
		t.output = out;
		EXPECT_THROW(TrainApp(t).run(), std::runtime_error) << out;
	}
	EXPECT_EQ(fs::file_size(rawlog), size);
	EXPECT_EQ(readText(ini), ini_text);

	t.output = dir + "/f.hist";
	TrainApp(t).run();
	ScanApp::Options s;
	s.ini = ini;
	s.histogram = t.output;
	s.scan.input = rawlog;
	s.scan.output = t.output;  // onto the histogram
	s.verbosity = mrpt::system::LVL_ERROR;
	EXPECT_THROW(ScanApp(s).run(), std::runtime_error);
	EXPECT_NO_THROW(ColourModel::load(t.output));
}

TEST(AppClasses, ACutImageIsAnErrorNamingTheFile)
{
	const std::string dir = workDir("cut_image");
	fs::copy_file(kSample, dir + "/s.rawlog");
	fs::create_directory(dir + "/s_Images");
	for (const auto& e : fs::directory_iterator(kSource + "/rawlogs/factory-sample_Images"))
		fs::copy_file(e.path(), dir + "/s_Images/" + e.path().filename().string());
	// Cut the fifth image in half, as a full disk or an interrupted copy would.
	std::vector<fs::path> images;
	for (const auto& e : fs::directory_iterator(dir + "/s_Images")) images.push_back(e.path());
	std::sort(images.begin(), images.end());
	const fs::path cut = images.at(4);
	fs::resize_file(cut, fs::file_size(cut) / 2);
	ScanApp::Options s;
	s.ini = kIni;
	s.histogram = trainHistogram(dir);
	s.scan.input = dir + "/s.rawlog";
	s.scan.output = dir + "/out.rawlog";
	s.verbosity = mrpt::system::LVL_ERROR;
	try
	{
		ScanApp(s).run();
		FAIL() << "a cut image must not be scanned";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find(cut.filename().string()), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
	}
	EXPECT_FALSE(fs::exists(s.scan.output));

	// Asked to, the scan skips it, names it and scans the other 19.
	s.scan.skip_bad_images = true;
	const RawlogScanSummary skipped = ScanApp(s).run();
	EXPECT_EQ(skipped.images, 19u);
	EXPECT_EQ(skipped.skipped, 1u);
	ASSERT_EQ(skipped.skipped_reasons.size(), 1u);
	EXPECT_NE(skipped.skipped_reasons[0].find(cut.filename().string()), std::string::npos);
	EXPECT_EQ(skipped.rays, 19u * 360);
}

TEST(AppClasses, ASensoryFrameRawlogIsTrainedScannedAndScoredInItsOwnFormat)
{
	const std::string dir = workDir("sensory_frames");
	ASSERT_EQ(eval::writeSensoryFrameFormat(kSample, dir + "/sf.rawlog"), 20);

	TrainApp::Options t;
	t.ini = kIni;
	t.output = dir + "/sf.hist";
	t.training.input = dir + "/sf.rawlog";
	t.verbosity = mrpt::system::LVL_ERROR;
	EXPECT_EQ(TrainApp(t).run().pairs, 20);

	// The same histogram scans both formats; the scores must be the same.
	const auto scanAndScore = [&](const std::string& in, const std::string& name) {
		ScanApp::Options s;
		s.ini = kIni;
		s.histogram = t.output;
		s.scan.input = in;
		s.scan.output = dir + "/" + name + ".rawlog";
		s.verbosity = mrpt::system::LVL_ERROR;
		EXPECT_EQ(ScanApp(s).run().images, 20u);
		AccuracyApp::Options a;
		a.input = s.scan.output;
		a.output = dir + "/" + name + "_acc";
		a.verbosity = mrpt::system::LVL_ERROR;
		return AccuracyApp(a).run();
	};
	const auto sf = scanAndScore(dir + "/sf.rawlog", "sf_scanned");
	const auto obs = scanAndScore(kSample, "obs_scanned");
	EXPECT_EQ(sf.frames, 20);
	EXPECT_EQ(sf.stats.compared, obs.stats.compared);
	EXPECT_DOUBLE_EQ(sf.stats.meanAbs(), obs.stats.meanAbs());

	// The output keeps the format: each scan inside its image's frame.
	RawlogReader reader(dir + "/sf_scanned.rawlog");
	int frames_with_both = 0, bare = 0;
	while (const auto obj = reader.next())
	{
		if (std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) ++bare;
		const auto frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj);
		if (!frame) continue;
		const auto image = frame->getObservationBySensorLabel("OMNICAM");
		const auto scan = frame->getObservationBySensorLabel("OMNISCAN");
		if (image && scan && image->timestamp == scan->timestamp) ++frames_with_both;
	}
	EXPECT_EQ(frames_with_both, 20);
	EXPECT_EQ(bare, 0);
}

TEST(AppClasses, FloorAdaptationScansTheSameWithAnyNumberOfThreads)
{
	const std::string dir = workDir("adaptation_threads");
	{
		std::istringstream in(test::factoryIniText());
		std::ofstream out(dir + "/adapt.ini");
		for (std::string line; std::getline(in, line);)
			out << (line == "floor_adaptation = false" ? "floor_adaptation = true"
					: line == "adaptation_memory = 50" ? "adaptation_memory = 3"
													   : line)
				<< "\n";
	}
	ASSERT_NE(readText(dir + "/adapt.ini").find("floor_adaptation = true"), std::string::npos);
	ASSERT_NE(readText(dir + "/adapt.ini").find("adaptation_memory = 3"), std::string::npos);
	// A floor of pure magenta: only what adaptation learns is free.
	ColourHistogram magenta;
	const std::uint8_t bgr[3] = {255, 0, 255};
	for (int i = 0; i < 100; ++i) magenta.addPixel(bgr);
	const std::string hist = dir + "/magenta.hist";
	ColourModel(magenta).save(hist);
	const auto ranges = [&](int threads) {
		ScanApp::Options s;
		s.ini = dir + "/adapt.ini";
		s.histogram = hist;
		s.scan.input = kSample;
		s.scan.output = dir + "/j" + std::to_string(threads) + ".rawlog";
		s.scan.threads = threads;
		s.verbosity = mrpt::system::LVL_ERROR;
		EXPECT_EQ(ScanApp(s).run().images, 20u);
		std::vector<float> all;
		RawlogReader reader(s.scan.output);
		while (const auto obj = reader.next())
			if (const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obj))
				if (scan->sensorLabel == "OMNISCAN")
					for (std::size_t i = 0; i < scan->getScanSize(); ++i)
						all.push_back(scan->getScanRangeValidity(i) ? scan->getScanRange(i) : -1.0f);
		return all;
	};
	const auto one = ranges(1), three = ranges(3);
	ASSERT_EQ(one.size(), 20u * 360);
	EXPECT_EQ(one, three);
	// The images are scanned in batches of 8 (one thread) or 24 (three): the
	// same result says each image saw what was learned up to it, no more.
	EXPECT_GT(std::count_if(one.begin(), one.end(), [](float r) { return r > 0; }), 20 * 360 / 4);
}

TEST(AppClasses, AHistogramOfAnotherFloorIsWarnedAbout)
{
	const std::string dir = workDir("other_floor");
	// A floor of pure magenta: nothing in the factory looks like it.
	ColourHistogram magenta;
	const std::uint8_t bgr[3] = {255, 0, 255};
	for (int i = 0; i < 100; ++i) magenta.addPixel(bgr);
	ColourModel(magenta).save(dir + "/magenta.hist");
	ScanApp::Options s;
	s.ini = kIni;
	s.histogram = dir + "/magenta.hist";
	s.scan.input = kSample;
	s.scan.output = dir + "/out.rawlog";
	const auto [r, warned] = scanWithWarnings(s);
	EXPECT_LT(r.hits, r.rays / 50);
	EXPECT_NE(warned.find("magenta.hist"), std::string::npos) << warned;
}

TEST(AppClasses, OutOfMemoryIsOneLineNamingWhatWasBeingRead)
{
	testing::internal::CaptureStderr();
	const int code = runApp("omnirange-test", [] {
		activity::set("reading rawlog 'big.rawlog'");
		throw std::bad_alloc();
	});
	activity::set("");
	const std::string err = testing::internal::GetCapturedStderr();
	EXPECT_EQ(code, 1);
	EXPECT_EQ(err, "omnirange-test: error: out of memory while reading rawlog 'big.rawlog'\n");
}

TEST(AppClasses, OpenCVsAndMRPTsErrorsAreOneLineWithoutPathsOrCallStacks)
{
	// OpenCV's own text: version, source path and line, code, message, function.
	try
	{
		cv::Mat a(2, 2, CV_8U), b(3, 3, CV_8U);
		cv::Mat c = a + b;
		ADD_FAILURE() << "OpenCV added matrices of two sizes";
	}
	catch (const cv::Exception& e)
	{
		const std::string text = errorText(e);
		EXPECT_EQ(text.rfind("OpenCV: ", 0), 0u) << text;
		EXPECT_NE(text.find("(in arithm_op)"), std::string::npos) << text;
		EXPECT_EQ(text.find(".cpp"), std::string::npos) << text;
		EXPECT_EQ(text.find('\n'), std::string::npos) << text;
	}
	// MRPT's: a header, the message, its location and a call stack of many lines.
	try
	{
		THROW_EXCEPTION("the sensor 'X' is unknown");
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("Call stack"), std::string::npos);  // what MRPT gives
		EXPECT_EQ(errorText(e), "MRPT: the sensor 'X' is unknown");
		// Made one line where it is caught and said more of (an experiment's stage): what is said after it is kept.
		const std::runtime_error said("stage 'icp-slam' failed: " + errorInOneLine(e.what()) + " (the disk is full)");
		EXPECT_EQ(errorText(said), "stage 'icp-slam' failed: MRPT: the sensor 'X' is unknown (the disk is full)");
	}
	// An assertion's message goes on over lines of its own (the values compared): all of it, no stack.
	try
	{
		const int decimation = 0;
		ASSERT_GT_(decimation, 0);
	}
	catch (const std::exception& e)
	{
		const std::string text = errorText(e);
		EXPECT_NE(text.find("ASSERT_GT_(decimation,0) failed with decimation=0"), std::string::npos) << text;
		EXPECT_EQ(text.find("Call stack"), std::string::npos) << text;
	}
	EXPECT_EQ(errorText(std::runtime_error("two\nlines")), "two lines");
	// A class name read from a damaged rawlog: its byte that is no text shows as '?', a name in UTF-8 as itself.
	EXPECT_EQ(errorText(std::runtime_error("class 'CObservation2DRa\xffgeScan' in 'r\xc3\xa9sum\xc3\xa9.rawlog'")),
			  "class 'CObservation2DRa?geScan' in 'r\xc3\xa9sum\xc3\xa9.rawlog'");
}

TEST(AppClasses, ARimCentreIsSavedOnlyForACameraOfTheImagesSize)
{
	const std::string dir = workDir("rim_size");
	// A mirror disc whose brightness falls towards its centre, as a scene in a mirror does.
	cv::Mat img(480, 640, CV_8UC1, cv::Scalar(10)), noise(480, 640, CV_8UC1);
	for (int r = 180; r > 0; r -= 4) cv::circle(img, {330, 236}, r, cv::Scalar(60 + 170 * r / 180), -1);
	cv::randu(noise, 0, 20);
	img += noise;
	cv::imwrite(dir + "/rim.png", img);
	CalibrateApp::Options o;
	o.rim_images = {dir + "/rim.png"};
	o.save_to = dir + "/my.ini";
	const std::string other_camera = "[rangefinder]\nimage_width = 1024\nimage_height = 768\n";
	std::ofstream(o.save_to) << other_camera;
	try
	{
		CalibrateApp(o).runRim();
		ADD_FAILURE() << "a centre was saved for another camera";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("the images are 640x480 but the camera of " + o.save_to + " is 1024x768"), std::string::npos)
			<< e.what();
	}
	EXPECT_EQ(readText(o.save_to), other_camera);
	// Of the images' size (or with --accept): the size is saved with the centre.
	std::ofstream(o.save_to) << "[rangefinder]\nimage_width = 640\nimage_height = 480\n";
	const MirrorRim rim = CalibrateApp(o).runRim();
	EXPECT_NEAR(rim.cx, 330, 2);
	EXPECT_NEAR(rim.cy, 236, 2);
	const RangefinderParams saved = RangefinderParams::loadFromFile(o.save_to, "rangefinder");
	EXPECT_EQ(saved.camera.image_width, 640);
	EXPECT_NEAR(saved.camera.cx, rim.cx, 0.06);
}

TEST(AppClasses, ARimDiscPastTheImageOrFarFromRoundIsRefusedUnlessAccepted)
{
	// A bright ellipse on a dark image, its right side cut by the image's edge.
	const std::string dir = workDir("rim_doubt");
	cv::Mat img(480, 640, CV_8UC1, cv::Scalar(10)), noise(480, 640, CV_8UC1);
	cv::ellipse(img, {560, 240}, {200, 150}, 0, 0, 360, cv::Scalar(200), -1);
	cv::randu(noise, 0, 40);
	img += noise;  // a scene, not two flat grey levels
	cv::imwrite(dir + "/rim.png", img);
	CalibrateApp::Options o;
	o.rim_images = {dir + "/rim.png"};
	o.save_to = dir + "/my.ini";
	std::ofstream(o.save_to) << "[rangefinder]\n";
	std::string why;  // one line naming both doubts
	try
	{
		CalibrateApp(o).runRim();
	}
	catch (const std::runtime_error& e)
	{
		why = e.what();
	}
	EXPECT_NE(why.find("past the image"), std::string::npos) << why;
	EXPECT_NE(why.find("not round"), std::string::npos) << why;
	EXPECT_EQ(why.find('\n'), std::string::npos) << why;
	EXPECT_EQ(readText(o.save_to), "[rangefinder]\n");  // nothing saved
	o.accept = true;
	testing::internal::CaptureStderr();
	CalibrateApp(o).runRim();
	const std::string warned = testing::internal::GetCapturedStderr();
	EXPECT_NE(warned.find("warning: the disc found"), std::string::npos) << warned;
	EXPECT_NE(readText(o.save_to).find("cx = "), std::string::npos);
}

TEST(AppClasses, AFusedScanFollowsItsLaserAndIsNeverFartherThanIt)
{
	const std::string dir = workDir("fused");
	ScanApp::Options s = scanOf(dir, kSample);
	s.scan.fuse_with = kLaserLabel;
	const RawlogScanSummary scanned = ScanApp(s).run();
	EXPECT_EQ(scanned.fused, 20u);  // every image of the sample has its laser scan

	// In the file: each FUSED scan right after the LASER scan of its moment, after the image's OMNISCAN.
	RawlogProcessor loop(s.scan.output);
	mrpt::obs::CObservation2DRangeScan::Ptr laser, omni;
	std::string previous;
	int fused = 0, from_omnicam = 0, checked = 0;
	loop.on<mrpt::obs::CObservation2DRangeScan>("", [&](const mrpt::obs::CObservation2DRangeScan::Ptr& scan) {
		if (scan->sensorLabel == kLaserLabel) laser = scan;
		if (scan->sensorLabel == kOmniscanLabel) omni = scan;
		if (scan->sensorLabel == kFusedLabel)
		{
			++fused;
			EXPECT_EQ(previous, kLaserLabel);
			ASSERT_TRUE(laser && omni);
			EXPECT_EQ(scan->timestamp, omni->timestamp);
			const auto along = laserAlong(*laser, *omni);
			for (std::size_t i = 0; i < along.size(); ++i)
			{
				if (along[i].kind != LaserReading::Kind::Return) continue;
				// Never past the laser's return; where it is nearer, the omnicam's sure hit.
				ASSERT_TRUE(scan->getScanRangeValidity(i));
				EXPECT_LE(scan->getScanRange(i), along[i].range + 1e-4);
				if (scan->getScanIntensity(i) == static_cast<int>(FusedSource::Omnicam))
				{
					++from_omnicam;
					EXPECT_FLOAT_EQ(scan->getScanRange(i), omni->getScanRange(i));
				}
				++checked;
			}
		}
		previous = scan->sensorLabel;
	});
	loop.run();
	EXPECT_EQ(fused, 20);
	EXPECT_GT(checked, 20 * 100);
	EXPECT_GT(from_omnicam, 0);  // the factory's cabinet body is above the laser's plane

	// A label the rawlog does not hold: one line naming it, no output.
	fs::remove(s.scan.output);
	s.scan.fuse_with = "NOSUCH";
	EXPECT_THROW(
		{
			try
			{
				ScanApp(s).run();
			}
			catch (const std::runtime_error& e)
			{
				EXPECT_NE(std::string(e.what()).find("NOSUCH"), std::string::npos) << e.what();
				throw;
			}
		},
		std::runtime_error);
	EXPECT_FALSE(fs::exists(s.scan.output));
}
