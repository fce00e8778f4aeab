// The one output rule: an output replaces only what the same program wrote
// before, never an input or a folder or file of anyone else's (unless
// --force, and then never an input); a multi-file output commits all or
// nothing, and what a killed run left is cleared by the next.
#include <omnirange/config/AtomicWrite.h>
#include <omnirange/io/ImageFile.h>
#include <omnirange/io/OutputRule.h>
#include <omnirange/io/RawlogProcessor.h>
#include <omnirange/io/RawlogReader.h>
#include <omnirange/io/RawlogScan.h>
#include <omnirange/io/RawlogWriter.h>

#include "../common/FactorySample.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/core.hpp>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <fcntl.h>
#include <linux/fs.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace omnirange;
namespace fs = std::filesystem;

namespace
{
std::string fresh(const std::string& name) { return test::freshDir("omnirange_output_rule", name); }

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }
/** A rawlog of one odometry observation: a rawlog by its content, as the rule judges one. */
void writeRawlog(const std::string& path)
{
	mrpt::io::CFileGZOutputStream f(path);
	mrpt::serialization::archiveFrom(f) << *mrpt::obs::CObservationOdometry::Create();
}

std::string read(const std::string& path) { return test::readText(path); }

/** A rawlog of one 4x4 image of grey `value` in its images folder; `with_images` as RawlogWriter::commit() has it. */
void writeOneImageLog(const std::string& rawlog, int value, const std::function<void()>& with_images = {})
{
	RawlogWriter w(rawlog, "omnirange-test");
	w.externalImage(cv::Mat(4, 4, CV_8UC3, cv::Scalar(value, value, value)), "0.png");
	w.write(mrpt::obs::CObservationOdometry());
	w.commit({}, with_images);
}
/** The inode of `path`, as a set's journal records a new file's. */
unsigned long inodeNumber(const std::string& path)
{
	struct stat st{};
	return ::lstat(path.c_str(), &st) == 0 ? static_cast<unsigned long>(st.st_ino) : 0;
}

/** The error requireOutputAllowed() throws, or "" when it allows the output. */
std::string refusal(const std::string& out, OutputKind kind, const std::vector<std::string>& inputs = {}, bool force = false)
{
	try
	{
		requireOutputAllowed(out, kind, "omnirange-test", inputs, force);
		return "";
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
}
}  // namespace

TEST(OutputRule, AFolderIsReplacedOnlyWhenEmptyOrMarkedByTheSameProgram)
{
	const std::string d = fresh("folders");
	EXPECT_EQ(refusal(d + "/absent", OutputKind::Folder), "");
	fs::create_directory(d + "/empty");
	EXPECT_EQ(refusal(d + "/empty", OutputKind::Folder), "");
	fs::create_directory(d + "/users");
	write(d + "/users/notes.txt", "mine");
	EXPECT_NE(refusal(d + "/users", OutputKind::Folder).find("did not write"), std::string::npos);
	EXPECT_NE(refusal(d + "/users/", OutputKind::Folder).find("did not write"), std::string::npos);  // as tab completion writes it
	EXPECT_EQ(refusal(d + "/users", OutputKind::Folder, {}, true), "");  // --force
	fs::create_directory(d + "/ours");
	markOutputFolder(d + "/ours", "omnirange-test");
	write(d + "/ours/report.md", "old");
	// A marker that lists no file (an older version's, or cut short) vouches for none.
	EXPECT_NE(refusal(d + "/ours", OutputKind::Folder).find("report.md"), std::string::npos);
	listOutputFolder(d + "/ours");
	EXPECT_EQ(refusal(d + "/ours", OutputKind::Folder), "");
	fs::create_directory(d + "/other");
	markOutputFolder(d + "/other", "omnirange-other");
	write(d + "/other/x", "x");
	// Another program's: said whose, and no advice to remove it.
	EXPECT_NE(refusal(d + "/other", OutputKind::Folder).find("is what omnirange-other wrote, not omnirange-test"), std::string::npos)
		<< refusal(d + "/other", OutputKind::Folder);
	EXPECT_EQ(refusal(d + "/other", OutputKind::Folder).find("remove"), std::string::npos);
	write(d + "/a-file", "text");
	EXPECT_NE(refusal(d + "/a-file", OutputKind::Folder).find("is a file"), std::string::npos);
	EXPECT_NE(refusal(d + "/a-file", OutputKind::Folder, {}, true).find("is a file"), std::string::npos);
}

TEST(OutputRule, AFileIsReplacedOnlyByAnOutputOfItsKind)
{
	const std::string d = fresh("files");
	write(d + "/notes.txt", "my notes\n");
	writeRawlog(d + "/old.rawlog");
	write(d + "/floor.hist", "OMNIHIST....");
	write(d + "/my.ini", "; mine\n[rangefinder]\nN = 3\n");
	EXPECT_EQ(refusal(d + "/old.rawlog", OutputKind::Rawlog), "");
	EXPECT_NE(refusal(d + "/notes.txt", OutputKind::Rawlog).find("is not a rawlog"), std::string::npos);
	EXPECT_NE(refusal(d + "/floor.hist", OutputKind::Ini).find("is not an ini file"), std::string::npos);
	EXPECT_NE(refusal(d + "/old.rawlog", OutputKind::Ini), "");
	EXPECT_EQ(refusal(d + "/my.ini", OutputKind::Ini), "");
	EXPECT_EQ(refusal(d + "/floor.hist", OutputKind::Histogram), "");
	EXPECT_NE(refusal(d + "/my.ini", OutputKind::Histogram), "");
	EXPECT_EQ(refusal(d + "/notes.txt", OutputKind::Rawlog, {}, true), "");  // --force
}

TEST(OutputRule, NoOutputIsHoldsOrSitsInAnInputEvenWithForce)
{
	const std::string d = fresh("inputs");
	fs::create_directories(d + "/data/images");
	write(d + "/data/images/1.jpg", "jpg");
	write(d + "/data/log.csv", "1,2");
	fs::create_directory_symlink(d + "/data", d + "/link");
	for (const bool force : {false, true})
	{
		EXPECT_NE(refusal(d + "/data/log.csv", OutputKind::Text, {d + "/data/log.csv"}, force).find("is the input"),
				  std::string::npos);
		EXPECT_NE(refusal(d + "/data", OutputKind::Folder, {d + "/data/images/1.jpg"}, force).find("holds the input"),
				  std::string::npos);
		EXPECT_NE(refusal(d + "/data/images/out.rawlog", OutputKind::Rawlog, {d + "/data/images"}, force)
					  .find("is inside the input"),
				  std::string::npos);
		// Through a link to the input's folder.
		EXPECT_NE(refusal(d + "/link/log.csv", OutputKind::Text, {d + "/data/log.csv"}, force), "");
	}
	EXPECT_EQ(refusal(d + "/elsewhere.rawlog", OutputKind::Rawlog, {d + "/data/log.csv", d + "/data/images"}), "");
	// "data/../x" is beside data, not in it; through the link "link/../x" is beside what it names, not in it either.
	write(d + "/beside.csv", "1,2");
	EXPECT_EQ(refusal(d + "/data", OutputKind::Folder, {d + "/data/../beside.csv"}, true), "");
	EXPECT_EQ(refusal(d + "/link", OutputKind::Folder, {d + "/link/../beside.csv"}, true), "");
	EXPECT_NE(refusal(d + "/link", OutputKind::Folder, {d + "/link/images/../log.csv"}, true), "");
}

TEST(OutputRule, AFolderReachedByAnotherPathIsKnownByWhatItIsNotByItsName)
{
	// A bind mount: the same folder under two paths that no link resolves into each other.
	const std::string d = fresh("bound");
	fs::create_directories(d + "/work/ini"), fs::create_directories(d + "/bound");
	write(d + "/work/ini/run.ini", "[experiment]\n");
	if (::mount((d + "/work").c_str(), (d + "/bound").c_str(), nullptr, MS_BIND, nullptr) != 0)
		GTEST_SKIP() << "cannot bind-mount a folder here (needs CAP_SYS_ADMIN)";
	const std::string holds = refusal(d + "/bound/ini", OutputKind::Folder, {d + "/work/ini/run.ini"}, true);
	const std::string inside = refusal(d + "/bound/ini/report", OutputKind::Folder, {d + "/work/ini"}, true);
	const std::string beside = refusal(d + "/bound/report", OutputKind::Folder, {d + "/work/ini/run.ini"}, true);
	::umount((d + "/bound").c_str());
	EXPECT_NE(holds.find("holds the input"), std::string::npos) << holds;
	EXPECT_NE(inside.find("is inside the input"), std::string::npos) << inside;
	EXPECT_EQ(beside, "");
}

TEST(OutputRule, WhatAnInputBringsIsAnInputToo)
{
	const std::string d = fresh("brought");
	// An ini's base, down the chain.
	write(d + "/b2.ini", "[rangefinder]\nthreshold = 0.1\n");
	write(d + "/b.ini", "base = b2.ini\n[rangefinder]\nN = 10\n");
	write(d + "/cam.ini", "; mine\nbase = b.ini\n[rangefinder]\nK = 4\n");
	EXPECT_NE(refusal(d + "/b.ini", OutputKind::Ini, {d + "/cam.ini"}, true).find("is the input"), std::string::npos);
	EXPECT_NE(refusal(d + "/b2.ini", OutputKind::Ini, {d + "/cam.ini"}, true).find("is the input"), std::string::npos);
	// A rawlog's images folder, even as a link named like it.
	writeRawlog(d + "/s.rawlog");
	fs::create_directory(d + "/elsewhere");
	write(d + "/elsewhere/1.jpg", "jpg");
	fs::create_directory_symlink(d + "/elsewhere", d + "/s_Images");
	EXPECT_NE(refusal(d + "/s_Images", OutputKind::Folder, {d + "/s.rawlog"}, true), "");
	EXPECT_NE(refusal(d + "/s_Images/acc_pairs.csv", OutputKind::Text, {d + "/s.rawlog"}, true), "");
	// A hard link to an input is the input.
	fs::create_hard_link(d + "/s.rawlog", d + "/hard.rawlog");
	EXPECT_NE(refusal(d + "/hard.rawlog", OutputKind::Rawlog, {d + "/s.rawlog"}, true).find("is the input"),
			  std::string::npos);
	EXPECT_EQ(refusal(d + "/other.ini", OutputKind::Ini, {d + "/cam.ini", d + "/s.rawlog"}), "");
}

