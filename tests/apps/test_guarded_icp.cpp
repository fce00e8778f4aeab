// The odometry-guarded matcher: what a scan can fix and what it cannot, and
// the guard's refusal, on scans drawn from walls whose places are known.
#include <omnirange_apps/SlamApp.h>
#include <omnirange_slam/GuardedIcp.h>
#include <omnirange_eval/SensoryFrameFormat.h>
#include <omnirange_eval/Trajectory.h>

#include "../common/DrawnScans.h"

#include <omnirange/config/SensorLabels.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

using namespace omnirange;
using namespace omnirange::eval;
using namespace omnirange::slam;
using mrpt::poses::CPose2D;

namespace
{
using namespace omnirange::test;

Eigen::Vector2d eigenvalues(const Eigen::Matrix2d& m) { return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(m).eigenvalues(); }
}  // namespace

TEST(GuardedIcp, ACorridorFixesOnlyTheDirectionAcrossIt)
{
	// The robot turned 0.3 rad: in its frame the corridor runs at -0.3 rad.
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> corridor(
		translationInformation(*drawScan(kCorridor, CPose2D(0, 0, 0.3), 0)));
	EXPECT_LT(corridor.eigenvalues()[0], 0.02 * corridor.eigenvalues()[1]);  // along the corridor: nothing
	EXPECT_GT(std::abs(corridor.eigenvectors().col(0).dot(Eigen::Vector2d(std::cos(0.3), -std::sin(0.3)))), 0.999);
	const Eigen::Vector2d room = eigenvalues(translationInformation(*drawScan(kRoom, CPose2D(0.3, -0.2, 0.5), 0)));
	EXPECT_GT(room[0], 0.3 * room[1]);  // four walls: both directions
}

TEST(GuardedIcp, TheCorrectionAlongAWeakDirectionIsDropped)
{
	const Eigen::Matrix2d corridor = translationInformation(*drawScan(kCorridor, CPose2D(), 0));
	int weak = 0;
	const auto kept = keepConstrainedCorrection({1, 0, 0}, {1.3, 0.05, 0}, corridor, 0.1, weak);
	EXPECT_NEAR(kept.x, 1.0, 1e-3);  // the odometry's, along the corridor
	EXPECT_NEAR(kept.y, 0.05, 1e-3);  // the match's, across it
	EXPECT_EQ(weak, 1);
	const Eigen::Matrix2d room = translationInformation(*drawScan(kRoom, CPose2D(), 0));
	weak = 0;
	const auto all = keepConstrainedCorrection({1, 0, 0}, {1.3, 0.05, 0.02}, room, 0.1, weak);
	EXPECT_NEAR(all.x, 1.3, 1e-3);
	EXPECT_NEAR(all.y, 0.05, 1e-3);
	EXPECT_NEAR(all.phi, 0.02, 1e-9);  // the heading is always the match's
	EXPECT_EQ(weak, 0);
}

TEST(GuardedIcp, ScansCorrectWheelsThatReadLong)
{
	// The wheels read 10 % long across a room; the room's walls fix every
	// direction, so the matches must bring the path back to the truth.
	const auto truth = [](int i) { return CPose2D(-1.2 + 0.1 * i, 0.1, 0); };
	const Drive d("guarded_long_wheels.rawlog", 25, [&](int i) { return CPose2D(-1.2 + 0.11 * i, 0.1, 0); },
				  [&](int i, double t) { return drawScan(kRoom, truth(i), t); });
	const GuardedIcpResult r = runGuardedIcp(d.file, "OMNISCAN", kOdometryLabel, GuardedIcpOptions{});
	ASSERT_EQ(r.path.size(), 25u);
	// A match every 0.2 m of odometry (the ini's localizationLinDistance):
	// between two, the wheels' 1 cm per step adds up again, to 3 cm at most.
	double worst = 0;
	for (int i = 0; i < 25; ++i)
	{
		const CPose2D p = CPose2D(-1.2, 0.1, 0) + r.path[i].pose;  // the path starts at the origin
		worst = std::max(worst, std::hypot(p.x() - truth(i).x(), p.y() - truth(i).y()));
	}
	EXPECT_LT(worst, 0.04);  // the wheels alone: 0.24 m at the end
	EXPECT_GT(r.matches, 5);
	EXPECT_EQ(r.refused_jumps, 0);
}

TEST(GuardedIcp, InACorridorTheWheelsKeepTheLength)
{
	// Exact wheels down a corridor whose end is out of sight: no scan can say
	// how far the robot went, so the path must be the wheels' along it.
	const auto truth = [](int i) { return CPose2D(0.1 * i, 0.2, 0); };
	const Drive d("guarded_corridor.rawlog", 40, truth, [&](int i, double t) { return drawScan(kCorridor, truth(i), t); });
	const GuardedIcpResult r = runGuardedIcp(d.file, "OMNISCAN", kOdometryLabel, GuardedIcpOptions{});
	const CPose2D end = truth(0) + r.path.back().pose;
	EXPECT_NEAR(end.x(), truth(39).x(), 0.005);
	EXPECT_NEAR(end.y(), 0.2, 0.01);
	EXPECT_GT(r.weak_directions, 5);
}

