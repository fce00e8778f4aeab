// The produced data in MRPT's own programs: rawlog-edit counts the scans,
// icp-slam builds a map and a path from them (and follows the odometry down a
// synthetic featureless corridor with the omnicam's ini), rawlog-grabber runs
// the sensor plugin.
#include "Programs.h"

#include "../common/DrawnScans.h"

#include <omnirange_eval/SensoryFrameFormat.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <fstream>
#include <regex>

using namespace omnirange::e2e;
namespace fs = std::filesystem;

namespace
{
/** icp-slam (the real program) on `only` (OMNISCAN scans, in `dir`): the
 * sample drives 8 s at 0.4 m/s straight ahead; odometry drifts, ICP must
 * keep the path straight and about that long. */
void expectIcpSlamKeepsTheSamplesStraightPath(const std::string& dir, const std::string& only)
{
	const RunResult icp = run("icp-slam " + q(kSource + "/ini/icp-slam-omniscan.ini") + " " + q(only), dir);
	ASSERT_EQ(icp.code, 0) << icp.out;
	const auto path = readTable(dir + "/icp_slam_omniscan/log_estimated_path.txt");
	ASSERT_GE(path.size(), 20u);
	const auto& last = path.back();
	EXPECT_NEAR(std::hypot(last[1], last[2]), 0.4 * 7.6, 0.6);
	EXPECT_LT(std::abs(last[3]), 0.1);
}
/** A straight corridor 2.4 m wide, walls without features, driven 12 m along
 * its axis in steps of 0.16 m, 0.4 s apart: each step an exact odometry
 * reading and a 360-ray scan that, like the omnicam's, sees 3.8 m at most. */
void writeCorridorRun(const std::string& file)
{
	const std::vector<omnirange::test::Wall> corridor{{-50, -1.2, 50, -1.2}, {-50, 1.2, 50, 1.2}};
	omnirange::test::writeDrive(
		file, 76, [](int k) { return mrpt::poses::CPose2D(0.16 * k, 0, 0); },
		[&](int k, double t) {
			return omnirange::test::drawScan(corridor, mrpt::poses::CPose2D(0.16 * k, 0, 0), t, omnirange::scanAperture(360));
		},
		0.4);
}

/** Where icp-slam's path ends along the corridor, with the omnicam's ini
 * and `onlyUniqueRobust` as given. */
double icpSlamDistanceAlongCorridor(const std::string& dir, bool unique_pairs)
{
	std::ifstream in(kSource + "/ini/icp-slam-omniscan.ini");
	std::stringstream ini;
	ini << in.rdbuf();
	const std::string text = std::regex_replace(ini.str(), std::regex("onlyUniqueRobust = \\w+"),
												std::string("onlyUniqueRobust = ") + (unique_pairs ? "true" : "false"));
	EXPECT_NE(text.find(unique_pairs ? "onlyUniqueRobust = true" : "onlyUniqueRobust = false"), std::string::npos);
	std::ofstream(dir + "/icp.ini") << text;
	const RunResult icp = run("icp-slam icp.ini corridor.rawlog", dir);
	EXPECT_EQ(icp.code, 0) << icp.out;
	const auto path = readTable(dir + "/icp_slam_omniscan/log_estimated_path.txt");
	return path.empty() ? 0.0 : path.back()[1];
}
}  // namespace

TEST(MrptPrograms, IcpSlamFollowsTheOdometryDownAFeaturelessCorridor)
{
	// Walls parallel to the motion say nothing about it, so the matcher
	// should leave the (here exact) odometry's 12 m alone. The map ends where
	// the last keyframe's 3.8 m ended; with MRPT's default pairing the scan
	// points past that end all pair with its last points and pull the robot
	// back, and the path stalls. The shipped ini pairs each map point with
	// one scan point (docs/method.md, section 7).
	const std::string dir = workDir("icp_slam_corridor");
	writeCorridorRun(dir + "/corridor.rawlog");
	EXPECT_NEAR(icpSlamDistanceAlongCorridor(dir, true), 12.0, 0.3);  // measured 11.92 m
	EXPECT_LT(icpSlamDistanceAlongCorridor(dir, false), 6.0);  // measured 0.46 m
}