TEST(OutputRule, ALinkedFolderAReadOnlyFileAndTwoOutputsInOnePlaceAreRefused)
{
	const std::string d = fresh("refused");
	fs::create_directory(d + "/mine");
	write(d + "/mine/notes.txt", "mine");
	fs::create_directory_symlink(d + "/mine", d + "/report");
	EXPECT_NE(refusal(d + "/report", OutputKind::Folder, {}).find("symbolic link"), std::string::npos);
	EXPECT_EQ(refusal(d + "/report", OutputKind::Folder, {}, true), "");  // --force replaces the link only
	writeRawlog(d + "/locked.rawlog");
	fs::permissions(d + "/locked.rawlog", fs::perms::owner_read);
	EXPECT_NE(refusal(d + "/locked.rawlog", OutputKind::Rawlog, {}, true).find("read-only"), std::string::npos);
	try
	{
		requireOutputsAllowed({{d + "/same.ini", OutputKind::Ini}, {d + "/./same.ini", OutputKind::Text}}, "omnirange-test", {});
		ADD_FAILURE() << "two outputs in one place";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("in the same place"), std::string::npos) << e.what();
	}
	EXPECT_NO_THROW(requireOutputsAllowed({{d + "/a.ini", OutputKind::Ini}, {d + "/b.csv", OutputKind::Text}, {"", OutputKind::Text}},
										  "omnirange-test", {}));

	// A rawlog's images folder may be the link a scan made to its input's images: a second scan replaces it.
	fs::create_directory(d + "/in_Images");
	writeRawlog(d + "/in.rawlog");
	fs::create_directory_symlink(d + "/in_Images", d + "/out_Images");
	EXPECT_THROW(requireRawlogOutputAllowed(d + "/out.rawlog", "omnirange-scan", {d + "/in.rawlog"}, false), std::runtime_error);  // no rawlog of ours beside it: the user's link
	writeRawlog(d + "/out.rawlog");
	EXPECT_NO_THROW(requireRawlogOutputAllowed(d + "/out.rawlog", "omnirange-scan", {d + "/in.rawlog"}, false));
	// Only a scan makes such links: another program does not replace one unasked.
	EXPECT_THROW(requireRawlogOutputAllowed(d + "/out.rawlog", "omnirange-sim", {d + "/in.rawlog"}, false), std::runtime_error);
	// An output reached through a link and '..' is where the system takes it, not where the text says.
	fs::create_directories(d + "/data/images");
	fs::create_directory_symlink(d + "/data/images", d + "/imgs");
	write(d + "/data/cam.ini", "[rangefinder]\nN = 10\n");
	EXPECT_NE(refusal(d + "/imgs/../cam.ini", OutputKind::Ini, {d + "/data/cam.ini"}, true).find("is the input"),
			  std::string::npos);
	// A leftover marked by another program is not this one's to put back.
	fs::create_directory(d + "/rep.old-999991");
	markOutputFolder(d + "/rep.old-999991", "omnirange-other");
	recoverLeftoversOf(d + "/rep", OutputKind::Folder, "omnirange-test");
	EXPECT_FALSE(fs::exists(d + "/rep"));
	EXPECT_TRUE(fs::exists(d + "/rep.old-999991"));
}

TEST(OutputRule, AFolderIsReplacedAllOrNothingAndAKilledRunsLeftoversAreCleared)
{
	const std::string d = fresh("replace");
	fs::create_directory(d + "/report");
	write(d + "/report/old.md", "old");
	write(d + "/report/" + kOutputMarker, "omnirange-test\nrun 7\nfile old.md\n");
	fs::create_directory(d + "/report.staging-1");
	write(d + "/report.staging-1/new.md", "new");
	replaceFolder(d + "/report", d + "/report.staging-1", false);
	EXPECT_EQ(read(d + "/report/new.md"), "new");
	EXPECT_FALSE(fs::exists(d + "/report/old.md"));
	EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);  // nothing aside is left
	// A rename that fails (nothing to move) leaves the old folder where it was.
	EXPECT_THROW(replaceFolder(d + "/report", d + "/nothing", false), std::runtime_error);
	EXPECT_EQ(read(d + "/report/new.md"), "new");

	// A user's backups named as an old copy would be: a copy of the report (its marker too, but no
	// run moved it aside), and the report itself moved aside by hand. Neither is removed or put back.
	markOutputFolder(d + "/report", "omnirange-test");
	fs::copy(d + "/report", d + "/report.old-2024", fs::copy_options::recursive);
	fs::rename(d + "/report", d + "/report.old-1999");
	recoverLeftoversOf(d + "/report", OutputKind::Folder, "omnirange-test");
	EXPECT_FALSE(fs::exists(d + "/report"));
	EXPECT_EQ(read(d + "/report.old-2024/new.md"), "new");
	EXPECT_EQ(read(d + "/report.old-1999/new.md"), "new");
	fs::rename(d + "/report.old-1999", d + "/report");
	fs::remove_all(d + "/report.old-2024");

	// A run killed between its two renames: the old copy aside, no output. Process 999999 is not running;
	// it noted in the marker that it moved the folder aside, as moveAside() does.
	write(d + "/report/" + kOutputMarker, "omnirange-test\naside 999999\n");
	fs::rename(d + "/report", d + "/report.old-999999");
	fs::create_directory(d + "/report.staging-999998");
	write(d + "/report.staging-999998/" + kOutputMarker, "omnirange-test\nrun 999998\n");  // as markOutputFolder() in that run
	// Names a killed run could have left, but not ours (no marker; a file beside a folder output;
	// a copy of a report whose marker names another run): kept.
	write(d + "/.report.tmp-999997", "a user's notes");
	fs::create_directory(d + "/report.staging-999996");
	write(d + "/report.staging-999996/notes.txt", "a user's notes");
	fs::create_directory(d + "/report.old-999995");
	write(d + "/report.old-999995/notes.txt", "a user's notes");
	fs::copy(d + "/report.staging-999998", d + "/report.staging-2024", fs::copy_options::recursive);
	// Empty, its marker gone (a run killed removing it): nothing in it is anyone's.
	fs::create_directory(d + "/report.old-999994");
	recoverLeftoversOf(d + "/report");
	EXPECT_FALSE(fs::exists(d + "/report.old-999994"));
	EXPECT_EQ(read(d + "/report/new.md"), "new");  // put back
	EXPECT_FALSE(fs::exists(d + "/report.old-999999"));
	EXPECT_FALSE(fs::exists(d + "/report.staging-999998"));
	EXPECT_EQ(read(d + "/.report.tmp-999997"), "a user's notes");
	EXPECT_TRUE(fs::exists(d + "/report.staging-999996"));
	EXPECT_TRUE(fs::exists(d + "/report.staging-2024"));
	EXPECT_TRUE(fs::exists(d + "/report.old-999995"));
	// A listed leftover of ours that a user has added a file to since: theirs now, kept whole.
	fs::create_directory(d + "/report.old-999990");
	write(d + "/report.old-999990/" + kOutputMarker, "omnirange-test\naside 999990\n");
	write(d + "/report.old-999990/map.png", "ours");
	listOutputFolder(d + "/report.old-999990");
	write(d + "/report.old-999990/notes.txt", "a user's notes");
	// Kept under a name no run takes (in a container, the next run's own .old-1 would be in the way), and said.
	const auto keptAs = [](const std::string& said) {
		const auto at = said.find("kept '") + 6;
		return said.substr(at, said.find('\'', at) - at);
	};
	testing::internal::CaptureStderr();
	recoverLeftoversOf(d + "/report");
	const std::string kept = keptAs(testing::internal::GetCapturedStderr());
	EXPECT_EQ(kept.rfind(d + "/report.replaced-", 0), 0u) << kept;
	EXPECT_EQ(read(kept + "/notes.txt"), "a user's notes");
	EXPECT_EQ(read(kept + "/map.png"), "ours");
	EXPECT_FALSE(fs::exists(d + "/report.old-999990"));
	// One a run was killed removing, a folder its listed files were in emptied: all its own still, removed.
	fs::create_directories(d + "/report.old-999988/icp_slam");
	write(d + "/report.old-999988/" + kOutputMarker, "omnirange-test\naside 999988\n");
	write(d + "/report.old-999988/icp_slam/map.simplemap", "ours");
	listOutputFolder(d + "/report.old-999988");
	fs::remove(d + "/report.old-999988/icp_slam/map.simplemap");
	EXPECT_EQ(firstUnlistedIn(d + "/report.old-999988"), "");
	recoverLeftoversOf(d + "/report");
	EXPECT_FALSE(fs::exists(d + "/report.old-999988"));
	// A killed run's staging folder: what it listed as it wrote is removed with it; with a
	// file it did not list (a user's, added since), the whole folder is kept.
	for (const bool added : {false, true})
	{
		const std::string staging = d + "/report.staging-999989";
		fs::create_directory(staging);
		write(staging + "/" + kOutputMarker, "omnirange-test\nrun 999989\n");
		listOutputFile(staging, "img_0001.jpg");
		write(staging + "/img_0001.jpg", "ours");
		if (added) write(staging + "/NOTES.txt", "a user's notes");
		testing::internal::CaptureStderr();
		recoverLeftoversOf(d + "/report", OutputKind::Folder, "omnirange-test");
		const std::string said = testing::internal::GetCapturedStderr();
		EXPECT_FALSE(fs::exists(staging));
		// What is kept is said, naming the file that keeps it.
		EXPECT_EQ(said.find("warning: kept '") != std::string::npos && said.find("NOTES.txt") != std::string::npos, added)
			<< said;
		if (added)
		{
			EXPECT_EQ(read(keptAs(said) + "/NOTES.txt"), "a user's notes");
			fs::remove_all(keptAs(said));
		}
	}
	// Killed before it listed its files (an experiment during its simulation): what it wrote by then is
	// its hidden temporaries and folders its marker names; with anything else in it, it is kept and said.
	for (const bool added : {false, true})
	{
		const std::string staging = d + "/report.staging-999988";
		fs::create_directories(staging + "/dataset/.log_Images.tmp-999988");
		write(staging + "/" + kOutputMarker, "omnirange-test\nrun 999988\n");
		write(staging + "/dataset/.log_Images.tmp-999988/" + kOutputMarker, "omnirange-test\nrun 999988\nfile 0.jpg\n");
		write(staging + "/dataset/.log_Images.tmp-999988/0.jpg", "ours");
		write(staging + "/dataset/.log.rawlog.tmp-999988", "ours");
		write(staging + "/dataset/" + (added ? "notes.txt" : ".log_truemap.png.tmp-999988"), "either");
		testing::internal::CaptureStderr();
		recoverLeftoversOf(d + "/report", OutputKind::Folder, "omnirange-test");
		const std::string said = testing::internal::GetCapturedStderr();
		EXPECT_FALSE(fs::exists(staging));
		EXPECT_EQ(said.find("dataset/notes.txt") != std::string::npos, added) << said;
		if (added)
		{
			EXPECT_EQ(read(keptAs(said) + "/dataset/notes.txt"), "either") << "a user's file was removed";
			fs::remove_all(keptAs(said));
		}
	}
	// A path through a folder that is not there: the system could not write it, though it reads as "d".
	EXPECT_NE(refusal(d + "/missing/..", OutputKind::Folder).find("passes through"), std::string::npos);
	EXPECT_NE(refusal(d + "/missing/../x.rawlog", OutputKind::Rawlog).find("which is not a folder"), std::string::npos);

	// A file output's temporaries (hidden, temporaryOf()): an empty one (killed before it wrote) and
	// one of its kind are removed; another kind is a user's and stays, and so does a user's copy
	// named as a temporary would be if it were not hidden.
	write(d + "/.x.rawlog.tmp-999994", "");
	writeRawlog(d + "/.x.rawlog.tmp-999993");
	write(d + "/.x.rawlog.tmp-999992", "a user's text");
	writeRawlog(d + "/x.rawlog.tmp-2023");
	writeRawlog(d + "/x.rawlog.staging-2023");
	writeRawlog(d + "/x.rawlog.old-2023");
	recoverLeftoversOf(d + "/x.rawlog", OutputKind::Rawlog);
	EXPECT_TRUE(fs::exists(d + "/x.rawlog.staging-2023"));
	EXPECT_TRUE(fs::exists(d + "/x.rawlog.old-2023"));
	EXPECT_FALSE(fs::exists(d + "/.x.rawlog.tmp-999994"));
	EXPECT_FALSE(fs::exists(d + "/.x.rawlog.tmp-999993"));
	EXPECT_TRUE(fs::exists(d + "/.x.rawlog.tmp-999992"));
	EXPECT_TRUE(fs::exists(d + "/x.rawlog.tmp-2023"));
	EXPECT_EQ(temporaryOf(d + "/x.rawlog").rfind(d + "/.x.rawlog.tmp-", 0), 0u);
	// A temporary's own temporary (a journal or a staged file written whole itself): the same run's PID twice.
	write(d + "/..x.rawlog.tmp-999994.tmp-999994", "");
	write(d + "/..x.rawlog.commit-999994.tmp-999994", "run 999994 1\n");
	write(d + "/..x.rawlog.commit-999994.tmp-2023", "a user's text");
	recoverLeftoversOf(d + "/x.rawlog", OutputKind::Rawlog);
	EXPECT_FALSE(fs::exists(d + "/..x.rawlog.tmp-999994.tmp-999994"));
	EXPECT_FALSE(fs::exists(d + "/..x.rawlog.commit-999994.tmp-999994"));
	EXPECT_TRUE(fs::exists(d + "/..x.rawlog.commit-999994.tmp-2023"));
	// A run killed a moment ago, not yet reaped by its parent (a zombie), is gone too.
	const pid_t zombie = ::fork();
	if (zombie == 0) ::_exit(0);
	for (int i = 0; i < 200 && test::readText("/proc/" + std::to_string(zombie) + "/stat").find(") Z") == std::string::npos; ++i)
		::usleep(10000);
	write(d + "/.x.rawlog.tmp-" + std::to_string(zombie), "");
	recoverLeftoversOf(d + "/x.rawlog", OutputKind::Rawlog);
	EXPECT_FALSE(fs::exists(d + "/.x.rawlog.tmp-" + std::to_string(zombie)));
	::waitpid(zombie, nullptr, 0);
	// One with this run's PID is an earlier run's that had it (a container's PID 1): this run has made nothing yet.
	write(d + "/.x.rawlog.tmp-" + std::to_string(::getpid()), "");
	recoverLeftoversOf(d + "/x.rawlog", OutputKind::Rawlog);
	EXPECT_FALSE(fs::exists(d + "/.x.rawlog.tmp-" + std::to_string(::getpid())));
	// A user's gzip file (a .tar.gz backup) is gzip but no rawlog: a leftover's
	// name does not make it one, and a rawlog output does not replace it.
	const auto gzipOf = [](const std::string& path) {
		mrpt::io::CFileGZOutputStream f(path);
		f.Write("ustar backup", 12);
	};
	gzipOf(d + "/.x.rawlog.tmp-999991"), gzipOf(d + "/backup.tar.gz");
	recoverLeftoversOf(d + "/x.rawlog", OutputKind::Rawlog);
	EXPECT_TRUE(fs::exists(d + "/.x.rawlog.tmp-999991"));
	EXPECT_THROW(requireRawlogOutputAllowed(d + "/backup.tar.gz", "omnirange-scan", {}, false), std::runtime_error);
}