TEST(GuardedIcp, AMatchThatJumpsFartherThanTheWheelsCanErrIsRefused)
{
	// One scan is drawn 0.4 m to the side of where the (exact) wheels put the
	// robot: what a match on the wrong wall does. Unguarded, the path jumps;
	// guarded, it stays on the wheels' estimate.
	const auto truth = [](int i) { return CPose2D(-1.0 + 0.25 * i, 0, 0); };
	const auto scans = [&](int i, double t) { return drawScan(kRoom, i == 5 ? truth(i) + CPose2D(0, 0.4, 0) : truth(i), t); };
	const Drive d("guarded_jump.rawlog", 9, truth, scans);
	const GuardedIcpResult guarded = runGuardedIcp(d.file, "OMNISCAN", kOdometryLabel, GuardedIcpOptions{});
	EXPECT_EQ(guarded.refused_jumps, 1);
	EXPECT_NEAR(guarded.path[5].pose.y(), 0.0, 0.01);
	GuardedIcpOptions open;
	open.max_jump = 10;
	const GuardedIcpResult unguarded = runGuardedIcp(d.file, "OMNISCAN", kOdometryLabel, open);
	EXPECT_EQ(unguarded.refused_jumps, 0);
	EXPECT_GT(std::abs(unguarded.path[5].pose.y()), 0.3);
}

TEST(GuardedIcp, TheSensoryFrameFormatGivesTheSamePath)
{
	// The same drive rewritten in MRPT's other format, the odometry as each
	// frame's movement action: the matcher must read it and find the same path.
	const auto truth = [](int i) { return CPose2D(-1.2 + 0.1 * i, 0.1, 0.02 * i); };
	const Drive d("guarded_observations.rawlog", 25, [&](int i) { return CPose2D(-1.2 + 0.11 * i, 0.1, 0.02 * i); },
				  [&](int i, double t) { return drawScan(kRoom, truth(i), t); });
	const std::string frames = testing::TempDir() + "guarded_frames.rawlog";
	ASSERT_EQ(writeSensoryFrameFormat(d.file, frames), 25);
	const GuardedIcpResult a = runGuardedIcp(d.file, "OMNISCAN", kOdometryLabel, GuardedIcpOptions{});
	const GuardedIcpResult b = runGuardedIcp(frames, "OMNISCAN", kOdometryLabel, GuardedIcpOptions{});
	std::filesystem::remove(frames);
	ASSERT_EQ(b.path.size(), a.path.size());
	EXPECT_EQ(b.matches, a.matches);
	EXPECT_GT(a.matches, 5);
	for (std::size_t i = 0; i < a.path.size(); ++i)
	{
		EXPECT_NEAR(b.path[i].pose.x(), a.path[i].pose.x(), 1e-6) << i;
		EXPECT_NEAR(b.path[i].pose.y(), a.path[i].pose.y(), 1e-6) << i;
		EXPECT_NEAR(b.path[i].pose.phi(), a.path[i].pose.phi(), 1e-6) << i;
	}
}

TEST(GuardedIcp, ARawlogWithoutOdometryIsRefused)
{
	const std::string file = testing::TempDir() + "guarded_no_odometry.rawlog";
	{
		mrpt::io::CFileGZOutputStream out(file);
		auto a = mrpt::serialization::archiveFrom(out);
		a << *drawScan(kRoom, CPose2D(), 1000) << *drawScan(kRoom, CPose2D(0.3, 0, 0), 1001);
	}
	EXPECT_THROW(runGuardedIcp(file, "OMNISCAN", kOdometryLabel, GuardedIcpOptions{}), std::runtime_error);
	std::filesystem::remove(file);
}

TEST(GuardedIcp, TheAppWritesAPathAndKeyframesAsIcpSlamDoes)
{
	const auto truth = [](int i) { return CPose2D(-1.2 + 0.1 * i, 0.1, 0); };
	const Drive d("guarded_app.rawlog", 25, truth, [&](int i, double t) { return drawScan(kRoom, truth(i), t); });
	const std::string dir = testing::TempDir() + "guarded_app_out", ini = testing::TempDir() + "guarded_app.ini";
	std::filesystem::remove_all(dir);
	std::ofstream(ini) << "[MappingApplication]\ninsertionLinDistance = 0.5\n[odometry_guard]\nmax_jump = 0.05\n";
	app::SlamApp::Options o;
	o.input = d.file, o.ini = ini, o.output = dir, o.verbosity = mrpt::system::LVL_ERROR;
	const GuardedIcpResult r = app::SlamApp(o).run();
	std::ifstream path(dir + "/log_estimated_path.txt");
	std::string line;
	int rows = 0;
	while (std::getline(path, line))
		if (!line.empty() && line[0] != '%') ++rows;
	EXPECT_EQ(rows, 25);  // one pose per scan
	const auto keyframes = simplemapKeyframes(loadSimplemap(dir + "/_finalmap_.simplemap"));
	EXPECT_EQ(keyframes.size(), r.keyframes.size());
	EXPECT_GE(keyframes.size(), 5u);  // every 0.5 m of 2.4 m, and the first
	// A negative distance in the guard's section is refused, naming the key.
	std::ofstream(ini) << "[odometry_guard]\nmax_jump = -1\n";
	try
	{
		app::SlamApp(o).run();
		ADD_FAILURE() << "a negative max_jump was accepted";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("max_jump"), std::string::npos) << e.what();
	}
	std::filesystem::remove_all(dir);
	std::filesystem::remove(ini);
}