TEST(MrptPrograms, RawlogEditCountsTheOmniscans)
{
	const std::string dir = workDir("rawlog_edit");
	const std::string scanned = scannedFactorySample(dir);
	const RunResult info = run("rawlog-edit --info -i " + q(scanned));
	ASSERT_EQ(info.code, 0) << info.out;
	EXPECT_EQ(labelCount(info.out, "OMNISCAN"), 20) << info.out;
	EXPECT_EQ(labelCount(info.out, "OMNICAM"), 20) << info.out;
	EXPECT_EQ(labelCount(info.out, "LASER"), 20) << info.out;
	// Every scan comes right after its image.
	const RunResult list = run("cd " + q(dir) + " && rawlog-edit --list-timestamps -i scanned.rawlog >/dev/null && cat out.txt");
	ASSERT_EQ(list.code, 0) << list.out;
	std::istringstream in(list.out);
	std::string prev, line;
	int after_image = 0;
	while (std::getline(in, line))
	{
		if (line.find("OMNISCAN") != std::string::npos && prev.find("OMNICAM") != std::string::npos) ++after_image;
		prev = line;
	}
	EXPECT_EQ(after_image, 20) << list.out.substr(0, 2000);
}

TEST(MrptPrograms, IcpSlamMapsTheOmniscans)
{
	const std::string dir = workDir("icp_slam");
	const std::string scanned = scannedFactorySample(dir);
	const RunResult keep = run("cd " + q(dir) + " && rawlog-edit --keep-label OMNISCAN,ODOMETRY -i scanned.rawlog -o only.rawlog -w");
	ASSERT_EQ(keep.code, 0) << keep.out;
	expectIcpSlamKeepsTheSamplesStraightPath(dir, "only.rawlog");
	EXPECT_TRUE(fs::exists(dir + "/icp_slam_omniscan/_finalmaps_.txt_mrpt__maps__COccupancyGridMap2D_00.png"));
}

TEST(MrptPrograms, ObservationsToMapReadsOmnirangeSlamsKeyframes)
{
	// omnirange-slam writes icp-slam's kind of outputs: its keyframes must be
	// a simplemap that MRPT's observations2map turns into a grid map, and its
	// path must follow the sample's straight 3 m as icp-slam's does.
	const std::string dir = workDir("omnirange_slam");
	scannedFactorySample(dir);
	const RunResult keep = run("rawlog-edit --keep-label OMNISCAN,ODOMETRY -i scanned.rawlog -o only.rawlog -w", dir);
	ASSERT_EQ(keep.code, 0) << keep.out;
	const RunResult slam =
		run(app("omnirange-slam") + " -i only.rawlog -c " + q(kSource + "/ini/icp-slam-omniscan.ini") + " -o slam", dir);
	ASSERT_EQ(slam.code, 0) << slam.out;
	const auto path = readTable(dir + "/slam/log_estimated_path.txt");
	ASSERT_GE(path.size(), 20u);
	EXPECT_NEAR(std::hypot(path.back()[1], path.back()[2]), 0.4 * 7.6, 0.6);
	EXPECT_LT(std::abs(path.back()[3]), 0.1);
	const RunResult map = run("observations2map " + q(kSource + "/ini/observations2map-omniscan.ini") +
								  " slam/_finalmap_.simplemap slam/map",
							  dir);
	ASSERT_EQ(map.code, 0) << map.out;
	const std::string png = dir + "/slam/map_mrpt__maps__COccupancyGridMap2D_00.png";
	ASSERT_TRUE(fs::exists(png)) << map.out;
	// The grid holds walls and the free floor between them, not only unknown.
	mrpt::maps::COccupancyGridMap2D grid;
	mrpt::io::CFileGZInputStream in(dir + "/slam/map_gridmap_no00.gridmap");
	mrpt::serialization::archiveFrom(in) >> grid;
	int occupied = 0, free = 0;
	for (unsigned y = 0; y < grid.getSizeY(); ++y)
		for (unsigned x = 0; x < grid.getSizeX(); ++x)
		{
			const float p = grid.getCell(x, y);  // probability of free
			occupied += p < 0.4f;
			free += p > 0.6f;
		}
	EXPECT_GT(occupied, 100);
	EXPECT_GT(free, 2000);
}