TEST(OutputRule, WhatHasTheNameOfThisRunsTemporaryIsTheUsersAndIsNeitherEmptiedNorReplaced)
{
	// Every run in a container of its own is PID 1: a name with this run's PID is no proof that it made it.
	const std::string d = fresh("taken_names"), pid = std::to_string(::getpid());
	// An output of such a name would read as a killed run's leftover to the next run.
	for (const std::string& name : std::vector<std::string>{"report.staging-1", ".f.hist.tmp-" + pid, ".f.hist.old-7", ".f.hist.commit-7"})
		EXPECT_NE(refusal(d + "/" + name, OutputKind::Folder).find("the form runs give their temporaries"),
				  std::string::npos)
			<< name;
	for (const std::string name : {"f.old-7", "report.staging-", "report.staging-1a", "f.tmp-7"})
		EXPECT_EQ(refusal(d + "/" + name, OutputKind::Folder), "") << name;

	// The user's folder where this run would stage its report.
	fs::create_directories(d + "/report.staging-" + pid);
	write(d + "/report.staging-" + pid + "/notes.txt", "the user's");
	EXPECT_THROW(StagedFolder(d + "/report", "omnirange-test", {}, false), std::runtime_error);
	EXPECT_EQ(read(d + "/report.staging-" + pid + "/notes.txt"), "the user's");

	// The user's backup where this run would move the old images aside: refused, and the images' marker unchanged.
	writeOneImageLog(d + "/log.rawlog", 1);
	const std::string marker = read(d + "/log_Images/" + kOutputMarker);
	fs::create_directory(d + "/log_Images.old-" + pid);
	write(d + "/log_Images.old-" + pid + "/mine.txt", "the user's");
	EXPECT_THROW(writeOneImageLog(d + "/log.rawlog", 2), std::runtime_error);
	EXPECT_EQ(read(d + "/log_Images.old-" + pid + "/mine.txt"), "the user's");
	EXPECT_EQ(read(d + "/log_Images/" + kOutputMarker), marker);
	EXPECT_EQ(cv::imread(d + "/log_Images/0.png").at<cv::Vec3b>(0, 0)[0], 1);

	// The user's folder where this run would write new images: refused, its file kept.
	fs::create_directory(d + "/.other_Images.tmp-" + pid);
	write(d + "/.other_Images.tmp-" + pid + "/mine.txt", "the user's");
	EXPECT_THROW(writeOneImageLog(d + "/other.rawlog", 3), std::runtime_error);
	EXPECT_EQ(read(d + "/.other_Images.tmp-" + pid + "/mine.txt"), "the user's");
	EXPECT_FALSE(fs::exists(d + "/other.rawlog"));

	// The user's file where a set would put its old file aside: the set does not go in, nothing is replaced.
	write(d + "/a.txt", "old a"), write(d + "/.a.txt.old-" + pid, "the user's");
	{
		StagedFile a(d + "/a.txt", [](const std::string& tmp) { write(tmp, "new a"); });
		EXPECT_THROW(commitAll({&a}), std::runtime_error);
	}
	EXPECT_EQ(read(d + "/a.txt"), "old a");
	EXPECT_EQ(read(d + "/.a.txt.old-" + pid), "the user's");

	// The user's file where this run would write its temporary (not of the output's kind, so no leftover):
	// refused before anything is written, for a rawlog and for any other file.
	write(d + "/.third.rawlog.tmp-" + pid, "the user's notes");
	EXPECT_THROW(writeOneImageLog(d + "/third.rawlog", 4), std::runtime_error);
	EXPECT_EQ(read(d + "/.third.rawlog.tmp-" + pid), "the user's notes");
	EXPECT_FALSE(fs::exists(d + "/third.rawlog"));
	write(d + "/.b.txt.tmp-" + pid, "the user's notes");
	EXPECT_THROW(writeFileAtomically(d + "/b.txt", "new b"), std::runtime_error);
	EXPECT_EQ(read(d + "/.b.txt.tmp-" + pid), "the user's notes");
	EXPECT_FALSE(fs::exists(d + "/b.txt"));
	// A text output is known by how it begins: any text is of its kind. A leftover cut short within that goes.
	write(d + "/.t.md.tmp-" + pid, "the user's notes");
	EXPECT_NO_THROW(requireOutputAllowed(d + "/t.md", OutputKind::Text, "omnirange-test", {}, false, "# Table\n"));
	EXPECT_EQ(read(d + "/.t.md.tmp-" + pid), "the user's notes");
	write(d + "/.u.md.tmp-" + pid, "# Ta");
	EXPECT_NO_THROW(requireOutputAllowed(d + "/u.md", OutputKind::Text, "omnirange-test", {}, false, "# Table\n"));
	EXPECT_FALSE(fs::exists(d + "/.u.md.tmp-" + pid));
}

TEST(OutputRule, AFolderPutInTheOutputsPlaceWhileItIsReplacedIsKeptNotRemoved)
{
	const std::string d = fresh("swapped_in"), pid = std::to_string(::getpid());
	const auto output = [&](const std::string& name) {
		fs::create_directories(d + "/" + name);
		write(d + "/" + name + "/0.png", "ours");
		write(d + "/" + name + "/" + kOutputMarker, "omnirange-test\nrun 7\nfile 0.png\n");
		return d + "/" + name;
	};
	// The output as checked is moved aside, but a user's folder stands at its old name by the time it is removed.
	MovedAside a = moveAside(output("a"), false);
	ASSERT_TRUE(a.noted);
	fs::remove_all(a.path);
	fs::create_directories(a.path);
	write(a.path + "/notes.txt", "the user's");
	testing::internal::CaptureStderr();
	removeReplaced(a);
	EXPECT_NE(testing::internal::GetCapturedStderr().find("kept"), std::string::npos);
	EXPECT_EQ(read(d + "/a.replaced-" + pid + "/notes.txt"), "the user's");
	// A file added to the output's folder after it was checked is kept with it.
	MovedAside b = moveAside(output("b"), false);
	write(b.path + "/notes.txt", "the user's");
	testing::internal::CaptureStderr();
	removeReplaced(b);
	EXPECT_NE(testing::internal::GetCapturedStderr().find("'notes.txt', which the output did not list"), std::string::npos);
	EXPECT_EQ(read(d + "/b.replaced-" + pid + "/notes.txt"), "the user's");
	// What is wholly the output's goes, without a word.
	MovedAside c = moveAside(output("c"), false);
	testing::internal::CaptureStderr();
	removeReplaced(c);
	EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
	EXPECT_FALSE(fs::exists(c.path));
	// A folder with no marker (one put in the place of the output after it was checked) is not marked as moved aside,
	// nor moved aside (without --force) once it holds anything.
	fs::create_directories(d + "/user");
	EXPECT_THROW(noteInMarker(d + "/user", "aside " + pid, false), std::runtime_error);
	EXPECT_FALSE(fs::exists(d + "/user/" + kOutputMarker));
	write(d + "/user/notes.txt", "the user's");
	EXPECT_THROW(moveAside(d + "/user", false), std::runtime_error);
	EXPECT_EQ(read(d + "/user/notes.txt"), "the user's");
	// Empty when the run looked, filled by the time it is removed: kept.
	fs::create_directories(d + "/empty");
	MovedAside e = moveAside(d + "/empty", false);
	write(e.path + "/notes.txt", "the user's");
	testing::internal::CaptureStderr();
	removeReplaced(e);
	EXPECT_NE(testing::internal::GetCapturedStderr().find("was empty when the run looked"), std::string::npos);
	EXPECT_EQ(read(d + "/empty.replaced-" + pid + "/notes.txt"), "the user's");
	// A folder made while a staged output was being written is not replaced by it.
	StagedFolder late(d + "/late", "omnirange-test", {}, false);
	fs::create_directories(d + "/late");
	write(d + "/late/notes.txt", "the user's");
	EXPECT_THROW(late.commit(), std::runtime_error);
	EXPECT_EQ(read(d + "/late/notes.txt"), "the user's");
}

