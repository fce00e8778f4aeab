#pragma once
// Small worlds written by the tests into a temporary folder.

#include <omnirange_sim/RobotParams.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace omnirange::sim::test
{
/** A folder of this process's own: ctest runs tests in parallel processes,
 * and two writing "room.world" into one folder would race. */
inline std::string tempDir()
{
	static const std::string d = [] {
		const std::string p = testing::TempDir() + "omnirange_sim_tests/" + std::to_string(::getpid());
		std::filesystem::create_directories(p);
		return p;
	}();
	return d;
}

inline std::string writeFile(const std::string& name, const std::string& text)
{
	const std::string path = tempDir() + "/" + name;
	std::ofstream(path) << text;
	return path;
}

/** A room: a red wall 2 m ahead of the origin (x = 2), a blue one 1.5 m to
 * the left (y = 1.5), grey floor, nothing else within 6 m. */
inline std::string roomWorld()
{
	return "omnirange-world 1\nname room\nbounds xmin=-6 ymin=-6 xmax=6 ymax=6\n"
		   "floor material=concrete\n"
		   "box x=2.5 y=0 w=1.0 d=4 z1=2 material=paint_red\n"
		   "box x=0 y=2.0 w=1.5 d=1.0 z1=2 material=paint_blue\n";
}

/** The stock robot without sensor noise: images that tests can compare pixel by pixel. */
inline RobotParams quietRobot()
{
	RobotParams r;
	r.omnicam.noise_sigma = 0;
	return r;
}

}  // namespace omnirange::sim::test
