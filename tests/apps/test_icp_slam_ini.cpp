// icp-slam's ini as MRPT reads it: the keys it would ignore are found, and
// the shipped inis have none.
#include <omnirange_eval/IcpSlamIni.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using omnirange::eval::icpKeysMrptIgnores;

TEST(IcpSlamIni, TheShippedInisHaveNoKeyMrptIgnores)
{
	const std::string ini = OMNIRANGE_SOURCE_DIR "/ini/";
	for (const std::string name : {"icp-slam-laser.ini", "icp-slam-omniscan.ini"})
		EXPECT_EQ(icpKeysMrptIgnores(ini + name), std::vector<std::string>{}) << name;
}

TEST(IcpSlamIni, AnOldNameAndATypoAreFoundAndKnownKeysAreNot)
{
	const auto file = (std::filesystem::temp_directory_path() / "omnirange_icp_keys.ini").string();
	std::ofstream(file) << "[ICP]\nthresholdDist = 0.5\nthresholdAng_DEG = 7\nonlyUniqueRobust = true\n"
						   "onlyClosestCorrespondences = true\nmaxIteration = 80\n[MappingApplication]\nfoo = 1\n";
	EXPECT_EQ(icpKeysMrptIgnores(file), (std::vector<std::string>{"maxIteration", "onlyClosestCorrespondences"}));
	std::filesystem::remove(file);
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