TEST(OutputRule, AFolderMadeAtTheOutputsNameAsItGoesInGetsNoMarkerAndTheOldOutputIsKept)
{
	const std::string d = fresh("made_at_commit"), pid = std::to_string(::getpid());
	writeOneImageLog(d + "/x.rawlog", 1);
	// The new images are in and the rawlog about to be: the user moves them away and makes a folder of that name.
	const auto userFolder = [&] {
		fs::rename(d + "/x_Images", d + "/x_Images.moved");
		fs::create_directory(d + "/x_Images");
		write(d + "/x_Images/notes.txt", "the user's");
	};
	EXPECT_THROW(writeOneImageLog(d + "/x.rawlog", 2, userFolder), std::runtime_error);
	EXPECT_EQ(read(d + "/x_Images/notes.txt"), "the user's");
	EXPECT_FALSE(fs::exists(d + "/x_Images/" + kOutputMarker));
	// The old images a run moved aside, beside a folder of the user's at the output's name: kept, and said.
	fs::create_directories(d + "/S.old-999999");
	write(d + "/S.old-999999/a.md", "the old output");
	write(d + "/S.old-999999/" + kOutputMarker, "omnirange-test\nrun 5\nfile a.md\naside 999999\n");
	fs::create_directories(d + "/S");
	write(d + "/S/notes.txt", "the user's");
	testing::internal::CaptureStderr();
	recoverLeftoversOf(d + "/S", OutputKind::Folder, "omnirange-test");
	EXPECT_NE(testing::internal::GetCapturedStderr().find("is not this program's output"), std::string::npos);
	EXPECT_EQ(read(d + "/S.old-999999/a.md"), "the old output");
	EXPECT_EQ(read(d + "/S/notes.txt"), "the user's");
}

TEST(OutputRule, FoldersForceReplacesAreKeptEachUnderANameOfItsOwnAndAMarkersTemporaryIsNoObstacle)
{
	// In a container every run is PID 1: the second folder kept must not meet the first.
	const std::string d = fresh("kept_twice"), pid = std::to_string(::getpid());
	const auto forced = [&](int value) {
		RawlogWriter w(d + "/x.rawlog", "omnirange-test");
		w.replaceAnyImagesFolder();
		w.externalImage(cv::Mat(4, 4, CV_8UC3, cv::Scalar(value, value, value)), "0.png");
		w.write(mrpt::obs::CObservationOdometry());
		w.commit();
	};
	for (int i = 1; i <= 2; ++i)
	{
		fs::remove_all(d + "/x_Images");
		fs::create_directories(d + "/x_Images");
		write(d + "/x_Images/notes.txt", "the user's " + std::to_string(i));
		testing::internal::CaptureStderr();
		forced(i);
		EXPECT_NE(testing::internal::GetCapturedStderr().find("replaced with --force"), std::string::npos);
	}
	EXPECT_EQ(read(d + "/x_Images.replaced-" + pid + "/notes.txt"), "the user's 1");
	EXPECT_EQ(read(d + "/x_Images.replaced-" + pid + "-2/notes.txt"), "the user's 2");
	// A run killed rewriting the output's marker left the marker's temporary in it: the next run goes on.
	write(d + "/x_Images/." + std::string(kOutputMarker) + ".tmp-" + pid, "omnirange-te");
	EXPECT_NO_THROW(writeOneImageLog(d + "/x.rawlog", 3));
	EXPECT_EQ(cv::imread(d + "/x_Images/0.png").at<cv::Vec3b>(0, 0)[0], 3);
}

TEST(OutputRule, AFolderItsRunWasKilledMarkingIsRemovedAndOneWithAnythingElseIsKept)
{
	// Killed between making its staging folder and writing the marker's lines: an empty marker, no file
	// (as PID 1, in a container, every later run would find its staging name taken). Process 999999 is not running.
	const std::string d = fresh("killed_marking"), pid = std::to_string(::getpid());
	for (const std::string& run : {std::string("999999"), pid})
	{
		fs::create_directories(d + "/report.staging-" + run);
		write(d + "/report.staging-" + run + "/" + kOutputMarker, "");
	}
	fs::create_directories(d + "/.out_Images.tmp-999999");
	write(d + "/.out_Images.tmp-999999/" + kOutputMarker, "omnirange-te");
	// A marker cut short beside a file: the file may be anyone's.
	fs::create_directories(d + "/other.staging-999999");
	write(d + "/other.staging-999999/" + kOutputMarker, "");
	write(d + "/other.staging-999999/notes.txt", "the user's");
	recoverLeftoversOf(d + "/report", OutputKind::Folder, "omnirange-test");
	recoverLeftoversOf(d + "/out_Images", OutputKind::Folder, "omnirange-test");
	recoverLeftoversOf(d + "/other", OutputKind::Folder, "omnirange-test");
	EXPECT_FALSE(fs::exists(d + "/report.staging-999999"));
	EXPECT_FALSE(fs::exists(d + "/report.staging-" + pid));
	EXPECT_FALSE(fs::exists(d + "/.out_Images.tmp-999999"));
	EXPECT_EQ(read(d + "/other.staging-999999/notes.txt"), "the user's");
	EXPECT_NO_THROW(StagedFolder(d + "/report", "omnirange-test", {}, false));
}

TEST(OutputRule, AFolderItsRunWasKilledFillingIsRemovedWholeAndOneItFinishedIsListed)
{
	// An experiment killed while icp-slam writes into its staging folder: files no list names, all the run's.
	const std::string d = fresh("killed_filling");
	const pid_t run = ::fork();
	if (run == 0)
	{
		StagedFolder staged(d + "/report", "omnirange-test", {}, false);
		fillListed(staged.path(), [&] {
			fs::create_directory(staged.path() + "/icp_slam");
			write(staged.path() + "/icp_slam/_finalmap.png", "MRPT's");
			::raise(SIGKILL);
		});
		::_exit(0);
	}
	int status = 0;
	::waitpid(run, &status, 0);
	ASSERT_TRUE(WIFSIGNALED(status)) << status;
	const std::string staging = d + "/report.staging-" + std::to_string(run);
	ASSERT_TRUE(fs::exists(staging + "/icp_slam/_finalmap.png"));
	testing::internal::CaptureStderr();
	recoverLeftoversOf(d + "/report", OutputKind::Folder, "omnirange-test");
	EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
	EXPECT_FALSE(fs::exists(staging));
	// A fill that ends, also in an error, lists what it wrote: a file added later is told apart.
	const std::string kept = fresh("filled") + "/out";
	fs::create_directory(kept);
	markOutputFolder(kept, "omnirange-test");
	EXPECT_THROW(fillListed(kept, [&] {
		write(kept + "/stage.log", "ours");
		throw std::runtime_error("a stage failed");
	}),
				 std::runtime_error);
	EXPECT_EQ(firstUnlistedIn(kept), "");
	write(kept + "/notes.txt", "a user's");
	EXPECT_EQ(firstUnlistedIn(kept), "notes.txt");
	// A staged folder output (omnirange-slam's) is filled so too: killed in it, its staging folder is all its own.
	const std::string slam = fresh("staged_fill") + "/S";
	StagedFolder staged(slam, "omnirange-test", {}, false);
	staged.fill([&] {
		write(staged.path() + "/_finalmap_.simplemap", "ours");
		EXPECT_NE(read(staged.path() + "/" + kOutputMarker).find("\nfilling\n"), std::string::npos);
	});
	EXPECT_EQ(read(staged.path() + "/" + kOutputMarker).find("\nfilling\n"), std::string::npos);
	EXPECT_EQ(firstUnlistedIn(staged.path()), "");
}

TEST(OutputRule, AFolderOutputNamedDotIsTheFolderItself)
{
	// `-o .` in a folder made for the report: staged beside it and put in its place, not moved aside as '.'.
	const std::string d = fresh("dot_output");
	fs::create_directory(d + "/report");
	const fs::path back = fs::current_path();
	for (const std::string& given : {std::string("."), std::string("./")})
	{
		fs::current_path(d + "/report");  // the one put in place by the last pass
		StagedFolder staged(given, "omnirange-test", {}, false);
		EXPECT_EQ(staged.target(), fs::canonical(d + "/report").string());
		EXPECT_EQ(staged.path(), staged.target() + ".staging-" + std::to_string(::getpid()));
		write(staged.path() + "/summary.md", "new");
		staged.commit();
	}
	fs::current_path(back);
	EXPECT_EQ(read(d + "/report/summary.md"), "new");
	fs::create_directory(d + "/report/sub");
	fs::current_path(d + "/report/sub");
	StagedFolder up("..", "omnirange-test", {}, true);
	EXPECT_EQ(up.target(), fs::canonical(d + "/report").string());
	fs::current_path(back);
}

TEST(OutputRule, ANameWithALineBreakIsRefusedBeforeAMarkerOrJournalCouldListIt)
{
	// A marker lists a file a line: "x\nfile notes.txt" would make the user's notes.txt the run's own.
	const std::string d = fresh("line_break");
	const std::string said = refusal(d + "/x\nfile notes.txt", OutputKind::Rawlog);
	EXPECT_NE(said.find("has a control character"), std::string::npos) << said;
	EXPECT_EQ(said.find('\n'), std::string::npos) << "one line";
	EXPECT_NE(refusal(d + "/tab\there.hist", OutputKind::Histogram).find("control character"), std::string::npos);
	fs::create_directory(d + "/out");
	markOutputFolder(d + "/out", "omnirange-test");
	listOutputFile(d + "/out", "img0.jpg");
	EXPECT_THROW(listOutputFile(d + "/out", "img.jpg\nfile notes.txt"), std::runtime_error);  // an input's image so named
	write(d + "/out/img0.jpg", "ours");
	EXPECT_EQ(firstUnlistedIn(d + "/out"), "");
	write(d + "/out/notes.txt", "a user's");
	EXPECT_EQ(firstUnlistedIn(d + "/out"), "notes.txt");
}