TEST(MrptPrograms, IcpSlamMapsASensoryFrameRawlogScannedInItsOwnFormat)
{
	// The actions/sensory-frames format, scanned: icp-slam reads the
	// odometry from the actions and the omnicam scans from the frames.
	const std::string dir = workDir("icp_slam_sf");
	ASSERT_EQ(omnirange::eval::writeSensoryFrameFormat(kSource + "/rawlogs/factory-sample.rawlog", dir + "/sf.rawlog"), 20);
	const std::string ini = kSource + "/ini/factory.ini";
	const RunResult t = run(app("omnirange-train") + " -q -i sf.rawlog -c " + q(ini) + " -o f.hist", dir);
	ASSERT_EQ(t.code, 0) << t.out;
	const RunResult s = run(app("omnirange-scan") + " -q -i sf.rawlog -c " + q(ini) + " -H f.hist -o scanned.rawlog", dir);
	ASSERT_EQ(s.code, 0) << s.out;
	const RunResult info = run("rawlog-edit --info -i scanned.rawlog", dir);
	ASSERT_EQ(info.code, 0) << info.out;
	EXPECT_EQ(labelCount(info.out, "OMNISCAN"), 20) << info.out;
	const RunResult keep = run("rawlog-edit --keep-label OMNISCAN -i scanned.rawlog -o only.rawlog -w", dir);
	ASSERT_EQ(keep.code, 0) << keep.out;
	expectIcpSlamKeepsTheSamplesStraightPath(dir, "only.rawlog");
}

TEST(MrptPrograms, RawlogGrabberRunsTheSensorPlugin)
{
	const std::string dir = workDir("grabber");
	const RunResult t = run(app("omnirange-train") + " -q -i " + q(kSource + "/rawlogs/factory-sample.rawlog") + " -c " +
					  q(kSource + "/ini/factory.ini") + " -o " + q(dir + "/f.hist"));
	ASSERT_EQ(t.code, 0) << t.out;
	std::ofstream(dir + "/grab.ini")
		<< "[global]\nrawlog_prefix = " << dir << "/grabbed\ntime_between_launches = 300\n"
		<< "use_sensoryframes = 0\nGRABBER_PERIOD_MS = 100\n\n"
		<< "[OMNIRANGE]\ndriver = COmniRangefinderSensor\nprocess_rate = 20\nhistogram_file = " << dir
		<< "/f.hist\nthreshold = 0.075\ncamera_grabber_type = image_dir\ncamera_image_dir_url = " << kSource
		<< "/rawlogs/factory-sample_Images\ncamera_left_format = factory-sample_OMNICAM_%06d.jpg\n"
		<< "camera_start_index = 0\ncamera_end_index = 19\ncamera_sensorLabel = OMNICAM\n";
	// rawlog-grabber quits at the end of its input: keep it open while the
	// 20 frames replay (the sensor stops at the last one).
	const RunResult g = run("cd " + q(dir) + " && sleep 8 | rawlog-grabber -p " + q(kPlugin) + " grab.ini");
	std::string grabbed;
	for (const auto& e : fs::directory_iterator(dir))
		if (e.path().extension() == ".rawlog") grabbed = e.path().string();
	ASSERT_FALSE(grabbed.empty()) << g.out;
	const RunResult info = run("rawlog-edit --info -i " + q(grabbed));
	const int images = labelCount(info.out, "OMNICAM"), scans = labelCount(info.out, "OMNISCAN");
	EXPECT_GE(scans, 15) << info.out << g.out.substr(0, 3000);
	EXPECT_LE(scans, images);  // every scan comes with its image
}
