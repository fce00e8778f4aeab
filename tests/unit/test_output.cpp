// The output guarantee (config/Output.h): an output replaces only what the
// same program wrote, never an input; a killed or failed run leaves the old
// output whole and nothing that looks whole; the files of one run go in together.
#include <omnirange/config/Output.h>
#include <omnirange/io/RawlogWriter.h>

#include "../common/FactorySample.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/core.hpp>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

using namespace omnirange;
namespace fs = std::filesystem;

namespace
{
std::string fresh(const std::string& name) { return test::freshDir("omnirange_output", name); }
void put(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }
std::string read(const std::string& path) { return test::readText(path); }

using test::errorOf;
#define EXPECT_REFUSED(call, phrase)                                              \
	do                                                                            \
	{                                                                             \
		const std::string why = errorOf([&] { call; });                           \
		EXPECT_NE(why.find(phrase), std::string::npos) << "said: '" << why << "'"; \
	} while (0)

/** The lines of the marker in the folder `dir`. */
std::vector<std::string> markerLines(const std::string& dir)
{
	std::ifstream f(fs::path(dir) / kOutputMarker);
	std::vector<std::string> lines;
	for (std::string l; std::getline(f, l);) lines.push_back(l);
	return lines;
}

/** The names in `dir` that are staging folders (none once every run there is over). */
int stagingIn(const std::string& dir)
{
	int n = 0;
	for (const auto& e : fs::directory_iterator(dir))
		if (const std::string name = e.path().filename().string(); name.rfind(".omnirange-", 0) == 0 && name != kOutputMarker)
			++n;
	return n;
}

void commitFiles(const std::vector<std::pair<std::string, std::string>>& files, const std::string& program = "")
{
	OutputSet set(program);
	for (const auto& [path, text] : files) set.write({path, OutputKind::Text}, text);
	set.commit();
}

/** A folder `program` writes at `dir` holding `files` (name, text). */
void commitFolder(const std::string& dir, const std::string& program, const std::vector<std::pair<std::string, std::string>>& files,
				  bool force = false)
{
	requireOutputAllowed(dir, OutputKind::Folder, program, {}, force);
	OutputSet set(program, {}, force);
	const std::string staged = set.stage({dir, OutputKind::Folder});
	fs::create_directory(staged);
	for (const auto& [name, text] : files) put(staged + "/" + name, text);
	set.commit();
}

void writeRawlog(const std::string& path)
{
	mrpt::io::CFileGZOutputStream f(path);
	mrpt::serialization::archiveFrom(f) << *mrpt::obs::CObservationOdometry::Create();
}

/** A rawlog of one odometry observation and one 4x4 image of grey `value`, not committed unless `commit`. */
void writeImageLog(const std::string& rawlog, int value, bool commit = true, bool force = false)
{
	RawlogWriter w(rawlog, "omnirange-test", force);
	w.externalImage(cv::Mat(4, 4, CV_8UC3, cv::Scalar(value, value, value)), "0.png");
	w.write(*mrpt::obs::CObservationOdometry::Create());
	if (commit) w.commit();
}
}  // namespace

TEST(Output, AFileIsReplacedOnlyByAnOutputOfItsKind)
{
	const std::string d = fresh("kind");
	put(d + "/notes.hist", "my notes");
	EXPECT_REFUSED(requireOutputAllowed(d + "/notes.hist", OutputKind::Histogram, "omnirange-train", {}),
				   "exists and is not a colour model");
	put(d + "/old.hist", "OMNIHIST and the rest");
	EXPECT_NO_THROW(requireOutputAllowed(d + "/old.hist", OutputKind::Histogram, "omnirange-train", {}));
	EXPECT_NO_THROW(requireOutputAllowed(d + "/notes.hist", OutputKind::Histogram, "omnirange-train", {}, true));
	// A text output its program begins one way: a user's text of another beginning is not its.
	put(d + "/summary.csv", "my,own,table\n");
	EXPECT_REFUSED(requireOutputsAllowed({{d + "/summary.csv", OutputKind::Text, "name,group"}}, "omnirange-summary", {}),
				   "is not what omnirange-summary writes there");
	{
		mrpt::io::CFileGZOutputStream g(d + "/backup.gz");
		g.Write("a tar file, say", 15);
	}
	EXPECT_REFUSED(requireOutputAllowed(d + "/backup.gz", OutputKind::Rawlog, "omnirange-scan", {}), "is not a rawlog");
	writeRawlog(d + "/log.rawlog");
	EXPECT_NO_THROW(requireOutputAllowed(d + "/log.rawlog", OutputKind::Rawlog, "omnirange-scan", {}));
}

