#pragma once
// The laser, the odometry and the ground truth of the simulated robot, as the
// MRPT observations a real robot's rawlog holds.

#include <omnirange_sim/RobotParams.h>
#include <omnirange_sim/Route.h>
#include <omnirange_sim/World.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/poses/CPose2D.h>

#include <random>

namespace omnirange::sim
{
/** A planar laser scan: the first solid at the laser's height along each ray,
 * with Gaussian range noise; no return within max range is invalid. */
mrpt::obs::CObservation2DRangeScan::Ptr simulateLaser(
	const World& world, const LaserSimParams& laser, const Pose2& robot, std::mt19937_64& rng);

/** Integrates ground-truth increments with noise and a systematic yaw drift,
 * like wheel odometry. Starts at (0, 0, 0). */
class OdometrySimulator
{
   public:
	OdometrySimulator(const OdometrySimParams& p, std::uint64_t seed) : p_(p), rng_(seed) {}
	mrpt::obs::CObservationOdometry::Ptr step(const Pose2& truth);

   private:
	OdometrySimParams p_;
	std::mt19937_64 rng_;
	bool started_{false};
	Pose2 last_truth_;
	mrpt::poses::CPose2D odo_;
};

/** The ground-truth pose as a CObservationRobotPose. */
mrpt::obs::CObservationRobotPose::Ptr groundTruth(const Pose2& truth);

}  // namespace omnirange::sim
