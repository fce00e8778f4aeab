// Bad input to the apps: a clear one-line error, a non-zero exit, and no
// output left behind that looks whole.
#include "Programs.h"

using namespace omnirange::e2e;
namespace fs = std::filesystem;

namespace
{
const std::string kSample = kSource + "/rawlogs/factory-sample.rawlog";
const std::string kIni = kSource + "/ini/factory.ini";

/** One line on stderr naming `what`, exit code 1. */
void expectCleanFailure(const RunResult& r, const std::string& what)
{
	EXPECT_EQ(r.code, 1) << r.out;
	EXPECT_NE(r.out.find(what), std::string::npos) << r.out;
	EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
}

std::string histogram(const std::string& dir)
{
	const RunResult t = run(app("omnirange-train") + " -q -i " + q(kSample) + " -c " + q(kIni) + " -o " + q(dir + "/f.hist"));
	EXPECT_EQ(t.code, 0) << t.out;
	return dir + "/f.hist";
}

/** A copy of the sample's uncompressed bytes, edited by `sed_or_head`, re-gzipped, beside a link to its images. */
std::string damaged(const std::string& dir, const std::string& name, const std::string& edit)
{
	const std::string out = dir + "/" + name + ".rawlog";
	const RunResult r = run("zcat " + q(kSample) + " | " + edit + " | gzip > " + q(out) + " && ln -sfn " +
					  q(kSource + "/rawlogs/factory-sample_Images") + " " + q(dir + "/" + name + "_Images"));
	EXPECT_EQ(r.code, 0) << r.out;
	return out;
}
}  // namespace

TEST(Apps, ScanOfATruncatedRawlogFailsAndWritesNothing)
{
	const std::string dir = workDir("truncated");
	const std::string hist = histogram(dir);
	const std::string in = damaged(dir, "cut", "head -c 20000");
	const RunResult r = run(app("omnirange-scan") + " -q -i " + q(in) + " -c " + q(kIni) + " -H " + q(hist) + " -o " + q(dir + "/out.rawlog"));
	expectCleanFailure(r, "truncated or corrupt after");
	EXPECT_FALSE(fs::exists(dir + "/out.rawlog"));
	EXPECT_FALSE(fs::exists(dir + "/out_Images"));
	for (const auto& e : fs::directory_iterator(dir)) EXPECT_NE(e.path().filename().string().rfind(".omnirange-", 0), 0u) << e.path();
}

TEST(Apps, ScanOfARawlogWithAnUnknownClassFails)
{
	const std::string dir = workDir("unknown_class");
	const std::string hist = histogram(dir);
	const std::string in = damaged(dir, "alien", "LC_ALL=C sed 's/CObservationOdometry/CObservationOdometrX/g'");
	// MRPT's own reader stops there silently: rawlog-edit reports fewer objects and succeeds.
	const RunResult info = run("rawlog-edit --info -i " + q(in));
	EXPECT_EQ(info.code, 0);
	const RunResult r = run(app("omnirange-scan") + " -q -i " + q(in) + " -c " + q(kIni) + " -H " + q(hist) + " -o " + q(dir + "/out.rawlog"));
	expectCleanFailure(r, "CObservationOdometrX");
	EXPECT_FALSE(fs::exists(dir + "/out.rawlog"));
}

TEST(Apps, ScanWithMissingImagesOrTheWrongSizeFails)
{
	const std::string dir = workDir("images");
	const std::string hist = histogram(dir);
	fs::copy_file(kSample, dir + "/noimages.rawlog");
	RunResult r = run(app("omnirange-scan") + " -q -i " + q(dir + "/noimages.rawlog") + " -c " + q(kIni) + " -H " + q(hist) +
				" -o " + q(dir + "/out.rawlog"));
	expectCleanFailure(r, "of OMNICAM is missing");
	EXPECT_FALSE(fs::exists(dir + "/out.rawlog"));

	std::ofstream(dir + "/small.ini") << "[rangefinder]\nimage_width = 640\nimage_height = 480\ncx = 320\ncy = 240\n";
	r = run(app("omnirange-scan") + " -q -i " + q(kSample) + " -c " + q(dir + "/small.ini") + " -H " + q(hist) + " -o " +
			q(dir + "/out.rawlog"));
	expectCleanFailure(r, "is 1024x768 but");
	EXPECT_FALSE(fs::exists(dir + "/out.rawlog"));
}

TEST(Apps, ImpossibleParametersAndMissingFiles)
{
	const std::string dir = workDir("params");
	const std::string hist = histogram(dir);
	std::ofstream(dir + "/n0.ini") << "[rangefinder]\nN = 0\n";
	RunResult r = run(app("omnirange-scan") + " -q -i " + q(kSample) + " -c " + q(dir + "/n0.ini") + " -H " + q(hist) + " -o " + q(dir + "/o.rawlog"));
	expectCleanFailure(r, "[rangefinder] N = '0': must be within [1, 10000] px");
	std::ofstream(dir + "/typo.ini") << "[rangefinder]\nthreshhold = 0.1\n";
	r = run(app("omnirange-scan") + " -q -i " + q(kSample) + " -c " + q(dir + "/typo.ini") + " -H " + q(hist) + " -o " + q(dir + "/o.rawlog"));
	expectCleanFailure(r, "unknown key 'threshhold'");
	r = run(app("omnirange-scan") + " -q -i " + q(dir + "/nowhere.rawlog") + " -c " + q(kIni) + " -H " + q(hist) + " -o " + q(dir + "/o.rawlog"));
	expectCleanFailure(r, "cannot open rawlog");
	std::ofstream(dir + "/bad.hist") << "not a histogram";
	r = run(app("omnirange-scan") + " -q -i " + q(kSample) + " -c " + q(kIni) + " -H " + q(dir + "/bad.hist") + " -o " + q(dir + "/o.rawlog"));
	expectCleanFailure(r, "not an omnirange histogram file");
	r = run(app("omnirange-scan") + " -q --bogus");
	EXPECT_EQ(r.code, 2) << r.out;
	EXPECT_FALSE(fs::exists(dir + "/o.rawlog"));
}