TEST(Output, NoOutputIsHoldsOrSitsInAnInputEvenWithForce)
{
	const std::string d = fresh("inputs");
	put(d + "/in.ini", "[rangefinder]\nN = 20\n");
	EXPECT_REFUSED(requireOutputAllowed(d + "/in.ini", OutputKind::Ini, "p", {d + "/in.ini"}, true), "is the input");
	fs::create_symlink("in.ini", d + "/link.ini");
	EXPECT_REFUSED(requireOutputAllowed(d + "/link.ini", OutputKind::Ini, "p", {d + "/in.ini"}, true), "is the input");
	fs::create_hard_link(d + "/in.ini", d + "/hard.ini");
	EXPECT_REFUSED(requireOutputAllowed(d + "/hard.ini", OutputKind::Ini, "p", {d + "/in.ini"}, true), "is the input");
	EXPECT_REFUSED(requireOutputAllowed(d, OutputKind::Folder, "p", {d + "/in.ini"}, true), "holds the input");
	fs::create_directories(d + "/data");
	EXPECT_REFUSED(requireOutputAllowed(d + "/data/x.hist", OutputKind::Histogram, "p", {d + "/data"}, true), "is inside the input");
	// What an input brings: an ini's base, a rawlog's images.
	put(d + "/top.ini", "base = in.ini\n[rangefinder]\nK = 2\n");
	EXPECT_REFUSED(requireOutputAllowed(d + "/in.ini", OutputKind::Ini, "p", {d + "/top.ini"}, true), "is the input");
	writeRawlog(d + "/log.rawlog");
	fs::create_directories(d + "/log_Images");
	EXPECT_REFUSED(requireOutputAllowed(d + "/log_Images/x.png", OutputKind::Image, "p", {d + "/log.rawlog"}, true),
				   "is inside the input");
	// Two outputs of one run in one place.
	EXPECT_REFUSED(requireOutputsAllowed({{d + "/a.md", OutputKind::Text}, {d + "/./a.md", OutputKind::Text}}, "p", {}),
				   "are in the same place");
}

TEST(Output, AFolderIsReplacedOnlyByTheProgramThatWroteItAndOnlyWhole)
{
	const std::string d = fresh("folder"), out = d + "/report";
	commitFolder(out, "omnirange-experiment", {{"a.md", "first"}, {"b.md", "first"}});
	const auto marker = markerLines(out);
	ASSERT_EQ(marker.size(), 3u);
	EXPECT_EQ(marker[0], "omnirange-experiment");
	// The same program again: the new folder in whole, nothing of the old one left.
	commitFolder(out, "omnirange-experiment", {{"a.md", "second"}});
	EXPECT_EQ(read(out + "/a.md"), "second");
	EXPECT_FALSE(fs::exists(out + "/b.md"));
	EXPECT_EQ(stagingIn(d), 0);
	// Another program's, or one a user added to, is refused.
	EXPECT_REFUSED(requireOutputAllowed(out, OutputKind::Folder, "omnirange-slam", {}), "what omnirange-experiment wrote");
	put(out + "/mine.txt", "keep me");
	EXPECT_REFUSED(requireOutputAllowed(out, OutputKind::Folder, "omnirange-experiment", {}), "is not something");
	// A user's folder: refused, and with --force kept under one name.
	fs::create_directories(d + "/user");
	put(d + "/user/notes.txt", "mine");
	EXPECT_REFUSED(requireOutputAllowed(d + "/user", OutputKind::Folder, "omnirange-slam", {}), "did not write");
	commitFolder(d + "/user", "omnirange-slam", {{"path.txt", "0 0 0"}}, true);
	EXPECT_EQ(read(d + "/user.replaced/notes.txt"), "mine");
	EXPECT_EQ(read(d + "/user/path.txt"), "0 0 0");
	// An empty folder is nobody's work.
	fs::create_directories(d + "/empty");
	EXPECT_NO_THROW(requireOutputAllowed(d + "/empty", OutputKind::Folder, "omnirange-slam", {}));
}

