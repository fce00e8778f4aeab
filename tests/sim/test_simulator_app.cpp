// The whole simulator: its rawlog passes the real `rawlog-edit --info` with
// the expected count per label; bad input leaves nothing behind.
#include "SimFixtures.h"

#include <omnirange_sim/Simulator.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace omnirange::sim;
namespace fs = std::filesystem;

namespace
{
const std::string kSource = OMNIRANGE_SOURCE_DIR;

std::string run(const std::string& cmd)
{
	std::string out;
	FILE* p = ::popen((cmd + " </dev/null 2>&1").c_str(), "r");
	char buf[4096];
	while (p && std::fgets(buf, sizeof buf, p)) out += buf;
	if (p) ::pclose(p);
	return out;
}
}  // namespace

TEST(SimulatorApp, RawlogPassesRawlogEditInfo)
{
	const std::string out = test::tempDir() + "/factory10.rawlog";
	SimOptions o;
	o.world_file = kSource + "/worlds/factory.world";
	o.route_file = kSource + "/worlds/factory.route";
	o.robot_ini = kSource + "/ini/robot-omnip2dx.ini";
	o.output = out;
	o.max_frames = 10;
	Simulator sim;
	sim.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	const auto s = sim.run(o);
	EXPECT_EQ(s.frames, 10);
	EXPECT_TRUE(fs::exists(test::tempDir() + "/factory10_Images/factory10_OMNICAM_000009.jpg"));
	EXPECT_TRUE(fs::exists(test::tempDir() + "/factory10_truemap.png"));
	EXPECT_TRUE(fs::exists(test::tempDir() + "/factory10_truemap.gridmap.gz"));

	const std::string info = run("rawlog-edit --info -i '" + out + "'");
	for (const std::string label : {"OMNICAM", "LASER", "ODOMETRY", "GT", "TRUTH", "BODY"})
	{
		const std::regex row(label + R"(\s*/\s*(\d+)\s*/)");
		std::smatch m;
		ASSERT_TRUE(std::regex_search(info, m, row)) << info;
		EXPECT_EQ(m[1], "10") << label;
	}
	EXPECT_NE(info.find("Overall number of objects         : 60"), std::string::npos) << info;
	EXPECT_NE(info.find("Observations format               : Yes"), std::string::npos) << info;
}

TEST(SimulatorApp, ImpossibleFrameAndThreadCountsAreRefused)
{
	SimOptions o;
	o.world_file = kSource + "/worlds/factory.world";
	o.route_file = kSource + "/worlds/factory.route";
	o.output = test::tempDir() + "/refused.rawlog";
	Simulator sim;
	sim.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	o.max_frames = -1;  // once ran the whole route
	EXPECT_THROW(sim.run(o), std::invalid_argument);
	o.max_frames = 1;
	o.threads = 70000;  // once crashed at exit
	EXPECT_THROW(sim.run(o), std::invalid_argument);
	EXPECT_FALSE(fs::exists(o.output));
	// An output onto an input (here the world file, once destroyed) is refused before any work.
	o.threads = 2;
	o.world_file = test::writeFile("own.world", test::roomWorld());
	o.output = o.world_file;
	EXPECT_THROW(sim.run(o), std::runtime_error);
	EXPECT_EQ(loadWorld(o.world_file).solids.size(), 2u);
}

TEST(SimulatorApp, BadInputLeavesNoOutput)
{
	const std::string out = test::tempDir() + "/never.rawlog";
	SimOptions o;
	o.world_file = test::writeFile("room.world", test::roomWorld());
	o.route_file = test::writeFile("through.route", "0 0\n4 0\n");
	o.output = out;
	Simulator sim;
	EXPECT_THROW(sim.run(o), std::runtime_error);
	o.route_file = test::writeFile("fine.route", "0 0\n1.5 0\n");
	o.robot_ini = test::writeFile("bad.ini", "[laser]\nrays = 1\n");
	try
	{
		sim.run(o);
		ADD_FAILURE() << "accepted rays = 1";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("bad.ini"), std::string::npos) << e.what();
	}
	o.robot_ini = test::writeFile("typo.ini", "[robot]\nsped = 1\n");
	EXPECT_THROW(sim.run(o), std::runtime_error);
	EXPECT_FALSE(fs::exists(out));
	EXPECT_FALSE(fs::exists(test::tempDir() + "/never_Images"));
}

TEST(SimulatorApp, ARobotIniOverABaseIsTheBaseWithItsOwnKeys)
{
	// `base = robot-hyperbolic.ini` and one key: the hyperbolic camera, not the code's default one.
	const std::string dir = testing::TempDir() + "robot_base";
	fs::create_directories(dir);
	std::ofstream(dir + "/mine.ini") << "base = " << kSource << "/ini/robot-hyperbolic.ini\n[laser]\nsigma = 0.02\n";
	const RobotParams mine = RobotParams::loadFile(dir + "/mine.ini");
	const RobotParams hyperbolic = RobotParams::loadFile(kSource + "/ini/robot-hyperbolic.ini");
	EXPECT_EQ(mine.omnicam.camera.mirror_model, omnirange::MirrorModel::Mei);
	EXPECT_EQ(mine.omnicam.camera.xi, hyperbolic.omnicam.camera.xi);
	EXPECT_DOUBLE_EQ(mine.laser.sigma, 0.02);
	// A base that is not there is an error naming it, not the defaults.
	std::ofstream(dir + "/lost.ini") << "base = nothere.ini\n[laser]\nsigma = 0.02\n";
	try
	{
		RobotParams::loadFile(dir + "/lost.ini");
		ADD_FAILURE() << "a missing base was read as the defaults";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("nothere.ini"), std::string::npos) << e.what();
	}
}
