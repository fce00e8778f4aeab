// Paths against the truth: the odometry read back from a rawlog, and the
// absolute trajectory error of paths whose error is known by construction.
#include <omnirange_eval/Trajectory.h>

#include <omnirange/config/SensorLabels.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>

using namespace omnirange;
using mrpt::poses::CPose2D;

namespace
{
// A rawlog of 11 steps along x, 1 m and 1 s apart: GT at the true pose,
// ODOMETRY at `odometry(true pose)`; in the test's temporary folder, removed
// when it goes.
struct StraightRun
{
	StraightRun(const std::string& name, const std::function<CPose2D(const CPose2D&)>& odometry);
	~StraightRun() { std::filesystem::remove(file); }
	std::string file;
};

StraightRun::StraightRun(const std::string& name, const std::function<CPose2D(const CPose2D&)>& odometry)
	: file(testing::TempDir() + name)
{
	mrpt::io::CFileGZOutputStream out(file);
	auto a = mrpt::serialization::archiveFrom(out);
	for (int i = 0; i <= 10; ++i)
	{
		const auto t = mrpt::Clock::fromDouble(1000.0 + i);
		const CPose2D truth(i, 0, 0);
		auto gt = mrpt::obs::CObservationRobotPose::Create();
		gt->sensorLabel = kGroundTruthLabel;
		gt->timestamp = t;
		gt->pose.mean = mrpt::poses::CPose3D(truth);
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->sensorLabel = kOdometryLabel;
		odo->timestamp = t;
		odo->odometry = odometry(truth);
		a << *gt << *odo;
	}
}
}  // namespace

TEST(Trajectory, OdometryOffByARigidMotionHasNoError)
{
	// Odometry starts in its own frame: the truth turned 30 degrees and moved.
	const CPose2D frame(2, -1, M_PI / 6);
	const StraightRun run("omnirange_rigid.rawlog", [&](const CPose2D& p) { return frame + p; });
	const auto& file = run.file;
	const auto odo = eval::odometryPath(file, kOdometryLabel);
	ASSERT_EQ(odo.size(), 11u);
	EXPECT_DOUBLE_EQ(odo[3].t - odo[0].t, 3.0);
	EXPECT_NEAR(odo[3].pose.x(), (frame + CPose2D(3, 0, 0)).x(), 1e-9);
	const auto e = eval::comparePaths(odo, eval::groundTruthPath(file, kGroundTruthLabel));
	EXPECT_NEAR(e.ate_rmse, 0, 1e-9);
	EXPECT_NEAR(e.final_xy, 0, 1e-9);
	EXPECT_NEAR(e.final_yaw, 0, 1e-9);
}

TEST(Trajectory, OdometryThatOverCountsDistanceHasItsKnownError)
{
	// 10 % too long: after the best alignment the residuals are 0.1 (x - 5)
	// for x = 0..10, whose RMS is 0.1 sqrt(10); started together, the path
	// ends 1 m too far.
	const StraightRun run("omnirange_scaled.rawlog", [](const CPose2D& p) { return CPose2D(1.1 * p.x(), 0, 0); });
	const auto& file = run.file;
	const auto e =
		eval::comparePaths(eval::odometryPath(file, kOdometryLabel), eval::groundTruthPath(file, kGroundTruthLabel));
	EXPECT_EQ(e.poses, 11);
	EXPECT_NEAR(e.ate_rmse, 0.1 * std::sqrt(10.0), 1e-6);
	EXPECT_NEAR(e.final_xy, 1.0, 1e-6);
}

TEST(Trajectory, AnAbsentOdometryLabelIsRefusedNamingItAndTheFile)
{
	const StraightRun run("omnirange_noodo.rawlog", [](const CPose2D& p) { return p; });
	const auto& file = run.file;
	try
	{
		eval::odometryPath(file, "WHEELS");
		FAIL() << "no error";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("no WHEELS odometry"), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
	}
}