TEST(Output, AFailedWriteReplacesNothingAndLeavesNothing)
{
	const std::string d = fresh("failed");
	put(d + "/a.csv", "old a"), put(d + "/b.csv", "old b");
	EXPECT_THROW(
		{
			OutputSet set;
			set.write({d + "/a.csv", OutputKind::Text}, "new a");
			set.write({d + "/b.csv", OutputKind::Text}, [](const std::string&) { throw std::runtime_error("disk full"); });
			set.commit();
		},
		std::runtime_error);
	EXPECT_EQ(read(d + "/a.csv"), "old a");
	EXPECT_EQ(read(d + "/b.csv"), "old b");
	EXPECT_EQ(stagingIn(d), 0);
}

TEST(Output, TheFilesOfASetGoInTogetherOrNotAtAll)
{
	const std::string d = fresh("set");
	put(d + "/s.csv", "name,group\nold\n"), put(d + "/s.md", "# old");
	commitFiles({{d + "/s.csv", "name,group\nnew\n"}, {d + "/s.md", "# new"}}, "omnirange-summary");
	EXPECT_EQ(read(d + "/s.csv"), "name,group\nnew\n");
	EXPECT_EQ(read(d + "/s.md"), "# new");
	// One of them made into a user's file of another kind while the run went: the commit checks again, neither goes in.
	{
		OutputSet set("omnirange-accuracy");
		set.write({d + "/s.csv", OutputKind::Text}, "name,group\nthird\n");
		set.write({d + "/s.png", OutputKind::Image}, "\x89PNG...");
		put(d + "/s.png", "a user's notes");
		EXPECT_REFUSED(set.commit(), "is not an image");
	}
	EXPECT_EQ(read(d + "/s.csv"), "name,group\nnew\n");
	EXPECT_EQ(read(d + "/s.png"), "a user's notes");
	EXPECT_EQ(stagingIn(d), 0);
}

TEST(Output, AKilledRunLeavesTheOldOutputAndTheNextRunRemovesWhatItLeft)
{
	const std::string d = fresh("killed");
	put(d + "/a.csv", "old a"), put(d + "/b.csv", "old b");
	const pid_t run = ::fork();
	if (run == 0)
	{
		auto* set = new OutputSet;  // never destroyed: the process ends as a killed one does
		set->write({d + "/a.csv", OutputKind::Text}, "new a");
		set->write({d + "/b.csv", OutputKind::Text}, "new b");
		::_exit(0);
	}
	int status = 0;
	::waitpid(run, &status, 0);
	EXPECT_EQ(read(d + "/a.csv"), "old a");
	EXPECT_EQ(read(d + "/b.csv"), "old b");
	EXPECT_EQ(stagingIn(d), 1);
	writeFileAtomically(d + "/c.csv", "c");
	EXPECT_EQ(stagingIn(d), 0);
	EXPECT_EQ(read(d + "/a.csv"), "old a");
}

