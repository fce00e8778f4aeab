// The tuner without its window: a session over the factory sample scans
// frames, follows parameter changes, trains, scores and saves the ini into a
// user's file without losing its comments; the overlays show what the scan
// found where it found it.
#include <omnirange_tuner/Overlays.h>
#include <omnirange_tuner/TunerSession.h>

#include "../common/FactorySample.h"

#include <mrpt/config/CConfigFile.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace omnirange;
using namespace omnirange::tuner;
namespace fs = std::filesystem;

namespace
{
using test::kIni;
using test::kSample;

std::string workDir(const std::string& name) { return test::freshDir("omnirange_tuner", name); }
std::string read(const std::string& path) { return test::readText(path); }

/** A session on the sample with a histogram trained in it. */
TunerSession trainedSession(const std::string& dir)
{
	SessionOptions o;
	o.rawlog = kSample;
	o.ini = kIni;
	TunerSession s(o);
	EXPECT_FALSE(s.hasColours());
	std::size_t last_count = 0;
	const auto r = s.train(dir + "/f.hist", {}, [&](std::size_t objects) { last_count = objects; });
	EXPECT_GT(last_count, 0u);  // the window's progress bar heard of it
	EXPECT_EQ(r.used, 20);
	EXPECT_TRUE(s.hasColours());
	EXPECT_TRUE(fs::exists(dir + "/f.hist"));
	return s;
}

int countColour(const cv::Mat& img, const cv::Scalar& c)
{
	int n = 0;
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
		{
			const auto& p = img.at<cv::Vec3b>(v, u);
			n += p[0] == c[0] && p[1] == c[1] && p[2] == c[2];
		}
	return n;
}
}  // namespace

TEST(TunerSession, FramesScansAndTheLaserAgreement)
{
	const std::string dir = workDir("frames");
	TunerSession s = trainedSession(dir);
	ASSERT_EQ(s.frames(), 20);
	for (int k = 0; k < s.frames(); ++k) EXPECT_TRUE(s.frame(k).laser) << k;
	const FrameScan f = s.scan(5);
	EXPECT_EQ(f.index, 5);
	EXPECT_EQ(f.scan.rays.size(), 360u);
	EXPECT_GT(f.scan.count(RayStatus::Hit), 50);
	const Agreement a = agreementOf(f.laser_pairs);
	EXPECT_GT(a.compared, 40u);
	EXPECT_LT(a.mean_abs, 0.1375);  // the paper's worst Table II figure
	const LogScore all = s.scoreAll();
	EXPECT_EQ(all.frames, 20);
	EXPECT_LT(all.mean_abs, 0.1375);
	// Each frame's own figure, against the laser and the simulator's truth; frame 5's is the one scanned above.
	ASSERT_EQ(all.laser_by_frame.size(), 20u);
	EXPECT_NEAR(all.laser_by_frame[5], a.mean_abs, 1e-12);
	for (int k = 0; k < 20; ++k)
		EXPECT_EQ(std::isfinite(all.truth_by_frame[static_cast<std::size_t>(k)]), s.frame(k).truth != nullptr) << k;
	// The plot of them: a click at its left edge is frame 0, at its right edge the last.
	const cv::Mat plot = drawErrorPlot(all, 5, cv::Size(400, 64));
	EXPECT_GT(countColour(plot, colour::kLaser), 20);
	EXPECT_EQ(countColour(plot, colour::kTruth) > 20, s.frame(0).truth != nullptr);
	EXPECT_EQ(frameAtColumn(0, 400, 20), 0);
	EXPECT_EQ(frameAtColumn(399, 400, 20), 19);
	EXPECT_EQ(frameAtColumn(105, 400, 20), 5);
}

