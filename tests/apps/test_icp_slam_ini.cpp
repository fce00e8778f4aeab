// icp-slam's ini as MRPT reads it: the keys it would ignore are found, and
// the shipped inis have none.
#include <omnirange_slam/IcpSlamIni.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using omnirange::slam::icpKeysMrptIgnores;

namespace
{
/** An ini file in the test's temporary folder, removed when it goes. */
struct TempIni
{
	explicit TempIni(const std::string& text) : path(testing::TempDir() + "omnirange_icp_keys.ini")
	{
		std::ofstream(path) << text;
	}
	~TempIni() { std::filesystem::remove(path); }
	std::string path;
};
}  // namespace

TEST(IcpSlamIni, TheShippedInisHaveNoKeyMrptIgnores)
{
	const std::string ini = OMNIRANGE_SOURCE_DIR "/ini/";
	for (const std::string name : {"icp-slam-laser.ini", "icp-slam-omniscan.ini"})
		EXPECT_EQ(icpKeysMrptIgnores(ini + name), std::vector<std::string>{}) << name;
}

TEST(IcpSlamIni, OldNamesAndATypoAreFoundAndKnownKeysAreNot)
{
	// The angles are read in degrees (_DEG); under their radian names, as
	// MRPT writes them, they are not read at all.
	const TempIni ini(
		"[ICP]\nthresholdDist = 0.5\nthresholdAng_DEG = 7\nransac_fuseMaxDiffPhi_DEG = 0.1\nonlyUniqueRobust = true\n"
		"onlyClosestCorrespondences = true\nmaxIteration = 80\nthresholdAng = 0.1\n[MappingApplication]\nfoo = 1\n");
	EXPECT_EQ(icpKeysMrptIgnores(ini.path),
			  (std::vector<std::string>{"maxIteration", "onlyClosestCorrespondences", "thresholdAng"}));
}

TEST(IcpSlamIni, AnIniWithoutTheSectionIsAnError)
{
	const TempIni ini("[MappingApplication]\ninsertionLinDistance = 0.5\n");
	EXPECT_THROW(icpKeysMrptIgnores(ini.path), std::runtime_error);
}

TEST(IcpSlamIni, AMissingFileIsAnErrorNamingIt)
{
	try
	{
		icpKeysMrptIgnores("/nonexistent/icp.ini");
		FAIL() << "no error";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/icp.ini"), std::string::npos) << e.what();
	}
}

TEST(IcpSlamIni, TheIcpSectionIsReadStrictlyNamingFileSectionAndKey)
{
	using omnirange::slam::requireStrictIcpSection;
	const auto refusal = [](const std::string& text) {
		const TempIni ini(text);
		try
		{
			requireStrictIcpSection(ini.path);
			return std::string();
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
	};
	EXPECT_EQ(refusal("[ICP]\nmaxIterations = 80\nthresholdAng_DEG = 7\nonlyUniqueRobust = true\n"
					  "ICP_algorithm = icpClassic\n"),
			  "");
	EXPECT_EQ(refusal("[MappingApplication]\ninsertionLinDistance = 0.5\n"), "");  // no [ICP]: MRPT's defaults
	for (const std::string bad : {"maxIterations = abc", "maxIterations = 0,4", "thresholdDist = 0.2m",
								  "onlyUniqueRobust = maybe", "ICP_algorithm = 3 classic", "maxIteration = 80"})
	{
		const std::string why = refusal("[ICP]\n" + bad + "\n");
		EXPECT_NE(why.find("omnirange_icp_keys.ini"), std::string::npos) << bad << ": " << why;
		EXPECT_NE(why.find("[ICP] " + bad.substr(0, bad.find(' '))), std::string::npos) << bad << ": " << why;
	}
	EXPECT_NE(refusal("[ICP]\nmaxIterations = 80\nmaxIterations = 90\n").find("repeats"), std::string::npos);
	// [MappingApplication]: the keys icp-slam and its map builder read, and a
	// count per map kind MRPT knows; a misspelt key would keep its default.
	EXPECT_EQ(refusal("[MappingApplication]\nlogOutput_dir = out\npointsMap_count = 1\nCSimplePointsMap_count = 0\n"
					  "localizationAngDistance = 5\n"),
			  "");
	for (const std::string bad : {"insertionLinDistnce = 0.5", "likelihoodMapSelection = -1", "pointMap_count = 1"})
		EXPECT_NE(refusal("[MappingApplication]\n" + bad + "\n").find("[MappingApplication] " + bad.substr(0, bad.find(' '))),
				  std::string::npos)
			<< bad;
}