TEST(Output, ALiveRunsStagingIsLeftAlone)
{
	const std::string d = fresh("live");
	int ready[2], done[2];
	ASSERT_EQ(::pipe(ready), 0);
	ASSERT_EQ(::pipe(done), 0);
	const pid_t run = ::fork();
	if (run == 0)
	{
		{
			OutputSet set;
			set.write({d + "/a.csv", OutputKind::Text}, "theirs");
			char c = 1;
			(void)!::write(ready[1], &c, 1);
			(void)!::read(done[0], &c, 1);  // until the other run is over
			set.commit();
		}
		::_exit(0);
	}
	char c = 0;
	ASSERT_EQ(::read(ready[0], &c, 1), 1);
	writeFileAtomically(d + "/b.csv", "mine");
	EXPECT_EQ(stagingIn(d), 1);  // the live run's, not removed
	(void)!::write(done[1], &c, 1);
	int status = 0;
	::waitpid(run, &status, 0);
	EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
	EXPECT_EQ(read(d + "/a.csv"), "theirs");
	EXPECT_EQ(read(d + "/b.csv"), "mine");
	EXPECT_EQ(stagingIn(d), 0);
}

namespace
{
/** In a fresh folder `name`, what a run killed after its list and its first
 * moves leaves: the list, report/ exchanged, a.csv moved in, b.csv staged. */
std::string halfCommitted(const std::string& name)
{
	const std::string d = fresh(name), staging = d + "/.omnirange-Killed";
	put(d + "/a.csv", "old a"), put(d + "/b.csv", "old b");
	fs::create_directories(d + "/report"), put(d + "/report/x.md", "old report");
	fs::create_directories(staging + "/report");
	put(staging + "/report/x.md", "new report");
	put(staging + "/a.csv", "new a"), put(staging + "/b.csv", "new b");
	const auto ino = [](const std::string& p) {
		struct stat st{};
		::lstat(p.c_str(), &st);
		return std::to_string(st.st_ino);
	};
	// The list a commit writes before its moves: each entry's inode and what it replaces, as checked.
	std::string list;
	for (const std::string name : {"report", "a.csv", "b.csv"})
		list += ino(staging + "/" + name) + " " + fileStateOf(d + "/" + name) + " " + name + "\n";
	put(staging + "/.omnirange-commit", list);
	fs::rename(staging + "/report", d + "/report.tmp"), fs::rename(d + "/report", staging + "/report"),
		fs::rename(d + "/report.tmp", d + "/report");  // the folder exchanged
	fs::rename(staging + "/a.csv", d + "/a.csv");  // a.csv moved; killed before b.csv
	return d;
}
}  // namespace

TEST(Output, ARunKilledInTheMiddleOfItsCommitIsFinishedByTheNextRun)
{
	const std::string d = halfCommitted("half_committed");
	writeFileAtomically(d + "/other.txt", "another run beside them");
	EXPECT_EQ(read(d + "/report/x.md"), "new report");
	EXPECT_EQ(read(d + "/a.csv"), "new a");
	EXPECT_EQ(read(d + "/b.csv"), "new b");
	EXPECT_EQ(stagingIn(d), 0);
}

TEST(Output, AKilledCommitIsNotFinishedOverAFileChangedSince)
{
	// Killed before b.csv went in; the user edits b.csv, then any run beside it: the edit stays.
	const std::string d = halfCommitted("half_then_edited");
	put(d + "/b.csv", "the user's b");
	writeFileAtomically(d + "/other.txt", "another run beside them");
	EXPECT_EQ(read(d + "/b.csv"), "the user's b");
	EXPECT_EQ(read(d + "/a.csv"), "new a");
	EXPECT_EQ(stagingIn(d), 0);
}