TEST(OutputRule, AnInterruptDuringACommitEndsTheRunOnlyAfterItsRenames)
{
	// Ctrl-C while a commit moves files: the commit ends whole, then the run ends as the interrupt says.
	const std::string d = fresh("interrupt_in_commit");
	const pid_t run = ::fork();
	if (run == 0)
	{
		temporaries::removeOnInterrupt();
		{
			const FolderLock commit(d + "/a.txt");
			::kill(::getpid(), SIGINT);
			::usleep(300000);  // the commit's renames
			write(d + "/a.txt", "whole");
		}
		::sleep(5);  // the interrupt ends the run here
		::_exit(0);
	}
	int status = 0;
	::waitpid(run, &status, 0);
	EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
	EXPECT_EQ(read(d + "/a.txt"), "whole");
}

TEST(OutputRule, ACommitWaitingLongForAnotherRunsSaysSo)
{
	// A run stopped (Ctrl+Z) while it puts its output in place holds the folder: another run waits, visibly.
	const std::string d = fresh("long_wait");
	{
		testing::internal::CaptureStderr();
		const FolderLock free_folder(d + "/a.txt");
		EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
	}
	const pid_t other = ::fork();
	if (other == 0)
	{
		const int fd = ::open(d.c_str(), O_RDONLY | O_DIRECTORY);
		::flock(fd, LOCK_EX);
		write(d + "/held", "");
		::sleep(3);
		::_exit(0);
	}
	while (!fs::exists(d + "/held")) ::usleep(10000);
	testing::internal::CaptureStderr();
	{
		const FolderLock commit(d + "/b.txt");  // its turn comes when the other ends
	}
	const std::string said = testing::internal::GetCapturedStderr();
	EXPECT_NE(said.find("waiting for another run, which is putting its output into '"), std::string::npos) << said;
	int status = 0;
	::waitpid(other, &status, 0);
}

TEST(OutputRule, SetsOverTheSameFoldersLockThemInOneOrderHoweverTheyAreNamed)
{
	// Folder A named through a link Z: a set over Z and B takes A first, as a set over A and B does.
	const std::string d = fresh("lock_order");
	fs::create_directory(d + "/A"), fs::create_directory(d + "/B");
	fs::create_directory_symlink("A", d + "/Z");
	const int a = ::open((d + "/A").c_str(), O_RDONLY | O_DIRECTORY);
	ASSERT_EQ(::flock(a, LOCK_EX), 0);  // another run's set, holding A and about to take B
	const pid_t run = ::fork();
	if (run == 0)
	{
		::close(a);  // the parent's lock, which a copy of its descriptor would hold on for this run too
		StagedFile y(d + "/Z/y.txt", [](const std::string& tmp) { std::ofstream(tmp) << "y"; });
		StagedFile m(d + "/B/m.txt", [](const std::string& tmp) { std::ofstream(tmp) << "m"; });
		commitAll({&y, &m});
		::_exit(0);
	}
	::sleep(1);
	const int b = ::open((d + "/B").c_str(), O_RDONLY | O_DIRECTORY);
	EXPECT_EQ(::flock(b, LOCK_EX | LOCK_NB), 0) << "B taken before A: each run would wait for the other";
	::close(b), ::close(a);
	int status = 0;
	::waitpid(run, &status, 0);
	EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
	EXPECT_EQ(read(d + "/A/y.txt"), "y");
	EXPECT_EQ(read(d + "/B/m.txt"), "m");
}

TEST(OutputRule, AWorkingFolderPastPathMaxIsNoReasonToRefuse)
{
	// There no path resolves (realpath fails): compared as written, an output elsewhere is not "inside" an input.
	const std::string d = fresh("path_max");
	const fs::path back = fs::current_path();
	fs::current_path(d);
	const std::string level(200, 'l');
	for (int i = 0; i < 22; ++i) fs::create_directory(level), fs::current_path(level);
	writeRawlog("in.rawlog");
	EXPECT_EQ(refusal(d + "/out.rawlog", OutputKind::Rawlog, {"in.rawlog"}), "");
	EXPECT_NE(refusal("in.rawlog", OutputKind::Rawlog, {"in.rawlog"}), "");
	fs::remove("in.rawlog");
	// Two new outputs are two places; a report's listed file there is still the report's.
	EXPECT_NO_THROW(requireOutputsAllowed({{"a.csv", OutputKind::Text}, {"b.csv", OutputKind::Text}}, "omnirange-test", {}));
	fs::create_directory("R");
	write("R/" + std::string(kOutputMarker), "omnirange-experiment\nrun 999984\nfile floor.hist\n");
	EXPECT_THROW(requireNotAnothersPart("R/floor.hist", "omnirange-train"), std::runtime_error);
	fs::remove_all("R");
	for (int i = 0; i < 22; ++i) fs::current_path(".."), fs::remove(level);  // no path reaches them whole
	fs::current_path(back);
}

TEST(OutputRule, AFileIsWrittenThroughItsLinkKeepsItsModeAndAReadOnlyOneIsKept)
{
	const std::string d = fresh("links");
	write(d + "/real.ini", "old");
	fs::permissions(d + "/real.ini", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
	fs::create_symlink(d + "/real.ini", d + "/link.ini");
	writeFileAtomically(d + "/link.ini", "new");
	EXPECT_TRUE(fs::is_symlink(d + "/link.ini"));
	EXPECT_EQ(read(d + "/real.ini"), "new");
	EXPECT_EQ(fs::status(d + "/real.ini").permissions(),
			  fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
	write(d + "/locked.ini", "keep");
	fs::permissions(d + "/locked.ini", fs::perms::owner_read);
	EXPECT_THROW(writeFileAtomically(d + "/locked.ini", "lost"), std::runtime_error);
	EXPECT_EQ(read(d + "/locked.ini"), "keep");
}

TEST(OutputRule, ARawlogWriterReplacesOnlyImagesFoldersItMade)
{
	const std::string d = fresh("writer");
	const auto writeOne = [&](bool force) {
		RawlogWriter w(d + "/log.rawlog", "omnirange-test");
		if (force) w.replaceAnyImagesFolder();
		w.externalImage(cv::Mat(4, 4, CV_8UC3, cv::Scalar(1, 2, 3)), "0.png");
		w.write(mrpt::obs::CObservationOdometry());
		w.commit();
	};
	fs::create_directory(d + "/log_Images");
	write(d + "/log_Images/photo.jpg", "the user's");
	EXPECT_THROW(writeOne(false), std::runtime_error);
	EXPECT_EQ(read(d + "/log_Images/photo.jpg"), "the user's");
	EXPECT_FALSE(fs::exists(d + "/log.rawlog"));
	testing::internal::CaptureStderr();
	writeOne(true);  // --force: replaced, and the user's folder kept beside it, said
	EXPECT_NE(testing::internal::GetCapturedStderr().find("replaced with --force"), std::string::npos);
	EXPECT_TRUE(fs::exists(d + "/log_Images/0.png"));
	EXPECT_TRUE(isOutputFolderOf(d + "/log_Images", "omnirange-test"));
	const std::string kept = d + "/log_Images.replaced-" + std::to_string(::getpid());
	EXPECT_EQ(read(kept + "/photo.jpg"), "the user's");
	fs::remove_all(kept);
	writeOne(false);  // now ours: replaced again without asking
	EXPECT_TRUE(fs::exists(d + "/log.rawlog"));
	EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 2);  // no .old or .tmp left

	// log.rawlog.gz would read the same log_Images: while log.rawlog is there, its images are not taken over.
	const auto writeGz = [&] {
		RawlogWriter w(d + "/log.rawlog.gz", "omnirange-test");
		w.externalImage(cv::Mat(4, 4, CV_8UC3, cv::Scalar(9, 9, 9)), "0.png");
		w.write(mrpt::obs::CObservationOdometry());
		w.commit();
	};
	// (A program's output is named NAME.rawlog, the one name MRPT's programs and these read the same images of.)
	try
	{
		requireRawlogOutputAllowed(d + "/log.rawlog.gz", "omnirange-test", {}, false);
		ADD_FAILURE() << "an output MRPT's programs would read other images of was allowed";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("log.rawlog_Images"), std::string::npos) << e.what();
	}
	EXPECT_THROW(writeGz(), std::runtime_error);
	EXPECT_EQ(cv::imread(d + "/log_Images/0.png").at<cv::Vec3b>(0, 0), cv::Vec3b(1, 2, 3));
	// Renamed by hand to another name of the stem, it still reads them: not taken over either.
	fs::rename(d + "/log.rawlog", d + "/log");
	EXPECT_THROW(writeGz(), std::runtime_error);
	fs::remove(d + "/log");  // with their rawlog gone, the images are the new one's to replace
	writeGz();
	EXPECT_EQ(cv::imread(d + "/log_Images/0.png").at<cv::Vec3b>(0, 0), cv::Vec3b(9, 9, 9));
	// Their marker names log.rawlog.gz; a copy of the folder under another stem is that copy's.
	fs::copy(d + "/log_Images", d + "/copy_Images", fs::copy_options::recursive);
	EXPECT_NO_THROW(requireRawlogOutputAllowed(d + "/copy.rawlog", "omnirange-test", {}, false));
	// The marker's rawlog, there, of the same stem, holds them against another name.
	try
	{
		requireRawlogOutputAllowed(d + "/log.rawlog", "omnirange-test", {}, false);
		ADD_FAILURE() << "log.rawlog.gz's images were to be replaced";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("reads '" + d + "/log_Images' too"), std::string::npos) << e.what();
	}
}

TEST(OutputRule, ARawlogWhoseImagesARunWasKilledReplacingIsNotRead)
{
	const std::string d = fresh("half_replaced");
	{
		RawlogWriter w(d + "/log.rawlog", "omnirange-test");
		w.externalImage(cv::Mat(4, 4, CV_8UC3, cv::Scalar(1, 2, 3)), "0.png");
		w.write(mrpt::obs::CObservationOdometry());
		w.commit();
	}
	// A user's backup of the images beside them: no run moved it aside, the rawlog is read.
	fs::copy(d + "/log_Images", d + "/log_Images.old-2024", fs::copy_options::recursive);
	EXPECT_NO_THROW(RawlogReader(d + "/log.rawlog"));
	// Run 999988 moved the images aside and was killed before its new ones were in.
	write(d + "/log_Images/" + kOutputMarker, "omnirange-test\nrawlog log.rawlog\naside 999988\n");
	fs::rename(d + "/log_Images", d + "/log_Images.old-999988");
	try
	{
		RawlogReader reader(d + "/log.rawlog");
		ADD_FAILURE() << "a rawlog was read with images a killed run had half replaced";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("log_Images.old-999988"), std::string::npos) << e.what();
	}
	// ... or once its new ones were in, marked pending until its rawlog was in.
	fs::create_directory(d + "/log_Images");
	markOutputFolder(d + "/log_Images", "omnirange-test");
	noteInMarker(d + "/log_Images", "pending 999988");
	EXPECT_THROW(RawlogReader(d + "/log.rawlog"), std::runtime_error);
	// ... or after its rawlog was in and the mark taken off, before the old ones went: whole, and read.
	unnoteInMarker(d + "/log_Images", "pending 999988");
	forgetReadings();  // read as a new run would: this one read the folder before
	EXPECT_NO_THROW(RawlogReader(d + "/log.rawlog"));
	// A report that run 999987 moved aside, killed before its new one was in: a rawlog in it is named there.
	fs::create_directory(d + "/report.old-999987");
	write(d + "/report.old-999987/" + kOutputMarker, "omnirange-test\naside 999987\n");
	try
	{
		RawlogReader reader(d + "/report/scanned.rawlog");
		ADD_FAILURE() << "a missing rawlog was opened";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("report.old-999987"), std::string::npos) << e.what();
	}
}

