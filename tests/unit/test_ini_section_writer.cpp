// Writing one section into a person's ini: values replaced in place, new
// keys at the section's end, every comment and other section kept.
#include <omnirange/core/Rangefinder.h>
#include <omnirange/config/Output.h>
#include <omnirange/config/IniSectionWriter.h>
#include <omnirange/config/OptionsTable.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

using namespace omnirange;

namespace
{
std::string read(const std::string& path)
{
	std::ifstream in(path);
	std::stringstream s;
	s << in.rdbuf();
	return s.str();
}
/** `name` in a folder of the running test's own (tests run side by side: one
 * test's staging folder must not show in another's). */
std::string tmp(const std::string& name)
{
	static std::string test;
	const std::string now = testing::UnitTest::GetInstance()->current_test_info()->name();
	const auto dir = std::filesystem::temp_directory_path() / "omnirange_ini_section_writer" / now;
	if (test != now) std::filesystem::remove_all(dir), std::filesystem::create_directories(dir), test = now;
	return (dir / name).string();
}
}  // namespace

TEST(IniSectionWriter, ReplacesInPlaceAddsAtTheSectionsEndAndKeepsTheRest)
{
	const std::string path = tmp("user.ini");
	std::ofstream(path) << "; my robot\n[experiment]\nname = x\nN = 99\n\n[rangefinder]\n; [px] filter\n  N = 20\n"
						   "threshold = 0.075\n\n; the end of rangefinder\n[other]\nK = 7\n";
	writeIniSection(path, "rangefinder", {{"threshold", "0.01"}, {"N", "10"}, {"K", "4"}});
	EXPECT_EQ(read(path),
			  "; my robot\n[experiment]\nname = x\nN = 99\n\n[rangefinder]\n; [px] filter\n  N = 10\n"
			  "threshold = 0.01\nK = 4\n\n; the end of rangefinder\n[other]\nK = 7\n");
}

TEST(IniSectionWriter, AFileWithCrlfLineEndsKeepsThemOnEveryLine)
{
	const std::string path = tmp("crlf.ini");
	std::ofstream(path, std::ios::binary) << "; mine\r\n[rangefinder]\r\nN = 20\r\n\r\n[other]\r\nK = 7\r\n";
	writeIniSection(path, "rangefinder", {{"N", "10"}, {"K", "4"}});
	EXPECT_EQ(read(path), "; mine\r\n[rangefinder]\r\nN = 10\r\nK = 4\r\n\r\n[other]\r\nK = 7\r\n");
}

TEST(IniSectionWriter, ASectionOrKeyInAnotherCaseIsTheSameOne)
{
	// MRPT reads [RangeFinder] as [rangefinder] and Threshold as threshold:
	// a second section or key would make every reader refuse the file.
	const std::string path = tmp("case.ini");
	std::ofstream(path) << "[RangeFinder]\nThreshold = 0.05\ncx = 100\n";
	writeIniSection(path, "rangefinder", {{"threshold", "0.1"}, {"cx", "101"}, {"cy", "99"}});
	EXPECT_EQ(read(path), "[RangeFinder]\nThreshold = 0.1\ncx = 101\ncy = 99\n");
	EXPECT_EQ(requireWellFormedIni(path), 3);
}

TEST(IniSectionWriter, AppendsAMissingSectionAndCreatesAMissingFile)
{
	const std::string path = tmp("no_section.ini");
	std::ofstream(path) << "[experiment]\nname = x";
	writeIniSection(path, "rangefinder", {{"N", "10"}});
	EXPECT_EQ(read(path), "[experiment]\nname = x\n\n[rangefinder]\nN = 10\n");
	const std::string fresh = tmp("fresh.ini");
	std::filesystem::remove(fresh);
	writeIniSection(fresh, "rangefinder", {{"K", "2"}});
	EXPECT_EQ(read(fresh), "[rangefinder]\nK = 2\n");
}

TEST(IniSectionWriter, ASectionTwiceIsAnErrorAndTheFileStays)
{
	const std::string path = tmp("twice.ini");
	const std::string text = "[rangefinder]\nN = 1\n[rangefinder]\nK = 2\n";
	std::ofstream(path) << text;
	EXPECT_THROW(writeIniSection(path, "rangefinder", {{"N", "10"}}), std::runtime_error);
	EXPECT_EQ(read(path), text);
}

TEST(IniSectionWriter, AnAddedKeyGetsItsCommentAKeptOneKeepsItsOwn)
{
	const std::string path = tmp("comments.ini");
	std::ofstream(path) << "[rangefinder]\n; mine\nN = 20\n";
	const auto comments = RangefinderParams::table().comments();
	writeIniSection(path, "rangefinder", {{"N", "10"}, {"xi", "0.8"}}, comments);
	EXPECT_EQ(read(path), "[rangefinder]\n; mine\nN = 10\n; " + comments.at("xi") + "\nxi = 0.8\n");
	EXPECT_EQ(comments.at("xi").rfind("[-] ", 0), 0u) << comments.at("xi");  // the unit first, as every shipped ini has it
}