TEST(Output, ARunReadingAHalfCommittedSetFinishesItBeforeReading)
{
	// From another folder: the reader's own outputs go elsewhere, its input is the killed run's b.csv.
	const std::string d = halfCommitted("half_read"), elsewhere = fresh("half_read_out");
	ASSERT_EQ(read(d + "/b.csv"), "old b");
	requireOutputAllowed(elsewhere + "/out.csv", OutputKind::Text, "p", {d + "/b.csv"});
	EXPECT_EQ(read(d + "/b.csv"), "new b");
	EXPECT_EQ(read(d + "/report/x.md"), "new report");
	EXPECT_EQ(stagingIn(d), 0);
}

TEST(Output, AnUpdateOfAFileChangedSinceItWasReadReplacesNothing)
{
	const std::string d = fresh("update"), ini = d + "/my.ini";
	put(ini, "[rangefinder]\nN = 20\n");
	const std::string state = fileStateOf(ini);
	put(ini, "[rangefinder]\nN = 20\nK = 3\n");  // a user's editor, meanwhile
	OutputSet set;
	set.write({ini, OutputKind::Ini}, "[rangefinder]\nN = 10\n");
	set.requireUnchanged(ini, state);
	EXPECT_THROW(set.commit(), ChangedMeanwhile);
	EXPECT_EQ(read(ini), "[rangefinder]\nN = 20\nK = 3\n");
}