TEST(TunerSession, ChangesCanBeUndoneOneByOneAndResetToWhatTheIniHeld)
{
	const std::string dir = workDir("undo");
	TunerSession s = trainedSession(dir);
	const double loaded = s.params().threshold;
	EXPECT_FALSE(s.undo());  // nothing changed yet
	for (const double t : {0.1, 0.2, 0.3})
	{
		RangefinderParams p = s.params();
		p.threshold = t;
		s.changeParams(p);
	}
	s.changeParams(s.params());  // the same values: no step to undo
	ASSERT_TRUE(s.undo());
	EXPECT_DOUBLE_EQ(s.params().threshold, 0.2);
	s.resetToLoaded();
	EXPECT_DOUBLE_EQ(s.params().threshold, loaded);
	EXPECT_FALSE(s.unsaved());
	ASSERT_TRUE(s.undo());  // the reset itself is a step
	EXPECT_DOUBLE_EQ(s.params().threshold, 0.2);
	ASSERT_TRUE(s.undo());
	EXPECT_DOUBLE_EQ(s.params().threshold, 0.1);
	ASSERT_TRUE(s.undo());
	EXPECT_DOUBLE_EQ(s.params().threshold, loaded);
	EXPECT_FALSE(s.undo());
	// A/B: the log scored with the loaded values while others are in force, which stay.
	const LogScore loaded_score = s.scoreAll();
	RangefinderParams p = s.params();
	p.threshold = 0.3;
	s.changeParams(p);
	const LogScore changed = s.scoreAll(), ab = s.scoreWith(s.loaded());
	EXPECT_DOUBLE_EQ(ab.mean_abs, loaded_score.mean_abs);
	EXPECT_NE(changed.mean_abs, loaded_score.mean_abs);
	EXPECT_DOUBLE_EQ(s.params().threshold, 0.3);
}

TEST(TunerSession, ParameterChangesRescanAndImpossibleOnesAreRefused)
{
	const std::string dir = workDir("params");
	TunerSession s = trainedSession(dir);
	const int hits = s.scan(3).scan.count(RayStatus::Hit);
	RangefinderParams p = s.params();
	p.threshold = 1.0;  // no colour is that frequent: nothing is floor
	s.setParams(p);
	EXPECT_EQ(s.scan(3).scan.count(RayStatus::TooClose), 360);
	RangefinderParams bad = s.params();
	bad.scanner.filter.N = 0;
	EXPECT_THROW(s.setParams(bad), std::invalid_argument);
	EXPECT_EQ(s.params().scanner.filter.N, p.scanner.filter.N);  // the old ones stay
	p.threshold = 0.075;
	s.setParams(p);
	EXPECT_EQ(s.scan(3).scan.count(RayStatus::Hit), hits);
}

TEST(TunerSession, ChangesAreUnsavedUntilSaved)
{
	const std::string dir = workDir("unsaved");
	TunerSession s = trainedSession(dir);
	EXPECT_FALSE(s.unsaved());
	RangefinderParams p = s.params();
	const double loaded = p.threshold;
	p.threshold = loaded * 2;
	s.setParams(p);
	EXPECT_TRUE(s.unsaved());
	p.threshold = loaded;  // back to what the ini holds
	s.setParams(p);
	EXPECT_FALSE(s.unsaved());
	p.scanner.filter.K += 1;
	s.setParams(p);
	fs::copy_file(kIni, dir + "/user.ini");
	fs::copy_file(test::kSource + "/ini/experiment-base.ini", dir + "/experiment-base.ini");  // its base: it loads
	s.saveIni(dir + "/user.ini");
	EXPECT_FALSE(s.unsaved());
}

