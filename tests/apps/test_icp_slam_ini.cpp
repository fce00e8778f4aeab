// icp-slam's ini as MRPT reads it: the keys it would ignore are found, and
// the shipped inis have none.
#include <omnirange_slam/IcpSlamIni.h>
#include <omnirange_slam/MrptMapSections.h>

#include <functional>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using omnirange::slam::icpKeysMrptIgnores;

namespace
{
/** An ini file in the test's temporary folder, removed when it goes. */
struct TempIni
{
	// One file per test: ctest runs each test as its own process, two at a time.
	explicit TempIni(const std::string& text)
		: path(testing::TempDir() + "omnirange_icp_keys_" +
			   testing::UnitTest::GetInstance()->current_test_info()->name() + ".ini")
	{
		std::ofstream(path) << text;
	}
	~TempIni() { std::filesystem::remove(path); }
	std::string path;
};

/** What `check` throws on an ini holding `text`, or "" if it takes it. */
std::string refusalOf(const std::function<void(const std::string&)>& check, const std::string& text)
{
	const TempIni ini(text);
	try
	{
		check(ini.path);
		return std::string();
	}
	catch (const std::runtime_error& e)
	{
		return std::string(e.what());
	}
}

/** refusalOf() for omnirange-slam's reading of an icp-slam ini. */
std::string refusal(const std::string& text)
{
	return refusalOf([](const std::string& f) { omnirange::slam::requireStrictIcpSection(f); }, text);
}
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
	EXPECT_EQ(refusal("[ICP]\nmaxIterations = 80\nthresholdAng_DEG = 7\nonlyUniqueRobust = true\n"
					  "ICP_algorithm = icpClassic\n"),
			  "");
	EXPECT_EQ(refusal("[MappingApplication]\ninsertionLinDistance = 0.5\n"), "");  // no [ICP]: MRPT's defaults
	for (const std::string bad : {"maxIterations = abc", "maxIterations = 0,4", "thresholdDist = 0.2m",
								  "onlyUniqueRobust = maybe", "ICP_algorithm = 3 classic", "maxIteration = 80"})
	{
		const std::string why = refusal("[ICP]\n" + bad + "\n");
		EXPECT_NE(why.find("omnirange_icp_keys_"), std::string::npos) << bad << ": " << why;
		EXPECT_NE(why.find("[ICP] " + bad.substr(0, bad.find(' '))), std::string::npos) << bad << ": " << why;
	}
	EXPECT_NE(refusal("[ICP]\nmaxIterations = 80\nmaxIterations = 90\n").find("repeats"), std::string::npos);
	// What MRPT reads otherwise than it reads here: a whole number by atoi ('8e1' is 8 there), a float rounded
	// (0.99999999999 is 1, which MRPT asserts against), and an ALFA near 1, which makes a match take minutes.
	for (const std::string bad : {"maxIterations = 8e1", "maxIterations = 80.0", "corresponding_points_decimation = 0.1e1",
								  "ALFA = 0.99999999999", "ALFA = 0.999"})
		EXPECT_NE(refusal("[ICP]\n" + bad + "\n").find("[ICP] " + bad.substr(0, bad.find(' '))), std::string::npos) << bad;
	EXPECT_EQ(refusal("[ICP]\nALFA = 0.99\nmaxIterations = -0\n"), "");
	EXPECT_EQ(refusal("[MappingApplication]\npointsMap_count = 1\n"), "");
	EXPECT_NE(refusal("[MappingApplication]\npointsMap_count = 0.1e1\n").find("written in digits"), std::string::npos);
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

TEST(IcpSlamIni, TheMapSectionsAreHeldToTheKeysMrptReadsAsItReadsThem)
{
	const std::string maps = "[MappingApplication]\noccupancyGrid_count = 1\npointsMap_count = 1\n";
	const std::string grid = "[MappingApplication_occupancyGrid_00_creationOpts]\n";
	const std::string points = "[MappingApplication_pointsMap_00_insertOpts]\n";
	EXPECT_EQ(refusal(maps + grid + "resolution = 0.05\nmin_x = -10\n" + points +
					  "minDistBetweenLaserPoints = 0.05\nisPlanarMap = 1\nfuseWithExisting = false\n"),
			  "");
	// What MRPT 2.5 would read wrongly or not at all, and what it would not read.
	const std::vector<std::pair<std::string, std::string>> bad = {
		{grid + "resolution = 0,05\n", "resolution = '0,05'"},  // atof: 0
		{grid + "resolution = 0.05m\n", "resolution = '0.05m'"},
		{grid + "resolution = 0\n", "within [0.005, 10] m"},
		{grid + "resolutoin = 0.05\n", "resolutoin: not a key MRPT reads"},
		{grid + "disableSaveAs3DObject = 1\n", "disableSaveAs3DObject: not a key MRPT reads"},
		{points + "isPlanarMap = maybe\n", "must be true or false"},  // atoi: false
		{"[MappingApplication_pointsMap_00_insertOpt]\nisPlanarMap = 1\n", "unknown section"},
		{"[MappingApplication_pointsMap_01_insertOpts]\nisPlanarMap = 1\n", "unknown section"},  // one points map
		{"[MappingApplication_occupancyGrid_00_insertOpts]\nmaxOccupancyUpdateCertainty = 5\n", "within [0.5, 1)"},
		{"[MappingApplication_occupancyGrid_00_insertOpts]\nmaxDistanceInsertion = inf\n", "maxDistanceInsertion"},
	};
	for (const auto& [text, expected] : bad)
	{
		const std::string why = refusal(maps + text);
		EXPECT_NE(why.find(expected), std::string::npos) << text << ": " << why;
		EXPECT_NE(why.find("omnirange_icp_keys_"), std::string::npos) << why;
	}
	EXPECT_NE(refusal("[MappingApplication]\npointsMap_count = 1000000000\n").find("within [0, 16]"), std::string::npos);
	// icp-slam empties its logOutput_dir first: only a plain name, made where it runs.
	for (const std::string dir : {"..", ".", "/tmp/someones", "../other"})
		EXPECT_NE(refusal("[MappingApplication]\nlogOutput_dir = " + dir + "\n").find("plain folder name"),
				  std::string::npos)
			<< dir;
	// The shipped inis pass.
	for (const std::string shipped : {"icp-slam-omniscan.ini", "icp-slam-laser.ini"})
		EXPECT_NO_THROW(omnirange::slam::requireStrictIcpSection(std::string(OMNIRANGE_SOURCE_DIR) + "/ini/" + shipped)) << shipped;
}

TEST(IcpSlamIni, SettingsIcpSlamFollowsAndTheGuardedMatcherDoesNotAreNamed)
{
	const TempIni given("[MappingApplication]\nrawlog_offset = 15\nmatchAgainstTheGrid = true\npointsMap_count = 0\n");
	const auto ignored = omnirange::slam::mappingSettingsGuardedIcpIgnores(given.path);
	EXPECT_EQ(ignored, (std::vector<std::string>{"rawlog_offset = 15", "matchAgainstTheGrid = true", "pointsMap_count = 0"}));
	const TempIni shipped_like("[MappingApplication]\nrawlog_offset = 0\nmatchAgainstTheGrid = false\npointsMap_count = 1\n");
	EXPECT_TRUE(omnirange::slam::mappingSettingsGuardedIcpIgnores(shipped_like.path).empty());
}

TEST(IcpSlamIni, TheObservationsToMapAndRbpfInisAreHeldToWhatMrptReads)
{
	namespace slam = omnirange::slam;
	const std::string dir = OMNIRANGE_SOURCE_DIR "/ini/";
	for (const std::string shipped : {"observations2map-omniscan.ini", "observations2map-laser.ini"})
		EXPECT_NO_THROW(slam::requireStrictObservationsToMapIni(dir + shipped)) << shipped;
	for (const std::string shipped : {"rbpf-slam-omniscan.ini", "rbpf-slam-laser.ini"})
		EXPECT_NO_THROW(slam::requireStrictRbpfIni(dir + shipped)) << shipped;
	const auto map = [](const std::string& f) { slam::requireStrictObservationsToMapIni(f); };
	const std::string grid = "[MappingApplication]\noccupancyGrid_count = 1\n[MappingApplication_occupancyGrid_00_creationOpts]\n";
	for (const auto& [bad, expected] : std::vector<std::pair<std::string, std::string>>{
			 {"[MappingApplication]\npointsMap_count = -1\n", "within [0, 16]"},  // observations2map grew without end
			 {grid + "resolutoin = 0.05\n", "resolutoin: not a key MRPT reads"},
			 {grid + "resolution = 0,05\n", "resolution = '0,05'"},
			 {grid + "resolution = 0.0001\n", "within [0.005, 10] m"},
			 {grid + "min_x = -90000\n", "within [-1000, 1000] m"},
			 {grid + "resolution = 0.005\nmin_x = -900\nmax_x = 900\nmin_y = -900\nmax_y = 900\n",
			  "million cells, more than 100 million"},  // each bound kept, 130 GB in all
			 {"[MappingApplication]\noccupancyGrid_count = 1\n[MappingApplication_occupancyGrid_00_insertOpts]\n"
			  "maxDistanceInsertion = -1\n",
			  "must be > 0 m"},  // an empty map, reported as a result
			 {"[MappingApplication]\nlogOutput_dir = x\n", "not a key observations2map reads"},
			 {"[Other]\nk = 1\n", "unknown section [Other]"}})
		EXPECT_NE(refusalOf(map, bad).find(expected), std::string::npos) << bad << ": " << refusalOf(map, bad);
	// The shipped rbpf ini with one line changed (MRPT requires some of its keys).
	std::ifstream in(dir + "rbpf-slam-omniscan.ini");
	const std::string shipped((std::istreambuf_iterator<char>(in)), {});
	const auto edited = [&](const std::string& from, const std::string& to) {
		const auto at = shipped.find(from);
		EXPECT_NE(at, std::string::npos) << from;
		return shipped.substr(0, at) + to + shipped.substr(at + from.size());
	};
	const auto rbpf = [](const std::string& f) { slam::requireStrictRbpfIni(f); };
	for (const auto& [bad, expected] : std::vector<std::pair<std::string, std::string>>{
			 {edited("sampleSize = 10", "sampleSize = -1"), "within [1, 10000]"},  // rbpf-slam took 24 GB
			 {edited("sampleSize = 10", "sampleSize = 10\nsampelSize = 10"), "sampelSize: not a key rbpf-slam reads"},
			 {edited("sampleSize = 10", "sampleSize = 0,5"), "sampleSize = '0,5'"},
			 {edited("PF_algorithm = 2", "PF_algorithm = 99"), "must be one of pfStandardProposal"},
			 {edited("KLD_binSize_XY = 0.03", "KLD_binSize_XY = 0"), "must be > 0"},
			 {edited("adaptiveSampleSize = 0", ""), "adaptiveSampleSize is missing"},
			 {edited("[MappingApplication]\n", "[MappingApplication]\nmax_corr_distanc = 1.0\n"), "not a key rbpf-slam reads"}})
		EXPECT_NE(refusalOf(rbpf, bad).find(expected), std::string::npos) << expected << ": " << refusalOf(rbpf, bad);
	EXPECT_EQ(refusalOf(rbpf, edited("PF_algorithm = 2", "PF_algorithm = pfOptimalProposal")), "");
	// icp-slam's map builder's own keys in [MappingApplication]: their values are held to MRPT's too.
	std::ifstream icp_in(dir + "icp-slam-omniscan.ini");
	const std::string icp((std::istreambuf_iterator<char>(icp_in)), {});
	const std::string key = "minICPgoodnessToAccept = 0.40";
	ASSERT_NE(icp.find(key), std::string::npos);
	const std::string goodness =
		icp.substr(0, icp.find(key)) + "minICPgoodnessToAccept = 2147483648" + icp.substr(icp.find(key) + key.size());
	EXPECT_NE(refusal(goodness).find("minICPgoodnessToAccept = '2147483648': must be within [0, 1]"), std::string::npos)
		<< refusal(goodness);
}