TEST(OutputRule, WhatBelongsWithARawlogGoesInAfterItsImagesAndBeforeIt)
{
	// A simulation's true map: a run killed while it goes in must leave what readers refuse,
	// never a whole-looking rawlog beside another run's true map.
	const std::string d = fresh("with_images");
	const auto writeLog = [&](int value, const std::function<void()>& with_images = {}) {
		writeOneImageLog(d + "/log.rawlog", value, with_images);
	};
	writeLog(1, [&] { write(d + "/log_truemap.txt", "first"); });
	const std::string first_rawlog = read(d + "/log.rawlog");
	bool called = false;
	writeLog(2, [&] {
		called = true;
		// The state a kill here leaves: the new images in, the old rawlog, the old images aside.
		EXPECT_EQ(read(d + "/log.rawlog"), first_rawlog);
		EXPECT_EQ(cv::imread(d + "/log_Images/0.png").at<cv::Vec3b>(0, 0)[0], 2);
		EXPECT_TRUE(fs::exists(d + "/log_Images.old-" + std::to_string(::getpid())));
		// Every reader refuses it, whether this run is still going or was killed here.
		EXPECT_THROW(RawlogReader(d + "/log.rawlog"), std::runtime_error);
		write(d + "/log_truemap.txt", "second");
	});
	EXPECT_TRUE(called);
	EXPECT_NO_THROW(RawlogReader(d + "/log.rawlog"));
	// With no old images to move aside (a user removed them), the same: the new images are refused until their rawlog is in.
	fs::remove_all(d + "/log_Images");
	writeLog(4, [&] { EXPECT_THROW(RawlogReader(d + "/log.rawlog"), std::runtime_error); });
	EXPECT_NO_THROW(RawlogReader(d + "/log.rawlog"));
	EXPECT_EQ(read(d + "/log_truemap.txt"), "second");
	// One that fails: the old images come back and the rawlog is the old one.
	const std::string second_rawlog = read(d + "/log.rawlog");
	EXPECT_EQ(cv::imread(d + "/log_Images/0.png").at<cv::Vec3b>(0, 0)[0], 4);
	EXPECT_THROW(writeLog(3, [] { throw std::runtime_error("cannot put the true map in place"); }), std::runtime_error);
	EXPECT_EQ(read(d + "/log.rawlog"), second_rawlog);
	EXPECT_EQ(cv::imread(d + "/log_Images/0.png").at<cv::Vec3b>(0, 0)[0], 4);
	// Files that go along (a true map) come out again when the rawlog cannot go in (here its temporary is gone).
	write(d + "/log_truemap.txt", "before");
	{
		StagedFile map(d + "/log_truemap.txt", [](const std::string& tmp) { write(tmp, "after"); });
		RawlogWriter w(d + "/log.rawlog", "omnirange-test");
		w.externalImage(cv::Mat(4, 4, CV_8UC3, cv::Scalar(5, 5, 5)), "0.png");
		w.write(mrpt::obs::CObservationOdometry());
		EXPECT_THROW(w.commit({&map}, [&] { fs::remove(temporaryOf(d + "/log.rawlog")); }), std::runtime_error);
	}
	EXPECT_EQ(read(d + "/log_truemap.txt"), "before");
	EXPECT_EQ(cv::imread(d + "/log_Images/0.png").at<cv::Vec3b>(0, 0)[0], 4);
	// A scan's images are its input's files, each a hard link; an earlier scan's link to its input's is replaced.
	const auto scan = [&] {
		RawlogWriter w(d + "/scan.rawlog", kScanProgram);
		w.write(mrpt::obs::CObservationOdometry());
		EXPECT_EQ(w.shareImagesOf(d + "/log_Images"), 0u);  // none copied
		w.commit();
	};
	fs::create_directory_symlink("..", d + "/log_Images/up");  // a link that leads back up is not walked
	scan();
	EXPECT_FALSE(fs::exists(d + "/scan_Images/up"));
	fs::remove(d + "/log_Images/up");
	fs::remove_all(d + "/scan_Images");
	fs::create_directory_symlink("log_Images", d + "/scan_Images");
	scan();
	EXPECT_FALSE(fs::is_symlink(d + "/scan_Images"));
	EXPECT_TRUE(fs::equivalent(d + "/scan_Images/0.png", d + "/log_Images/0.png"));
	EXPECT_FALSE(fs::equivalent(d + "/scan_Images/" + kOutputMarker, d + "/log_Images/" + kOutputMarker));
	EXPECT_NO_THROW(RawlogReader(d + "/scan.rawlog"));
}

TEST(OutputRule, ARawlogWhoseImagesAreReplacedWhileItIsReadEndsInAnError)
{
	// A scan reading a dataset while a simulation writes it again: part of what it read is of other images.
	const std::string d = fresh("replaced_while_read");
	const auto writeLog = [&](int value, const std::function<void()>& with_images = {}) {
		writeOneImageLog(d + "/log.rawlog", value, with_images);
	};
	writeLog(1);
	{
		RawlogReader unchanged(d + "/log.rawlog");
		while (unchanged.next()) {}
	}
	RawlogReader reader(d + "/log.rawlog");
	writeLog(2);
	EXPECT_THROW(while (reader.next()) {}, std::runtime_error);
	// Images decoded after the end of the file (a scan's last batch) are checked again then.
	{
		RawlogReader late(d + "/log.rawlog");
		while (late.next()) {}
		writeLog(3);
		EXPECT_THROW(late.requireImagesUnchanged(), std::runtime_error);
	}
	// A scan's images stay those it was made from, whatever becomes of its input's.
	{
		RawlogWriter scan(d + "/scan.rawlog", kScanProgram);
		scan.write(mrpt::obs::CObservationOdometry());
		scan.shareImagesOf(d + "/log_Images");
		scan.commit();
	}
	writeLog(4);
	EXPECT_NO_THROW(RawlogReader(d + "/scan.rawlog"));
	EXPECT_EQ(cv::imread(d + "/scan_Images/0.png").at<cv::Vec3b>(0, 0)[0], 3);
	// A backup put back by hand over a newer run's rawlog, under any of its names, is not read with the
	// newer run's images; the newer rawlog itself, compressed otherwise or not at all, is.
	fs::copy_file(d + "/scan.rawlog", d + "/scan.bak");
	{
		RawlogWriter scan(d + "/scan.rawlog", kScanProgram);
		scan.write(mrpt::obs::CObservationOdometry()), scan.write(mrpt::obs::CObservationOdometry());
		scan.shareImagesOf(d + "/log_Images");
		scan.commit();
	}
	fs::copy_file(d + "/scan.rawlog", d + "/scan.new");
	fs::copy_file(d + "/scan.bak", d + "/scan.rawlog", fs::copy_options::overwrite_existing);
	EXPECT_THROW(RawlogReader(d + "/scan.rawlog"), std::runtime_error);
	fs::rename(d + "/scan.bak", d + "/scan.rawlog.gz");
	EXPECT_THROW(RawlogReader(d + "/scan.rawlog.gz"), std::runtime_error);
	fs::rename(d + "/scan.new", d + "/scan.rawlog.gz");
	EXPECT_NO_THROW(RawlogReader(d + "/scan.rawlog.gz"));
	{
		mrpt::io::CFileGZInputStream gz(d + "/scan.rawlog.gz");
		std::ofstream plain(d + "/scan", std::ios::binary);
		char buf[4096];
		for (std::size_t n; (n = gz.Read(buf, sizeof buf)) > 0;) plain.write(buf, static_cast<std::streamsize>(n));
	}
	EXPECT_NO_THROW(RawlogReader(d + "/scan"));
	// Paired through a link by hand: the same rawlog is read, another is not.
	fs::create_directory_symlink("scan_Images", d + "/paired_Images");
	fs::copy_file(d + "/scan", d + "/paired.rawlog");
	EXPECT_NO_THROW(RawlogReader(d + "/paired.rawlog"));
	fs::copy_file(d + "/log.rawlog", d + "/paired.rawlog", fs::copy_options::overwrite_existing);
	EXPECT_THROW(RawlogReader(d + "/paired.rawlog"), std::runtime_error);
	// On another file system they are copies.
	const std::string shm = "/dev/shm/omnirange_test_" + std::to_string(::getpid());
	struct stat here{}, there{};
	if (::stat("/dev/shm", &there) == 0 && ::stat(d.c_str(), &here) == 0 && here.st_dev != there.st_dev)
	{
		fs::remove_all(shm);
		fs::create_directory(shm);
		RawlogWriter scan(shm + "/scan.rawlog", kScanProgram);
		scan.write(mrpt::obs::CObservationOdometry());
		EXPECT_EQ(scan.shareImagesOf(d + "/log_Images"), 1u);
		scan.commit();
		EXPECT_EQ(cv::imread(shm + "/scan_Images/0.png").at<cv::Vec3b>(0, 0)[0], 4);
		fs::remove_all(shm);
	}
	// A rawlog read again by the same run (calibrate's passes) is the one it read first, or an error.
	{
		RawlogReader first(d + "/log.rawlog");
	}
	const std::string again = d + "/log_again.rawlog";
	fs::copy_file(d + "/log.rawlog", again);
	fs::create_directory_symlink("log_Images", d + "/log_again_Images");
	EXPECT_NO_THROW(RawlogReader{again});
	fs::copy_file(d + "/log.rawlog", again + ".new"), fs::rename(again + ".new", again);  // as a run puts one in
	EXPECT_THROW(RawlogReader{again}, std::runtime_error);
	// So is one that holds its images (no folder), and one reached through a link switched meanwhile.
	const std::string inside = d + "/inside.rawlog";
	writeRawlog(inside);
	EXPECT_NO_THROW(RawlogReader{inside});
	writeRawlog(inside + ".new"), fs::rename(inside + ".new", inside);
	EXPECT_THROW(RawlogReader{inside}, std::runtime_error);
	fs::create_symlink("log.rawlog", d + "/current.rawlog");
	EXPECT_NO_THROW(RawlogReader(d + "/current.rawlog"));
	fs::remove(d + "/current.rawlog"), fs::create_symlink("log_again.rawlog", d + "/current.rawlog");
	EXPECT_THROW(RawlogReader(d + "/current.rawlog"), std::runtime_error);
	// A reading stopped before the end of the file (train -n) is checked as it stops.
	RawlogProcessor stopped(d + "/log.rawlog");
	stopped.onObject([&](const mrpt::serialization::CSerializable::Ptr&) {
		writeLog(5);
		stopped.stop();
	});
	EXPECT_THROW(stopped.run(), std::runtime_error);
}