TEST(IniSectionWriter, AnIniEveryProgramWouldRefuseIsRefusedBeforeAnyKeyIsAdded)
{
	// Keys written into it would not make it readable: cx set, CX = 2 kept, every program refusing it.
	for (const std::string text : {"[rangefinder]\ncx = 1\nCX = 2\n", "cx = 1\n[rangefinder]\nN = 1\n",
								   "[rangefinder\nN = 1\n", "[]\nN = 1\n"})
	{
		const std::string path = tmp("refused.ini");
		std::ofstream(path) << text;
		EXPECT_THROW(writeIniSection(path, "rangefinder", {{"cx", "512"}}), std::runtime_error) << text;
		EXPECT_EQ(read(path), text);
	}
}

TEST(IniSectionWriter, ASectionNameNoReaderWouldTakeBackIsRefusedBeforeTheFileChanges)
{
	const std::string path = tmp("names.ini");
	const std::string text = "[rangefinder]\nthreshold = 0.05\n";
	std::ofstream(path) << text;
	for (const std::string bad : {"", "a]b", "x\ny = 2", "two words", "[rangefinder]"})
	{
		EXPECT_THROW(writeIniSection(path, bad, {{"cx", "512"}}), std::invalid_argument) << bad;
		EXPECT_EQ(read(path), text) << bad;
	}
	writeIniSection(path, "robot-2.mirror_v1", {{"cx", "512"}});
	EXPECT_EQ(read(path), text + "\n[robot-2.mirror_v1]\ncx = 512\n");
}

TEST(IniSectionWriter, AnUpdateNeverReplacesAChangeMadeSinceItWasRead)
{
	// A user's editor saving between the read and the rename: the update is refused, the edit stays.
	const std::string path = tmp("edited.ini");
	std::ofstream(path) << "[rangefinder]\nN = 20\n";
	const std::string state = fileStateOf(path);
	std::ofstream(path, std::ios::app) << "K = 3\n";
	const auto update = [&](const std::string& read_state) {
		OutputSet set;
		set.write({path, OutputKind::Ini}, "[rangefinder]\nN = 10\n");
		set.requireUnchanged(path, read_state);
		set.commit();
	};
	EXPECT_THROW(update(state), ChangedMeanwhile);
	EXPECT_EQ(read(path), "[rangefinder]\nN = 20\nK = 3\n");
	for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
		EXPECT_NE(e.path().filename().string().rfind(".omnirange-", 0), 0u) << e.path();  // nothing staged is left
	// Read as it is now, the update goes in.
	update(fileStateOf(path));
	EXPECT_EQ(read(path), "[rangefinder]\nN = 10\n");
}

TEST(IniSectionWriter, TwoRunsSavingIntoOneIniAtOnceKeepBothSections)
{
	// Two calibrations with --save-to the same ini: the later one reads the earlier one's keys and keeps them.
	const std::string path = tmp("shared.ini");
	for (int round = 0; round < 20; ++round)
	{
		std::ofstream(path, std::ios::trunc) << "; the robot\n";
		std::vector<pid_t> runs;
		for (const std::string section : {"rangefinder", "other"})
		{
			const pid_t run = ::fork();
			if (run == 0)
			{
				writeIniSection(path, section, {{"N", "10"}});
				::_exit(0);
			}
			runs.push_back(run);
		}
		for (const pid_t run : runs)
		{
			int status = 0;
			::waitpid(run, &status, 0);
			EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
		}
		const std::string text = read(path);
		ASSERT_NE(text.find("[rangefinder]"), std::string::npos) << "round " << round << ":\n" << text;
		ASSERT_NE(text.find("[other]"), std::string::npos) << "round " << round << ":\n" << text;
	}
}

TEST(IniSectionWriter, AFileWrittenWithTheKeysGoesInWithTheIniOrNeitherDoes)
{
	// A calibration's YAML and its keys: one set, so that a failure leaves no new YAML beside old keys.
	const std::string dir = tmp("with_set"), path = dir + "/my.ini", yaml = dir + "/cam.yaml";
	std::filesystem::remove_all(dir), std::filesystem::create_directories(dir);
	std::ofstream(path) << "[rangefinder]\nR = 192\n";
	std::ofstream(yaml) << "old";
	// Its writing fails (a full disk): neither goes in.
	const auto failing = [&](OutputSet& set) {
		set.write({yaml, OutputKind::Text}, [](const std::string&) { throw std::runtime_error("disk full"); });
	};
	EXPECT_THROW(writeIniSection(path, "rangefinder", {{"R", "200"}}, {}, {"", {}, failing}), std::runtime_error);
	EXPECT_EQ(read(path), "[rangefinder]\nR = 192\n");
	EXPECT_EQ(read(yaml), "old");
	writeIniSection(path, "rangefinder", {{"R", "200"}}, {},
					{"", {}, [&](OutputSet& set) { set.write({yaml, OutputKind::Text}, "new"); }});
	EXPECT_EQ(read(path), "[rangefinder]\nR = 200\n");
	EXPECT_EQ(read(yaml), "new");
	EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 2);
}
