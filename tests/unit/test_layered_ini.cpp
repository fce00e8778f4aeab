// An ini over a base: the file's keys replace the base's, bases chain, and a
// missing base or a cycle is an error that names the file.
#include <omnirange/config/LayeredIni.h>
#include <omnirange/core/Rangefinder.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace omnirange;
namespace fs = std::filesystem;

namespace
{
std::string write(const std::string& dir, const std::string& name, const std::string& text)
{
	fs::create_directories(dir);
	const std::string path = dir + "/" + name;
	std::ofstream(path) << text;
	return path;
}

std::string dir(const std::string& name) { return testing::TempDir() + "layered_ini_" + name; }
}  // namespace

TEST(LayeredIni, TheFilesKeysReplaceTheBasesAndTheRestIsInherited)
{
	const std::string d = dir("replace");
	write(d, "base.ini", "[a]\nx = 1\ny = 2\n[b]\nz = 3\n");
	const std::string top = write(d, "top.ini", "; a comment\nbase = base.ini\n\n[a]\ny = 20\nw = 4\n");
	const LayeredIni ini = readLayeredIni(top);
	ASSERT_EQ(ini.files.size(), 2u);
	EXPECT_EQ(fs::path(ini.files[0]).filename(), "base.ini");
	EXPECT_EQ(ini.merged->read_int("a", "x", 0), 1);
	EXPECT_EQ(ini.merged->read_int("a", "y", 0), 20);
	EXPECT_EQ(ini.merged->read_int("a", "w", 0), 4);
	EXPECT_EQ(ini.merged->read_int("b", "z", 0), 3);
	EXPECT_FALSE(ini.merged->keyExists("", "base"));
	// Which file each value came from: relative paths in it are relative to that file's folder.
	EXPECT_EQ(fs::path(ini.originOf("a", "x")).filename(), "base.ini");
	EXPECT_EQ(fs::path(ini.originOf("a", "y")).filename(), "top.ini");
	EXPECT_EQ(ini.originOf("a", "nothing"), "");
}

TEST(LayeredIni, BasesChainAndAFileWithoutOneIsItself)
{
	const std::string d = dir("chain");
	write(d + "/deep", "root.ini", "[s]\nk = root\nonly_root = 1\n");
	write(d, "mid.ini", "base = deep/root.ini\n[s]\nk = mid\n");
	const std::string top = write(d, "top.ini", "base = mid.ini\n[s]\nk = top\n");
	const LayeredIni ini = readLayeredIni(top);
	EXPECT_EQ(ini.files.size(), 3u);
	EXPECT_EQ(ini.merged->read_string("s", "k", ""), "top");
	EXPECT_EQ(ini.merged->read_int("s", "only_root", 0), 1);
	EXPECT_EQ(readLayeredIni(d + "/deep/root.ini").files.size(), 1u);
	EXPECT_EQ(iniBaseOf(d + "/deep/root.ini"), "");
	// An ini read through a link takes its base from beside the file, where it was written, not from beside the link.
	write(d + "/other", "mid.ini", "[s]\nk = beside the link\n");
	fs::remove(d + "/other/top.ini");
	fs::create_symlink("../top.ini", d + "/other/top.ini");
	EXPECT_EQ(readLayeredIni(d + "/other/top.ini").merged->read_int("s", "only_root", 0), 1);
}

TEST(LayeredIni, AMissingBaseACycleAndARepeatedKeyAreErrorsNamingTheFile)
{
	const std::string d = dir("errors");
	const auto fails = [](const std::string& path, const std::string& says) {
		try
		{
			readLayeredIni(path);
			ADD_FAILURE() << path << " was read";
		}
		catch (const std::runtime_error& e)
		{
			EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
		}
	};
	fails(write(d, "orphan.ini", "base = nowhere.ini\n[s]\nk = 1\n"), "nowhere.ini");
	write(d, "one.ini", "base = two.ini\n[s]\n");
	fails(write(d, "two.ini", "base = one.ini\n[s]\n"), "lead back");
	write(d, "twice.ini", "[s]\nk = 1\nk = 2\n");
	fails(write(d, "over-twice.ini", "base = twice.ini\n[s]\n"), "twice.ini:3");
	fails(write(d, "empty-base.ini", "base =\n[s]\n"), "names no file");
	fails(d + "/absent.ini", "absent.ini");
}

TEST(LayeredIni, AnErrorInABaseNamesTheBaseNotTheFileRead)
{
	const std::string d = dir("base_error");
	const auto refusal = [](const std::string& path) {
		try
		{
			RangefinderParams::loadFromFile(path, "rangefinder");
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
		return std::string("read");
	};
	write(d, "bad-value.ini", "[rangefinder]\nthreshold = 2\n");
	const std::string bad = refusal(write(d, "mine.ini", "base = bad-value.ini\n[rangefinder]\nN = 20\n"));
	EXPECT_EQ(bad.rfind(fs::absolute(d + "/bad-value.ini").string() + ": [rangefinder] threshold = '2'", 0), 0u) << bad;
	write(d, "misspelt.ini", "[rangefinder]\nthreshod = 0.1\n");
	const std::string misspelt = refusal(write(d, "mine2.ini", "base = misspelt.ini\n[rangefinder]\nN = 20\n"));
	EXPECT_NE(misspelt.find("misspelt.ini: unknown key 'threshod'"), std::string::npos) << misspelt;
	// The file's own key: the file is named.
	const std::string own = refusal(write(d, "own.ini", "base = mine.ini\n[rangefinder]\nthreshold = 3\n"));
	EXPECT_NE(own.find("own.ini: [rangefinder] threshold = '3'"), std::string::npos) << own;
	// A value refused by a check after loading ("[section] key must ...") names the base that set it;
	// one refused with keys of two files (the scan circle: N here, the image in the base) names the file read.
	write(d, "base-check.ini", "[rangefinder]\nsensor_label = OMNI\nmax_range = -1\n");
	const std::string checked = refusal(write(d, "mine3.ini", "base = base-check.ini\n[rangefinder]\nN = 20\n"));
	EXPECT_EQ(checked.rfind(fs::absolute(d + "/base-check.ini").string() + ": [rangefinder]", 0), 0u) << checked;
	const std::string circle = refusal(write(d, "mine4.ini", "base = base-check.ini\n[rangefinder]\nmax_range = 4\nN = 5000\n"));
	EXPECT_EQ(circle.rfind(d + "/mine4.ini: [rangefinder] scanner: the scan circle", 0), 0u) << circle;
}

TEST(LayeredIni, ABaseKeyInsideASectionIsAnOrdinaryKey)
{
	// Only a `base` before the first section names a base.
	const std::string d = dir("in_section");
	const std::string top = write(d, "top.ini", "[s]\nbase = other.ini\n");
	EXPECT_EQ(iniBaseOf(top), "");
	EXPECT_EQ(readLayeredIni(top).merged->read_string("s", "base", ""), "other.ini");
}