TEST(OutputRule, ACommitTheFolderRefusesHalfWaySaysWhereTheOldImagesAre)
{
	// The folder made immutable as the new images go in: neither the commit nor its undo can move them.
	const std::string d = fresh("immutable_mid_commit");
	const auto writeLog = [&](int value, const std::function<void()>& with_images = {}) {
		writeOneImageLog(d + "/log.rawlog", value, with_images);
	};
	writeLog(1, {});
	const int fd = ::open(d.c_str(), O_RDONLY | O_DIRECTORY);
	int flags = 0;
	ASSERT_EQ(::ioctl(fd, FS_IOC_GETFLAGS, &flags), 0);
	const auto immutable = [&](bool on) {
		int f = on ? (flags | FS_IMMUTABLE_FL) : flags;
		return ::ioctl(fd, FS_IOC_SETFLAGS, &f) == 0;
	};
	if (!immutable(true)) GTEST_SKIP() << "cannot make a folder immutable here (needs CAP_LINUX_IMMUTABLE)";
	immutable(false);
	std::string said;
	try
	{
		writeLog(2, [&] {
			immutable(true);
			throw std::runtime_error("the disk went away");
		});
	}
	catch (const std::runtime_error& e)
	{
		said = e.what();
	}
	immutable(false);
	::close(fd);
	const std::string old = d + "/log_Images.old-" + std::to_string(::getpid());
	EXPECT_NE(said.find("the old images could not be put back"), std::string::npos) << said;
	EXPECT_NE(said.find("'" + old + "'"), std::string::npos) << said;
	EXPECT_EQ(said.find("as they were"), std::string::npos) << said;
	EXPECT_EQ(cv::imread(old + "/0.png").at<cv::Vec3b>(0, 0)[0], 1);  // where it says
	fs::remove_all(old);
}

TEST(OutputRule, AnotherProgramsFolderAKilledRunMovedAsideIsStillNotOursToReplace)
{
	// A simulation killed between moving its images aside and putting the new ones in: an import onto its name would
	// replace the simulation's rawlog and leave its images aside.
	const std::string d = fresh("aside_by_other");
	writeRawlog(d + "/d.rawlog");
	fs::create_directory(d + "/d_Images.old-999987");
	write(d + "/d_Images.old-999987/" + kOutputMarker, "omnirange-sim\nrun 999986\naside 999987\n");
	const auto refused = [&](const std::string& program) {
		try
		{
			requireRawlogOutputAllowed(d + "/d.rawlog", program, {}, false);
			return std::string();
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
	};
	EXPECT_NE(refused("omnirange-import").find("leaving the old one in '" + d + "/d_Images.old-999987'"), std::string::npos)
		<< refused("omnirange-import");
	EXPECT_EQ(refused("omnirange-sim"), "");  // its own: the next simulation puts it back or replaces it
	EXPECT_NO_THROW(requireRawlogOutputAllowed(d + "/d.rawlog", "omnirange-import", {}, true));
}

TEST(OutputRule, AFileAnotherProgramsFolderListsIsNotReplacedByThisOne)
{
	// A report's histogram and dataset replaced by train or sim: its tables and figures would be of other data.
	const std::string d = fresh("part_of_report");
	fs::create_directories(d + "/rep/dataset");
	write(d + "/rep/" + kOutputMarker, "omnirange-experiment\nrun 999985\nfile floor.hist\nfile dataset/d.rawlog\n");
	write(d + "/rep/floor.hist", "");
	EXPECT_NE(refusal(d + "/rep/floor.hist", OutputKind::Histogram).find("is part of '" + d + "/rep', which omnirange-experiment wrote"),
			  std::string::npos)
		<< refusal(d + "/rep/floor.hist", OutputKind::Histogram);
	EXPECT_NE(refusal(d + "/rep/dataset", OutputKind::Folder).find("is part of"), std::string::npos);
	EXPECT_THROW(requireRawlogOutputAllowed(d + "/rep/dataset/d.rawlog", "omnirange-sim", {}, false), std::runtime_error);
	EXPECT_EQ(refusal(d + "/rep/notes.hist", OutputKind::Histogram), "");  // not the report's: a new file of the user's
	EXPECT_EQ(refusal(d + "/rep/floor.hist", OutputKind::Histogram, {}, true), "");  // --force: the user means it
	// Through a link to the file, a link to a folder in it, or a link and back up: where it is written counts.
	fs::create_symlink("rep/floor.hist", d + "/link.hist");
	fs::create_directory_symlink("rep/dataset", d + "/D");
	EXPECT_NE(refusal(d + "/link.hist", OutputKind::Histogram).find("is part of"), std::string::npos);
	EXPECT_THROW(requireRawlogOutputAllowed(d + "/D/d.rawlog", "omnirange-sim", {}, false), std::runtime_error);
	EXPECT_NE(refusal(d + "/D/../floor.hist", OutputKind::Histogram).find("is part of"), std::string::npos);
	// The program that made the folder fills it; so does the run filling it as its own staging folder (an
	// experiment's stages), known as its temporary: a PID in a marker, or a name, is every container's PID 1's.
	EXPECT_NO_THROW(requireNotAnothersPart(d + "/rep/floor.hist", "omnirange-experiment"));
	const std::string pid = std::to_string(::getpid()), staging = d + "/rep.staging-" + pid;
	fs::create_directory(staging);
	write(staging + "/" + kOutputMarker, "omnirange-experiment\nrun " + pid + "\nfile floor.hist\n");
	EXPECT_THROW(requireNotAnothersPart(staging + "/floor.hist", "omnirange-train"), std::runtime_error);
	temporaries::add(staging);
	EXPECT_NO_THROW(requireNotAnothersPart(staging + "/floor.hist", "omnirange-train"));
	temporaries::forget(staging);
	// A marker that is a FIFO (or a link to a device) is no marker: read, it would block or never end.
	fs::create_directory(d + "/fifo");
	ASSERT_EQ(::mkfifo((d + "/fifo/" + kOutputMarker).c_str(), 0600), 0);
	EXPECT_TRUE(markerLines(d + "/fifo").empty());
	EXPECT_EQ(refusal(d + "/fifo/x.hist", OutputKind::Histogram), "");
	EXPECT_THROW(noteInMarker(d + "/fifo", "file x.hist"), std::runtime_error);
	write(d + "/fifo/notes.txt", "the user's");  // and a folder with it, as an output, is said to be that
	EXPECT_NE(refusal(d + "/fifo", OutputKind::Folder).find("is a link or not a file, no marker of ours"), std::string::npos);
}

TEST(OutputRule, AnImageWrittenAgainAfterItWasCheckedIsNotCopiedIntoAnImport)
{
	// An import checks every image, then copies each: a simulation writing the source folder meanwhile would mix two datasets.
	const std::string d = fresh("import_changed_image");
	cv::imwrite(d + "/a.png", cv::Mat(4, 4, CV_8UC3, cv::Scalar(1, 1, 1)));
	const std::string checked = fileStateOf(d + "/a.png");
	RawlogWriter w(d + "/out.rawlog", "omnirange-test");
	EXPECT_NO_THROW(w.externalImageCopy(d + "/a.png", "0.png", checked));
	cv::imwrite(d + "/b.png", cv::Mat(4, 4, CV_8UC3, cv::Scalar(2, 2, 2)));
	fs::rename(d + "/b.png", d + "/a.png");  // another run's image in its place
	try
	{
		w.externalImageCopy(d + "/a.png", "1.png", checked);
		ADD_FAILURE() << "an image other than the one checked was copied";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("changed after it was checked"), std::string::npos) << e.what();
	}
}

TEST(OutputRule, StagedFilesAreReplacedOnlyWhenEveryPartOfTheOutputIsWritten)
{
	// omnirange-sim's order: the true map and its picture staged, the rawlog
	// committed, then the two renamed; a rawlog that fails keeps the old three.
	const std::string d = fresh("staged");
	write(d + "/log_truemap.gridmap.gz", "old map");
	write(d + "/log_truemap.png", "old picture");
	fs::create_directory(d + "/log_Images");
	write(d + "/log_Images/photo.jpg", "the user's");
	const auto simulate = [&] {
		StagedFile map(d + "/log_truemap.gridmap.gz", [](const std::string& tmp) { write(tmp, "new map"); });
		StagedFile picture = stageImage(d + "/log_truemap.png", cv::Mat(4, 4, CV_8UC3, cv::Scalar(9, 9, 9)));
		RawlogWriter w(d + "/log.rawlog", "omnirange-test");
		w.externalImage(cv::Mat(4, 4, CV_8UC3, cv::Scalar(1, 2, 3)), "0.png");
		w.write(mrpt::obs::CObservationOdometry());
		w.commit();
		map.commit();
		picture.commit();
	};
	EXPECT_THROW(simulate(), std::runtime_error);  // the images folder is the user's
	EXPECT_EQ(read(d + "/log_truemap.gridmap.gz"), "old map");
	EXPECT_EQ(read(d + "/log_truemap.png"), "old picture");
	EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 3);  // no temporary left
	fs::remove_all(d + "/log_Images");
	simulate();
	EXPECT_EQ(read(d + "/log_truemap.gridmap.gz"), "new map");
	EXPECT_EQ(read(d + "/log_truemap.png").substr(1, 3), "PNG");
	EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 4);
}