TEST(TunerSession, ImagesThatCannotWorkAreRefusedAtStartAndOneBadFrameIsLeftOut)
{
	const std::string dir = workDir("bad_images");
	const std::string log = dir + "/factory-sample.rawlog", images = dir + "/factory-sample_Images";
	fs::copy_file(kSample, log);
	fs::copy(test::kSource + "/rawlogs/factory-sample_Images", images);
	const std::string cut = images + "/factory-sample_OMNICAM_000003.jpg";
	const std::string bytes = read(cut);
	std::ofstream(cut, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() / 2);

	trainedSession(dir);  // on the whole sample: training stops at a cut image
	SessionOptions o;
	o.rawlog = log;
	o.ini = kIni;
	o.histogram = dir + "/f.hist";
	TunerSession s(o);
	EXPECT_NO_THROW(s.scan(2));
	try
	{
		s.scan(3);
		ADD_FAILURE() << "a cut frame scanned";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("000003.jpg"), std::string::npos) << e.what();
	}
	const Agreement all = s.scoreAll();
	EXPECT_EQ(all.unreadable, 1);
	EXPECT_EQ(all.frames, 19);

	// Every frame would fail: refused before any window opens, saying why.
	const auto refused = [&](const SessionOptions& bad, const std::string& why) {
		try
		{
			TunerSession{bad};
			ADD_FAILURE() << "accepted; expected: " << why;
		}
		catch (const std::runtime_error& e)
		{
			EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
		}
	};
	std::ofstream(dir + "/wide.ini") << "base = " << kIni << "\n[rangefinder]\nimage_width = 800\n";
	SessionOptions wide = o;
	wide.ini = dir + "/wide.ini";
	refused(wide, "is 1024x768 but the camera is 800x768");
	fs::rename(images, dir + "/elsewhere");
	refused(o, "the images folder '");
}

TEST(TunerSession, FramesOfImagesWrittenAgainWhileTheWindowIsOpenAreRefused)
{
	// A simulation run again onto the log the tuner has open: its new pictures under the old laser would score wrong.
	const std::string dir = workDir("written_again");
	const std::string log = dir + "/factory-sample.rawlog", images = dir + "/factory-sample_Images";
	fs::copy_file(kSample, log);
	fs::copy(test::kSource + "/rawlogs/factory-sample_Images", images);
	SessionOptions o;
	o.rawlog = log;
	o.ini = kIni;
	TunerSession s(o);
	s.train(dir + "/f.hist", {}, {});
	EXPECT_NO_THROW(s.image(1));
	fs::copy(images, dir + "/new_Images");
	fs::rename(images, dir + "/old_Images");
	fs::rename(dir + "/new_Images", images);  // a writer's last step: the same pictures, another folder
	EXPECT_NO_THROW(s.image(1));  // the picture already shown is the one read with its laser
	try
	{
		s.image(2);
		ADD_FAILURE() << "a frame of the images written again was decoded";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("were replaced after it was opened"), std::string::npos) << e.what();
	}
	EXPECT_THROW(s.scoreAll(), std::runtime_error);  // not a score with every frame "unreadable"
	EXPECT_THROW(s.train(dir + "/g.hist", {}, {}), std::runtime_error);  // the frames shown are the old log's
}

TEST(TunerSession, SavingKeepsTheUsersCommentsAndOtherSections)
{
	const std::string dir = workDir("save");
	TunerSession s = trainedSession(dir);
	const std::string user = dir + "/user.ini";
	// The maze's ini: an [experiment] section, then a [rangefinder] one.
	const std::string original = test::kSource + "/ini/maze.ini";
	fs::copy_file(original, user);
	fs::copy_file(test::kSource + "/ini/experiment-base.ini", dir + "/experiment-base.ini");  // its base
	RangefinderParams p = s.params();
	p.threshold = 0.0123;
	p.scanner.filter.K = 5;
	s.setParams(p);
	s.saveIni(user);
	RangefinderParams back;
	back.loadFromConfig(mrpt::config::CConfigFile(user), "rangefinder");
	EXPECT_DOUBLE_EQ(back.threshold, 0.0123);
	EXPECT_EQ(back.scanner.filter.K, 5);
	// Only the two keys changed are written: every other line stays as the user
	// wrote it (no default keys added, no number reformatted); a key the file
	// lacked comes with its comment (its unit and meaning).
	const auto lines = [](const std::string& text) {
		std::istringstream in(text);
		std::vector<std::string> out;
		for (std::string l; std::getline(in, l);) out.push_back(l);
		return out;
	};
	const auto before = lines(read(original)), after = lines(read(user));
	auto sorted_before = before, sorted_after = after;
	std::sort(sorted_before.begin(), sorted_before.end()), std::sort(sorted_after.begin(), sorted_after.end());
	std::vector<std::string> added, removed;
	std::set_difference(sorted_after.begin(), sorted_after.end(), sorted_before.begin(), sorted_before.end(),
						std::back_inserter(added));
	std::set_difference(sorted_before.begin(), sorted_before.end(), sorted_after.begin(), sorted_after.end(),
						std::back_inserter(removed));
	std::set<std::string> allowed{"threshold = 0.0123", "K = 5"};
	for (const auto& [key, c] : RangefinderParams::table().comments())
		if (key == "threshold" || key == "K") allowed.insert("; " + c);
	for (const auto& l : added) EXPECT_TRUE(allowed.count(l)) << "a line nobody changed: " << l;
	for (const auto& l : removed)
		EXPECT_TRUE(l.rfind("threshold", 0) == 0 || l.rfind("K ", 0) == 0) << "a line of the user's lost: " << l;
	// Saved again with nothing changed: not a byte moves.
	s.saveIni(user);
	EXPECT_EQ(lines(read(user)), after);
}

