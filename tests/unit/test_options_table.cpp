// The options tables: strict values, renamed and unknown keys named, angles
// in degrees in the ini and radians in memory, printing that loads back.
#include <omnirange/core/Rangefinder.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <cmath>
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
	EXPECT_NE(loadError("N = 0").find("[rangefinder] N (false-positive filter)"), std::string::npos);
	EXPECT_NE(loadError("N = 2147483647").find("N (false-positive filter) must be within"), std::string::npos);
	EXPECT_NE(loadError("outlier_max_width = 2147483647").find("outlier_max_width"), std::string::npos);
	EXPECT_NE(loadError("scanlines = 1000000000").find("scanlines must be within"), std::string::npos);
}

TEST(OptionsTable, OldAndUnknownKeysAreNamed)
{
	const std::string old = loadError("forward_azimuth = 3.14159");
	EXPECT_NE(old.find("forward_azimuth_deg"), std::string::npos) << old;
	EXPECT_NE(loadError("threshhold = 0.1").find("unknown key 'threshhold'"), std::string::npos);
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
