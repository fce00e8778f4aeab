// The options tables: strict values, renamed and unknown keys named, angles
// in degrees in the ini and radians in memory, printing that loads back.
#include <omnirange/core/Rangefinder.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace omnirange;

namespace
{
/** The error loading `body` as [rangefinder] gives, or "" if it loads. */
std::string loadError(const std::string& body)
{
	RangefinderParams p;
	try
	{
		p.loadFromConfig(mrpt::config::CConfigFileMemory("[rangefinder]\n" + body + "\n"), "rangefinder");
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(OptionsTable, ValuesAreParsedStrictly)
{
	for (const std::string bad : {"threshold = abc", "threshold = 0,075", "N = 20abc", "h = 0.931m",
								  "scanlines = 360.7", "mirrored = maybe", "pose_x = nan", "outlier_abs_tol = inf",
								  "N = 2147483648", "R = abc"})
	{
		const std::string key = bad.substr(0, bad.find(' '));
		const std::string e = loadError(bad);
		EXPECT_NE(e.find("[rangefinder] " + key + " = '"), std::string::npos) << bad << " -> " << e;
	}
	EXPECT_EQ(loadError("threshold = 0.075\nN = 12\nmirrored = false"), "");
}

TEST(OptionsTable, ImpossibleValuesNameTheUsersSection)
{
	EXPECT_NE(loadError("N = 0").find("[rangefinder] N = '0': must be within [1, 10000] px"), std::string::npos);
	EXPECT_NE(loadError("N = 2147483647").find("N = '2147483647': must be within [1, 10000] px"), std::string::npos);
	EXPECT_NE(loadError("outlier_max_width = 2147483647").find("outlier_max_width"), std::string::npos);
	EXPECT_NE(loadError("scanlines = 1000000000").find("scanlines = '1000000000': must be within [2, 36000]"),
			  std::string::npos);
	// Ranges with an open end, and a list's every element.
	EXPECT_NE(loadError("wall_fit_tolerance = 0").find("must be within (0, 100] sigma"), std::string::npos);
	EXPECT_NE(loadError("exposure_deadband = 1").find("must be within [0, 1)"), std::string::npos);
	EXPECT_NE(loadError("edge_bias = 0.1 0.6").find("edge_bias = '0.1 0.6': must be within [-0.5, 0.5] m"),
			  std::string::npos);
	EXPECT_EQ(loadError("exposure_deadband = 0\nwall_fit_tolerance = 100\nedge_bias = -0.5 0.5"), "");
	// Keys whose nonsense was once taken: a turn of 1e308 degrees, a float's max range overflowing.
	EXPECT_NE(loadError("forward_azimuth_deg = 1e308").find("must be within [-360, 360] deg"), std::string::npos);
	EXPECT_NE(loadError("max_range = 1e308").find("must be within (0, 1000] m"), std::string::npos);
	EXPECT_NE(loadError("h = 1e308").find("must be within (0, 100] m"), std::string::npos);
}

TEST(OptionsTable, OldAndUnknownKeysAreNamed)
{
	const std::string old = loadError("forward_azimuth = 3.14159");
	EXPECT_NE(old.find("forward_azimuth_deg"), std::string::npos) << old;
	EXPECT_NE(loadError("threshhold = 0.1").find("unknown key 'threshhold'"), std::string::npos);
	// A key in another case is the key, as MRPT reads it (and as --save-to writes into it).
	EXPECT_EQ(loadError("Threshold = 0.1\nn = 12"), "");
	RangefinderParams p;
	p.loadFromConfig(mrpt::config::CConfigFileMemory("[rangefinder]\nThreshold = 0.1\n"), "rangefinder");
	EXPECT_DOUBLE_EQ(p.threshold, 0.1);
}

TEST(OptionsTable, AnglesAreDegreesInTheIniAndRadiansInMemory)
{
	RangefinderParams p;
	p.loadFromConfig(mrpt::config::CConfigFileMemory("[r]\nforward_azimuth_deg = 90\npose_yaw = 30\n"), "r");
	EXPECT_NEAR(p.camera.forward_azimuth, M_PI / 2, 1e-12);
	EXPECT_NEAR(p.sensor_pose.yaw(), M_PI / 6, 1e-12);
	EXPECT_DOUBLE_EQ(p.sensor_pose.z(), p.camera.h);  // pose_z defaults to h
}

TEST(OptionsTable, PrintedOptionsLoadBackEqual)
{
	RangefinderParams p;
	p.camera.forward_azimuth = 1.0;
	p.scanner.filter.N = 7;
	p.outliers.outlier_filter = OutlierFilterKind::None;
	p.sensor_pose = mrpt::poses::CPose3D(0.1, -0.2, 0.5, 0.3, 0, 0);
	p.threshold = 0.0625;
	RangefinderParams q;
	q.loadFromConfig(mrpt::config::CConfigFileMemory("[r]\n" + p.asIni()), "r");
	EXPECT_EQ(q.asIni(), p.asIni());
	EXPECT_NEAR(q.camera.forward_azimuth, 1.0, 1e-9);
	EXPECT_EQ(q.scanner.filter.N, 7);
	EXPECT_EQ(q.outliers.outlier_filter, OutlierFilterKind::None);
	EXPECT_NEAR(q.sensor_pose.y(), -0.2, 1e-12);
	// Every field appears once: one line per key.
	const std::string ini = p.asIni();
	EXPECT_EQ(static_cast<std::size_t>(std::count(ini.begin(), ini.end(), '\n')), RangefinderParams::table().keys().size());
}

TEST(OptionsTable, ARepeatedKeyIsAnErrorNamingTheLine)
{
	const std::string path = testing::TempDir() + "repeated.ini";
	std::ofstream(path) << "[rangefinder]\n; N twice\nN = 20\nthreshold = 0.1\n\n[other]\nN = 3\n[rangefinder]\nN = 5\n";
	try
	{
		requireNoRepeatedKeys(path);
		FAIL() << "a repeated key must not pass";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("repeated.ini:9: key 'N' repeats in [rangefinder] (first at line 3"),
				  std::string::npos)
			<< e.what();
	}
	std::ofstream(path) << "[a]\nN = 1\n[b]\nN = 2\n";
	EXPECT_NO_THROW(requireNoRepeatedKeys(path));  // the same key in two sections is fine
}

TEST(OptionsTable, AnUnknownSectionIsAnErrorNamingTheLine)
{
	const std::string path = testing::TempDir() + "sections.ini";
	std::ofstream(path) << "[omnicam]\nfov_deg = 1\n\n; a comment [not a section]\n[lazer]\nfov_deg = 180\n";
	try
	{
		requireOnlySections(path, {"omnicam", "laser"});
		FAIL() << "a misspelt section must not pass";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("sections.ini:5: unknown section [lazer] (this file has [omnicam], [laser])"),
				  std::string::npos)
			<< e.what();
	}
	std::ofstream(path) << "[laser]\nfov_deg = 1\n";
	EXPECT_NO_THROW(requireOnlySections(path, {"omnicam", "laser"}));
}

TEST(OptionsTable, KeysAreWrittenOnlyIntoAnIniEveryProgramReads)
{
	const std::string path = (std::filesystem::temp_directory_path() / "omnirange_writable.ini").string();
	const auto refusal = [&](const std::string& text) {
		std::ofstream(path) << text;
		try
		{
			RangefinderParams::requireWritable(path, "rangefinder");
			return std::string();
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
	};
	EXPECT_EQ(refusal("[rangefinder]\nthreshold = 0.1\n"), "");
	EXPECT_EQ(refusal("[other]\nx = 1\n"), "");  // the section is about to be written
	EXPECT_EQ(refusal("[rangefinder]\nR = 5000\n"), "");  // bounded by other keys (the image) only once whole
	for (const std::string bad : {"thresold = 0.1", "threshold = 0,1", "N = 0"})
	{
		const std::string why = refusal("[rangefinder]\n" + bad + "\n");
		EXPECT_EQ(why.rfind(path + ": ", 0), 0u) << why;
		EXPECT_NE(why.find(bad.substr(0, bad.find(' '))), std::string::npos) << why;
	}
	// An ini whose base does not load (missing, a loop, no file) is read by no program.
	const std::string base = path + ".base.ini";
	std::ofstream(base) << "[rangefinder]\nh = 0.9\n";
	EXPECT_EQ(refusal("base = " + base + "\n[rangefinder]\nthreshold = 0.1\n"), "");
	for (const std::string& bad : {base + ".missing", path, std::string("/dev/zero")})
	{
		const std::string why = refusal("base = " + bad + "\n[rangefinder]\nthreshold = 0.1\n");
		EXPECT_NE(why, "") << bad;
		EXPECT_NE(why.find(path), std::string::npos) << why;
	}
	std::filesystem::remove(base);
	std::filesystem::remove(path);
	EXPECT_NO_THROW(RangefinderParams::requireWritable(path, "rangefinder"));  // a new file
}