TEST(OutputRule, AnOutputOfSeveralFilesGoesInAllOrNoneAndAKilledRunsHalfIsUndone)
{
	// train --learn's histogram, ini and candidates; the accuracy's tables; the summary's pages.
	const std::string d = fresh("file_set");
	write(d + "/a.txt", "old a"), write(d + "/b.txt", "old b");
	const auto stage = [&](const std::string& name, const std::string& text) {
		return std::make_unique<StagedFile>(d + "/" + name, [&](const std::string& tmp) { write(tmp, text); });
	};
	const auto leftovers = [&] {
		int n = 0;
		for (const auto& e : fs::directory_iterator(d)) n += e.path().filename().string().front() == '.';
		return n;
	};
	// A rename that fails (the third file's temporary gone): every file as it was, nothing left.
	{
		std::vector<std::unique_ptr<StagedFile>> set;
		set.push_back(stage("a.txt", "new a")), set.push_back(stage("b.txt", "new b")), set.push_back(stage("c.txt", "new c"));
		fs::remove(temporaryOf(d + "/c.txt"));
		EXPECT_THROW(commitAll(pointersTo(set)), std::runtime_error);
	}
	EXPECT_EQ(read(d + "/a.txt"), "old a");
	EXPECT_EQ(read(d + "/b.txt"), "old b");
	EXPECT_FALSE(fs::exists(d + "/c.txt"));
	EXPECT_EQ(leftovers(), 0);
	// One that goes in: every file new, nothing left.
	{
		std::vector<std::unique_ptr<StagedFile>> set;
		set.push_back(stage("a.txt", "new a")), set.push_back(stage("c.txt", "new c"));
		commitAll(pointersTo(set));
	}
	EXPECT_EQ(read(d + "/a.txt"), "new a");
	EXPECT_EQ(read(d + "/c.txt"), "new c");
	EXPECT_EQ(leftovers(), 0);
	// Run 999986, killed after putting in a new b (the old aside), before its new d (none before) went in.
	fs::rename(d + "/b.txt", d + "/.b.txt.old-999986");
	write(d + "/b.txt", "killed run's b"), write(d + "/.d.txt.tmp-999986", "killed run's d");
	const auto inode = [&](const std::string& name) { return std::to_string(inodeNumber(d + "/" + name)); };
	const std::string journal = "run 999986 1\n" + d + "/b.txt\t" + d + "/.b.txt.old-999986\t" + inode("b.txt") + "\n" +
								d + "/d.txt\t\t" + inode(".d.txt.tmp-999986") + "\n";
	write(d + "/.b.txt.commit-999986", journal), write(d + "/.d.txt.commit-999986", journal);
	EXPECT_THROW(requireWholeSet(d + "/b.txt"), std::runtime_error);  // every reader refuses either file
	EXPECT_THROW(requireWholeSet(d + "/d.txt"), std::runtime_error);
	EXPECT_NO_THROW(requireWholeSet(d + "/a.txt"));
	testing::internal::CaptureStderr();
	recoverLeftoversOf(d + "/d.txt", OutputKind::Text);  // the next run writing one of them, saying so
	EXPECT_NE(testing::internal::GetCapturedStderr().find("and 1 other file(s) in place: what was there before is back"),
			  std::string::npos);
	EXPECT_EQ(read(d + "/b.txt"), "old b");
	EXPECT_FALSE(fs::exists(d + "/d.txt"));
	EXPECT_NO_THROW(requireWholeSet(d + "/b.txt"));
	EXPECT_EQ(leftovers(), 0);
	// Run 999983, killed finishing: both new files in, b's journal gone, d's not. The next run writing b (alone, or
	// in a set of its own) settles the set by d's journal, which names b: the new set stays whole.
	fs::rename(d + "/b.txt", d + "/.b.txt.old-999983");
	write(d + "/b.txt", "killed run's b"), write(d + "/d.txt", "killed run's d");
	write(d + "/.d.txt.commit-999983", "run 999983 1\n" + d + "/b.txt\t" + d + "/.b.txt.old-999983\t" + inode("b.txt") +
										   "\n" + d + "/d.txt\t\t" + inode("d.txt") + "\n");
	// What is left of another journal of the set, one it was killed writing, goes with the set's settling.
	write(d + "/..d.txt.commit-999983.tmp-999983", "run 999983 1\n");
	EXPECT_THROW(requireWholeSet(d + "/b.txt"), std::runtime_error);  // d's journal names it: not settled yet
	testing::internal::CaptureStderr();
	recoverLeftoversOf(d + "/b.txt", OutputKind::Text);  // a run writing b alone settles the set it is in
	EXPECT_FALSE(fs::exists(d + "/.d.txt.commit-999983"));
	EXPECT_FALSE(fs::exists(d + "/..d.txt.commit-999983.tmp-999983"));
	EXPECT_NE(testing::internal::GetCapturedStderr().find("and 1 other file(s) in place: its new files stay"),
			  std::string::npos);
	EXPECT_EQ(read(d + "/b.txt"), "killed run's b");
	EXPECT_EQ(read(d + "/d.txt"), "killed run's d");
	EXPECT_NO_THROW(requireWholeSet(d + "/d.txt"));
	EXPECT_EQ(leftovers(), 0);
	// A journal's own temporary (a run killed writing it) names no set: b is read.
	write(d + "/..b.txt.commit-999982.tmp-999982", "run 999982 1\n" + d + "/b.txt\t\t1\n");
	EXPECT_NO_THROW(requireWholeSet(d + "/b.txt"));
	fs::remove(d + "/..b.txt.commit-999982.tmp-999982");
	fs::remove(d + "/d.txt"), write(d + "/b.txt", "old b");
	// A file put where a killed run's new one was (a user's, since) is not taken out by the undoing.
	write(d + "/e.txt", "the user's e");
	write(d + "/.e.txt.commit-999985", "run 999985 1\n" + d + "/e.txt\t\t1\n");
	recoverLeftoversOf(d + "/e.txt", OutputKind::Text);
	EXPECT_EQ(read(d + "/e.txt"), "the user's e");
	EXPECT_EQ(leftovers(), 0);
	// An old file that cannot be put back (its folder gone since): an error, and the journal that says where it is stays.
	write(d + "/.f.txt.old-999984", "old f");
	write(d + "/.g.txt.commit-999984", "run 999984 1\n" + d + "/gone/f.txt\t" + d + "/.f.txt.old-999984\t1\n" + d +
											"/g.txt\t\t1\n");
	EXPECT_THROW(recoverLeftoversOf(d + "/g.txt", OutputKind::Text), std::runtime_error);
	EXPECT_EQ(read(d + "/.f.txt.old-999984"), "old f");
	EXPECT_TRUE(fs::exists(d + "/.g.txt.commit-999984"));
	// A killed run that had this run's PID (a container's PID 1, run after run) but started at another time is gone.
	const std::string pid = std::to_string(::getpid());
	// It was killed before putting in its i: its temporary goes with the undoing.
	write(d + "/h.txt", "killed run's h"), write(d + "/.i.txt.tmp-" + pid, "killed run's i");
	write(d + "/.h.txt.commit-" + pid, "run " + pid + " 1\n" + d + "/h.txt\t\t" + inode("h.txt") + "\n" + d +
										   "/i.txt\t\t" + inode(".i.txt.tmp-" + pid) + "\n");
	EXPECT_NO_THROW(recoverLeftoversOf(d + "/h.txt", OutputKind::Text));
	EXPECT_FALSE(fs::exists(d + "/h.txt"));
	EXPECT_FALSE(fs::exists(d + "/.i.txt.tmp-" + pid));
}

TEST(OutputRule, AWriteThatFailsNamesTheFileTheUserAskedForNotItsTemporary)
{
	const std::string d = fresh("failed_write");
	write(d + "/floor.hist", "old histogram");
	std::string why;
	try
	{
		writeAtomically(d + "/floor.hist", [](const std::string& tmp) {
			write(tmp, "half");
			throw std::runtime_error("error while writing '" + tmp + "'");  // as a writer past the disk's end says
		});
	}
	catch (const std::exception& e)
	{
		why = e.what();
	}
	EXPECT_EQ(why, "error while writing '" + d + "/floor.hist'");
	EXPECT_EQ(read(d + "/floor.hist"), "old histogram");
	EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);  // no temporary left
}

TEST(OutputRule, ATextFileIsReplacedOnlyIfItBeginsAsTheProgramsOwnAndALinkToNothingIsKept)
{
	const std::string d = fresh("begins");
	write(d + "/notes.md", "# my notes\n");
	write(d + "/summary.md", "# omnirange: the experiments' figures\n\nold\n");
	const auto allowed = [&](const std::string& out) {
		try
		{
			requireOutputAllowed(out, OutputKind::Text, "omnirange-test", {}, false, "# omnirange: the experiments' figures");
			return std::string();
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
	};
	EXPECT_NE(allowed(d + "/notes.md").find("is not what omnirange-test writes there"), std::string::npos);
	EXPECT_EQ(allowed(d + "/summary.md"), "");
	EXPECT_EQ(allowed(d + "/new.md"), "");
	EXPECT_NO_THROW(requireOutputAllowed(d + "/notes.md", OutputKind::Text, "omnirange-test", {}, true, "# omnirange"));
	fs::create_symlink("nowhere/x.rawlog", d + "/dangling.rawlog");
	EXPECT_NE(refusal(d + "/dangling.rawlog", OutputKind::Rawlog).find("which does not exist"), std::string::npos);
	EXPECT_TRUE(fs::is_symlink(d + "/dangling.rawlog"));
}

TEST(OutputRule, AFileAUserAddedToAnOutputFolderIsNotReplacedWithIt)
{
	const std::string d = fresh("added");
	{
		StagedFolder staged(d + "/report", "omnirange-test", {}, false);
		write(staged.path() + "/report.md", "ours");
		fs::create_directories(staged.path() + "/maps");
		write(staged.path() + "/maps/a.png", "ours");
		staged.commit();
	}
	EXPECT_EQ(refusal(d + "/report", OutputKind::Folder), "");  // only what it wrote: replaced again
	write(d + "/report/maps/notes.txt", "mine");
	EXPECT_NE(refusal(d + "/report", OutputKind::Folder).find("maps/notes.txt' is not something omnirange-test wrote"),
			  std::string::npos);
	EXPECT_EQ(refusal(d + "/report", OutputKind::Folder, {}, true), "");  // --force
	// An empty folder a user added is theirs too.
	fs::remove(d + "/report/maps/notes.txt");
	fs::create_directory(d + "/report/mine_empty");
	EXPECT_NE(refusal(d + "/report", OutputKind::Folder).find("mine_empty' is not something"), std::string::npos);
	fs::remove(d + "/report/mine_empty");
	// A link a user added is named as it is in the folder, not as where it points.
	fs::remove(d + "/report/maps/notes.txt");
	fs::create_directory(d + "/elsewhere");
	fs::create_directory_symlink("../elsewhere", d + "/report/mine");
	EXPECT_NE(refusal(d + "/report", OutputKind::Folder).find("report/mine' is not something"), std::string::npos)
		<< refusal(d + "/report", OutputKind::Folder);
	// The temporary of its marker that a run killed as it rewrote it left is the program's, not the user's.
	fs::remove(d + "/report/mine");
	write(d + "/report/." + std::string(kOutputMarker) + ".tmp-999983", "omnirange-test\n");
	EXPECT_EQ(refusal(d + "/report", OutputKind::Folder), "");
}

TEST(OutputRule, ARawlogOutputIsNamedAsMrptReadsItsImagesThroughALinkToo)
{
	const std::string d = fresh("rawlog_names");
	for (const std::string bad : {"f.rawlog.gz", "d.dat", "E.RAWLOG"})
		EXPECT_THROW(requireRawlogOutputAllowed(d + "/" + bad, "omnirange-test", {}, false), std::runtime_error) << bad;
	EXPECT_NO_THROW(requireRawlogOutputAllowed(d + "/log.rawlog", "omnirange-test", {}, false));
	EXPECT_NO_THROW(requireRawlogOutputAllowed(d + "/log", "omnirange-test", {}, false));
	// A link named NAME.rawlog to a file of another name: the images would go beside that file, where MRPT reads
	// that file's from another folder.
	{
		RawlogWriter w(d + "/real.rawlog", "omnirange-test");
		w.write(mrpt::obs::CObservationOdometry());
		w.commit();
	}
	fs::copy_file(d + "/real.rawlog", d + "/t.dat");  // a rawlog the output may replace, but under another name
	fs::create_symlink("t.dat", d + "/out.rawlog");
	try
	{
		requireRawlogOutputAllowed(d + "/out.rawlog", "omnirange-test", {}, false);
		ADD_FAILURE() << "a link to t.dat was taken as a NAME.rawlog";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("t.dat' is not named NAME.rawlog"), std::string::npos) << e.what();
	}
}