TEST(TunerSession, SavingKeepsAnEditMadeInTheFileWhileTheWindowWasOpen)
{
	const std::string dir = workDir("save_edit");
	fs::copy_file(kIni, dir + "/user.ini");
	fs::copy_file(test::kSource + "/ini/experiment-base.ini", dir + "/experiment-base.ini");  // its base
	SessionOptions o;
	o.rawlog = kSample;
	o.ini = dir + "/user.ini";
	TunerSession s(o);
	s.train(dir + "/f.hist");
	// The user edits N in the file meanwhile; the window changes only the threshold.
	std::ofstream(o.ini, std::ios::app) << "\n[rangefinder]\nN = 11\n";
	RangefinderParams p = s.params();
	p.threshold = 0.0123;
	s.setParams(p);
	s.saveIni();
	const RangefinderParams back = RangefinderParams::loadFromFile(o.ini, "rangefinder");
	EXPECT_DOUBLE_EQ(back.threshold, 0.0123);
	EXPECT_EQ(back.scanner.filter.N, 11) << "an edit made in the file was undone";
}

TEST(TunerSession, SaveChecksTheIniAgainWhenItIsSavedNotOnlyWhenTheWindowOpens)
{
	const std::string dir = workDir("save_moved");
	fs::copy_file(kIni, dir + "/user.ini");
	fs::copy_file(test::kSource + "/ini/experiment-base.ini", dir + "/experiment-base.ini");
	const std::string base_text = read(dir + "/experiment-base.ini");
	SessionOptions o;
	o.rawlog = kSample;
	o.ini = dir + "/user.ini";
	TunerSession s(o);
	RangefinderParams p = s.params();
	p.threshold = 0.0123;
	s.setParams(p);
	const auto refusal = [&] {
		try
		{
			s.saveIni();
			return std::string();
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
	};
	// The ini moved away meanwhile: a new file would hold the threshold and none of its other keys or its base.
	fs::rename(o.ini, dir + "/moved.ini");
	EXPECT_NE(refusal().find("was moved or removed since the window opened"), std::string::npos);
	EXPECT_FALSE(fs::exists(o.ini));
	// Put back as a link to its base: the base, which other inis read, is not written through it.
	fs::create_symlink("experiment-base.ini", o.ini);
	EXPECT_NE(refusal().find("is the input"), std::string::npos) << refusal();
	EXPECT_EQ(read(dir + "/experiment-base.ini"), base_text);
	fs::remove(o.ini);
	// Put back as a link to a file that is no input (another camera's ini): not the file the window opened on.
	std::ofstream(dir + "/camera2.ini") << "[rangefinder]\nthreshold = 0.9\n";
	fs::create_symlink("camera2.ini", o.ini);
	EXPECT_NE(refusal().find("now leads to"), std::string::npos) << refusal();
	EXPECT_EQ(read(dir + "/camera2.ini"), "[rangefinder]\nthreshold = 0.9\n");
	fs::remove(o.ini);
	// Its base line edited to a file that is not there: what would be saved no program could read.
	std::ofstream(o.ini) << "base = missing-base.ini\n[rangefinder]\nN = 12\n";
	EXPECT_NE(refusal().find("missing-base.ini"), std::string::npos) << refusal();
	EXPECT_EQ(read(o.ini), "base = missing-base.ini\n[rangefinder]\nN = 12\n");
	fs::remove(o.ini);
	// Emptied meanwhile (by an editor, a copy that failed): the same as gone.
	const std::string text = read(dir + "/moved.ini");
	std::ofstream(o.ini).flush();
	EXPECT_NE(refusal().find("holds no key now"), std::string::npos) << refusal();
	EXPECT_EQ(fs::file_size(o.ini), 0u);
	fs::remove(o.ini);
	fs::rename(dir + "/moved.ini", o.ini);
	EXPECT_EQ(read(o.ini), text);
	EXPECT_EQ(refusal(), "");
	EXPECT_DOUBLE_EQ(RangefinderParams::loadFromFile(o.ini, "rangefinder").threshold, 0.0123);
	// Another ini to save into (--save-to), there when the window opened: the same once it is gone.
	fs::copy_file(o.ini, dir + "/other.ini");
	s.requireSaveAllowed(dir + "/other.ini");
	fs::remove(dir + "/other.ini");
	EXPECT_THROW(s.saveIni(dir + "/other.ini"), std::runtime_error);
	EXPECT_FALSE(fs::exists(dir + "/other.ini"));
	s.saveIni(dir + "/new.ini");  // one that was never there is made
	EXPECT_TRUE(fs::exists(dir + "/new.ini"));
	std::ofstream(dir + "/empty.ini").flush();  // and one empty when first checked takes its first keys
	s.saveIni(dir + "/empty.ini");
	EXPECT_DOUBLE_EQ(RangefinderParams::loadFromFile(dir + "/empty.ini", "rangefinder").threshold, 0.0123);
}

TEST(TunerOverlays, RayEndsLaserAndFreeTintAreDrawnWhereTheScanSaysAndOffMeansOff)
{
	const std::string dir = workDir("overlays");
	TunerSession s = trainedSession(dir);
	const FrameScan f = s.scan(5);
	const Rangefinder& rf = s.rangefinder();
	OverlayOptions none;
	none.classification = none.rays = none.candidates = none.laser = none.truth = none.camera = none.legend = false;
	const cv::Mat plain = drawOmniOverlay(f, rf, none);
	EXPECT_EQ(cv::norm(plain, f.bgr, cv::NORM_INF), 0.0);

	OverlayOptions rays = none;
	rays.rays = true;
	const cv::Mat with_rays = drawOmniOverlay(f, rf, rays);
	// Every hit's end pixel is painted the hit colour.
	int checked = 0, hit_coloured = 0;
	for (const Ray& r : f.scan.rays)
	{
		if (r.status != RayStatus::Hit) continue;
		const Pixel p = rf.camera().pixelFromPolar(r.bearing, r.hit_rho);
		const cv::Vec3b px = with_rays.at<cv::Vec3b>(static_cast<int>(std::lround(p.v)), static_cast<int>(std::lround(p.u)));
		const cv::Scalar c(px[0], px[1], px[2]);
		// The hit colour, or a neighbouring ray's status colour drawn over it.
		EXPECT_TRUE(c == colour::kHit || c == colour::kNoHit || c == colour::kTooClose || c == colour::kOutlier)
			<< r.bearing << ": " << c;
		hit_coloured += c == colour::kHit;
		++checked;
	}
	EXPECT_GT(checked, 50);
	EXPECT_GT(hit_coloured, 0.9 * checked);  // overdrawn by a neighbour now and then, not as a rule

	OverlayOptions laser = none;
	laser.laser = true;
	EXPECT_GT(countColour(drawOmniOverlay(f, rf, laser), colour::kLaser), 50);

	OverlayOptions tint = none;
	tint.classification = true;
	tint.legend = false;
	const cv::Mat tinted = drawOmniOverlay(f, rf, tint);
	// Just beyond the base ahead is free floor: tinted towards blue in stripes,
	// so about half of a patch there is tinted and half is not.
	const Pixel ahead = rf.camera().pixelFromPolar(0.0, rf.params().scanner.base_radius + 8);
	int tinted_px = 0, patch = 0;
	for (int dv = -3; dv <= 3; ++dv)
		for (int du = -3; du <= 3; ++du, ++patch)
		{
			const cv::Point at(static_cast<int>(ahead.u) + du, static_cast<int>(ahead.v) + dv);
			const cv::Vec3b a = tinted.at<cv::Vec3b>(at), b = f.bgr.at<cv::Vec3b>(at);
			tinted_px += a[0] > b[0] && a[2] < b[2];
		}
	EXPECT_GT(tinted_px, patch / 4);
	EXPECT_LT(tinted_px, 3 * patch / 4);

	// In dimmer light, with exposure compensation on, the tint shows what the
	// scan classified: the compensated floor, which the trained classifier
	// alone calls an obstacle.
	RangefinderParams compensated = s.params();
	compensated.exposure_compensation = true;
	const Rangefinder dim_rf(compensated, s.colours());
	FrameScan dim = f;
	f.bgr.convertTo(dim.bgr, -1, 0.6);
	const cv::Mat dim_tinted = drawOmniOverlay(dim, dim_rf, tint);
	int dim_free = 0, dim_tinted_px = 0;
	for (int dv = -3; dv <= 3; ++dv)
		for (int du = -3; du <= 3; ++du)
		{
			const cv::Point at(static_cast<int>(ahead.u) + du, static_cast<int>(ahead.v) + dv);
			const cv::Vec3b d = dim.bgr.at<cv::Vec3b>(at);
			dim_free += rf.classifier().isFree(&d[0]);
			dim_tinted_px += dim_tinted.at<cv::Vec3b>(at)[0] > d[0];
		}
	ASSERT_EQ(dim_free, 0) << "the dimmed floor must be outside the trained colours";
	EXPECT_GT(dim_tinted_px, patch / 4);

	const cv::Mat plot = drawScanPlot(f, s.params(), 300);
	EXPECT_GT(countColour(plot, colour::kHit), 50);
	EXPECT_GT(countColour(plot, colour::kLaser), 20);
	const cv::Mat swatches = drawFloorColours(s.colours(), rf.classifier(), cv::Size(160, 160));
	EXPECT_GT(countColour(swatches, cv::Scalar(30, 30, 30)), 0);
	EXPECT_LT(countColour(swatches, cv::Scalar(30, 30, 30)), 160 * 160);
}

TEST(TunerOverlays, RaysTheBrightnessStepEndedAreRinged)
{
	const std::string dir = workDir("step_rings");
	TunerSession s = trainedSession(dir);
	OverlayOptions rays;
	rays.classification = rays.candidates = rays.laser = rays.truth = rays.camera = false;
	const FrameScan off = s.scan(5);
	EXPECT_EQ(countColour(drawOmniOverlay(off, s.rangefinder(), rays), colour::kByStep), 0);
	RangefinderParams p = s.params();
	p.scanner.step_threshold = 0.05;  // low: the sample's floor has steps that high
	s.setParams(p);
	const FrameScan on = s.scan(5);
	int by_step = 0;
	for (const Ray& r : on.scan.rays) by_step += r.by_step;
	ASSERT_GT(by_step, 0);
	EXPECT_GT(countColour(drawOmniOverlay(on, s.rangefinder(), rays), colour::kByStep), by_step);
}

TEST(TunerOverlays, APlaceholderShowsItsReasonOnNoPicture)
{
	const cv::Mat p = drawPlaceholder({640, 480}, "frame 3: image 'x.jpg' is truncated: no JPEG end-of-image marker");
	ASSERT_EQ(p.size(), cv::Size(640, 480));
	const int background = countColour(p, colour::kPlaceholder), text = countColour(p, cv::Scalar(255, 255, 255));
	EXPECT_GT(background, 640 * 480 * 9 / 10);
	EXPECT_GT(text, 200);  // the reason is written
	EXPECT_EQ(countColour(p, colour::kHit), 0);  // nothing of a scan
}