TEST(Apps, TrainingWithoutALaserFails)
{
	const std::string dir = workDir("no_laser");
	const RunResult cut = run("cd " + q(dir) + " && rawlog-edit --remove-label LASER -i " + q(kSample) + " -o nolaser.rawlog -w");
	ASSERT_EQ(cut.code, 0) << cut.out;
	fs::create_directory_symlink(kSource + "/rawlogs/factory-sample_Images", dir + "/nolaser_Images");
	const RunResult r = run(app("omnirange-train") + " -q -i " + q(dir + "/nolaser.rawlog") + " -c " + q(kIni) + " -o " + q(dir + "/f.hist"));
	expectCleanFailure(r, "training needs both");
	EXPECT_FALSE(fs::exists(dir + "/f.hist"));
}

TEST(Apps, AccuracyOfTheFactorySample)
{
	const std::string dir = workDir("accuracy");
	const std::string scanned = scannedFactorySample(dir);
	const RunResult r = run(app("omnirange-accuracy") + " -q -i " + q(scanned) + " -o " + q(dir + "/acc"));
	ASSERT_EQ(r.code, 0) << r.out;
	for (const std::string f : {"_pairs.csv", "_histogram.png", "_table.md"}) EXPECT_TRUE(fs::exists(dir + "/acc" + f)) << f;
	// One CSV row per valid laser ray: the sample's 20 scans of 181 rays.
	const auto csv = run("tail -n +2 " + q(dir + "/acc_pairs.csv") + " | wc -l");
	EXPECT_GT(std::stoi(csv.out), 20 * 150);
	EXPECT_LE(std::stoi(csv.out), 20 * 181);
	const RunResult none = run(app("omnirange-accuracy") + " -q -i " + q(kSample) + " -o " + q(dir + "/none"));
	expectCleanFailure(none, "no LASER observation had a partner labelled OMNISCAN within 0.1 s");
	EXPECT_FALSE(fs::exists(dir + "/none_table.md"));
}

namespace
{
/** The hidden staging folders in `dir` (Output.h). */
int stagingIn(const std::string& dir)
{
	int n = 0;
	for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().rfind(".omnirange-", 0) == 0;
	return n;
}
}  // namespace

TEST(Apps, AnInterruptedRunLeavesTheOldOutputAndTheNextRunRemovesWhatItLeft)
{
	// SIGINT in the middle of a whole-route simulation and of an experiment, over outputs of theirs.
	const std::string dir = workDir("interrupted"), hist = histogram(dir);
	const std::string old_report = dir + "/report/old.md";
	fs::create_directories(dir + "/report");
	std::ofstream(dir + "/report/.omnirange-output") << "omnirange-experiment\nfile old.md\n";
	std::ofstream(old_report) << "old";
	RunResult r = run("timeout -s INT 2 " + app("omnirange-sim") + " -q -w " + q(kSource + "/worlds/factory.world") +
					  " -r " + q(kSource + "/worlds/factory.route") + " -o " + q(dir + "/sim.rawlog"));
	EXPECT_NE(r.code, 0) << r.out;  // it was interrupted, not finished
	EXPECT_FALSE(fs::exists(dir + "/sim.rawlog"));
	r = run("timeout -s INT 4 " + app("omnirange-experiment") + " " + q(kSource + "/ini/maze.ini") + " -o " +
			q(dir + "/report"));
	EXPECT_NE(r.code, 0) << r.out;
	EXPECT_NE(r.out.find("[1/8] simulate"), std::string::npos) << r.out;  // what it said, into a pipe, is kept
	EXPECT_EQ(fs::file_size(old_report), 3u);
	// The next run writing there removes what the interrupted ones left.
	const RunResult next = run(app("omnirange-train") + " -q -i " + q(kSample) + " -c " + q(kIni) + " -o " + q(dir + "/g.hist"));
	EXPECT_EQ(next.code, 0) << next.out;
	EXPECT_EQ(stagingIn(dir), 0);
}

TEST(Apps, ACorruptJpegInsideARawlogEndsTheRunNamingTheRawlog)
{
	// Found by fuzzing: MRPT decodes a JPEG stored in a rawlog with libjpeg's
	// default error handler, which calls exit() on corrupt data. The run
	// cannot go on, but it must name the rawlog and put nothing in place.
	const std::string dir = workDir("corrupt_embedded_jpeg");
	const std::string in = kSource + "/tests/data/corrupt-embedded-jpeg.rawlog";
	const RunResult r = run(app("omnirange-scan") + " -q -i " + q(in) + " -c " + q(kSource + "/ini/factory.ini") +
							" -H " + q(kSource + "/fuzz/corpus/histogram/one_class_rgb4.hist") + " -o out.rawlog", dir);
	EXPECT_EQ(r.code, 1) << r.out;
	EXPECT_NE(r.out.find("corrupt-embedded-jpeg.rawlog"), std::string::npos) << r.out;
	for (const auto& e : fs::directory_iterator(dir))  // only a hidden staging folder, for the next run to remove
		EXPECT_EQ(e.path().filename().string().rfind(".omnirange-", 0), 0u) << e.path();
}