TEST(Output, ALinkToAFileIsWrittenThroughAndKeepsTheFilesMode)
{
	const std::string d = fresh("link");
	put(d + "/real.ini", "[a]\n");
	fs::permissions(d + "/real.ini", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
	fs::create_symlink("real.ini", d + "/link.ini");
	writeFileAtomically(d + "/link.ini", "[b]\n");
	EXPECT_TRUE(fs::is_symlink(d + "/link.ini"));
	EXPECT_EQ(read(d + "/real.ini"), "[b]\n");
	EXPECT_EQ(fs::status(d + "/real.ini").permissions() & fs::perms::all,
			  fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(Output, ALinkToAFolderIsWrittenThroughWhenItLeadsToTheProgramsOwn)
{
	const std::string d = fresh("folder_link");
	commitFolder(d + "/run1", "p", {{"a.csv", "old"}});
	fs::create_symlink("run1", d + "/latest");
	commitFolder(d + "/latest", "p", {{"a.csv", "new"}});
	EXPECT_TRUE(fs::is_symlink(d + "/latest"));
	EXPECT_EQ(read(d + "/run1/a.csv"), "new");
	// A link to a user's folder is theirs, as the folder is.
	fs::create_directories(d + "/mine"), put(d + "/mine/notes.txt", "mine");
	fs::create_symlink("mine", d + "/to_mine");
	EXPECT_REFUSED(requireOutputAllowed(d + "/to_mine", OutputKind::Folder, "p", {}), "did not write");
}

TEST(Output, AnUpdateReplacedByAnEditorBeforeItsMoveIsExchangedBack)
{
	// The editor saves by rename after the run read the file: the update's move finds another file there.
	const std::string d = fresh("update_race"), ini = d + "/my.ini";
	put(ini, "[a]\n");
	const std::string state = fileStateOf(ini);
	put(d + "/saved.ini", "[edited]\n"), fs::rename(d + "/saved.ini", ini);
	OutputSet set;
	set.write({ini, OutputKind::Ini}, "[ours]\n");
	set.write({d + "/other.csv", OutputKind::Text}, "x");
	set.requireUnchanged(ini, state);
	EXPECT_THROW(set.commit(), ChangedMeanwhile);
	EXPECT_EQ(read(ini), "[edited]\n");
	EXPECT_FALSE(fs::exists(d + "/other.csv"));  // nothing of the set went in
}

TEST(Output, NamesNoRunCanKeepItsPromiseForAreRefused)
{
	const std::string d = fresh("names");
	EXPECT_REFUSED(requireOutputAllowed(d + "/a\nb.csv", OutputKind::Text, "p", {}), "control character");
	EXPECT_REFUSED(requireOutputAllowed(d + "/.omnirange-abcdef", OutputKind::Text, "p", {}), "staging folders");
	EXPECT_REFUSED(requireOutputAllowed(d + "/x.csv/", OutputKind::Text, "p", {}), "names a folder");
	// Before any work, not at the commit: the folder an output goes in must be one.
	EXPECT_REFUSED(requireOutputAllowed(d + "/nodir/x.csv", OutputKind::Text, "p", {}), "does not exist (make it first)");
	put(d + "/plain", "a file");
	EXPECT_REFUSED(requireOutputAllowed(d + "/plain/x.csv", OutputKind::Text, "p", {}), "is not a folder");
	EXPECT_REFUSED(requireOutputAllowed(d + "/" + std::string(256, 'n'), OutputKind::Text, "p", {}), "(File name too long)");
	EXPECT_NO_THROW(requireOutputAllowed(d + "/" + std::string(255, 'n'), OutputKind::Text, "p", {}));
	fs::create_symlink("nowhere.csv", d + "/dangling.csv");
	EXPECT_REFUSED(requireOutputAllowed(d + "/dangling.csv", OutputKind::Text, "p", {}), "which does not exist");
	put(d + "/ro.csv", "kept");
	fs::permissions(d + "/ro.csv", fs::perms::owner_read);
	EXPECT_REFUSED(requireOutputAllowed(d + "/ro.csv", OutputKind::Text, "p", {}, true), "read-only");
	fs::create_directories(d + "/dir.csv");
	EXPECT_REFUSED(requireOutputAllowed(d + "/dir.csv", OutputKind::Text, "p", {}, true), "is not a file");
	EXPECT_REFUSED(writeFileAtomically(d + "/no_such_folder/x.csv", "x"), "'" + d + "/no_such_folder' of the output");
	put(d + "/file_not_folder", "x");
	EXPECT_REFUSED(requireOutputAllowed(d + "/file_not_folder", OutputKind::Folder, "p", {}), "is a file");
}

TEST(Output, ARawlogAndItsImagesGoInTogetherAndAFailedOneLeavesTheOldOnes)
{
	const std::string d = fresh("rawlog"), log = d + "/log.rawlog";
	writeImageLog(log, 10);
	const std::string rawlog_before = read(log), image_before = read(d + "/log_Images/0.png");
	EXPECT_EQ(markerLines(d + "/log_Images").front(), "omnirange-test");
	writeImageLog(log, 200, false);  // destroyed uncommitted: a failed run
	EXPECT_EQ(read(log), rawlog_before);
	EXPECT_EQ(read(d + "/log_Images/0.png"), image_before);
	EXPECT_EQ(stagingIn(d), 0);
	writeImageLog(log, 200);
	EXPECT_NE(read(d + "/log_Images/0.png"), image_before);
	EXPECT_EQ(stagingIn(d), 0);
}

TEST(Output, ARawlogIsNamedSoThatMrptFindsItsImagesAndNoOtherRawlogReadsThem)
{
	const std::string d = fresh("rawlog_names");
	EXPECT_REFUSED(requireRawlogOutputAllowed(d + "/log.rlog", "omnirange-scan", {}, false), "is not named NAME.rawlog");
	writeImageLog(d + "/log.rawlog.gz", 10);
	EXPECT_REFUSED(requireRawlogOutputAllowed(d + "/log.rawlog", "omnirange-test", {}, false), "reads '");
	// --force replaces what is there, not what another rawlog would then read.
	EXPECT_REFUSED(requireRawlogOutputAllowed(d + "/log.rawlog", "omnirange-test", {}, true), "reads '");
	// A user's folder at NAME_Images is theirs.
	fs::create_directories(d + "/mine_Images"), put(d + "/mine_Images/photo.jpg", "\xff\xd8\xff");
	EXPECT_REFUSED(requireRawlogOutputAllowed(d + "/mine.rawlog", "omnirange-scan", {}, false), "did not write");
}
