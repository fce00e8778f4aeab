#pragma once
// Robot paths: ground truth and odometry from a rawlog, keyframes estimated by
// a SLAM engine, and the absolute trajectory error between them.

#include <omnirange_slam/StampedPose.h>

#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace omnirange::eval
{
using slam::StampedPose;

/** Every GT (CObservationRobotPose) pose of a rawlog, in time order. */
std::vector<StampedPose> groundTruthPath(const std::string& rawlog, const std::string& label);

/** Every odometry (CObservationOdometry) pose of a rawlog, in time order: the
 * path dead reckoning alone gives, which a scan matcher should improve on. */
std::vector<StampedPose> odometryPath(const std::string& rawlog, const std::string& label);

/** The pose of `path` at time t (the nearest sample). */
mrpt::poses::CPose2D poseAt(const std::vector<StampedPose>& path, double t);

/** Keyframes of a SLAM engine's simplemap: estimated pose, time of its first observation. */
std::vector<StampedPose> simplemapKeyframes(const mrpt::maps::CSimpleMap& map);
mrpt::maps::CSimpleMap loadSimplemap(const std::string& file);

struct PathError
{
	int poses{0};
	double ate_rmse{0};  ///< [m] after the best rigid alignment
	double final_xy{0};  ///< [m] last pose, after aligning the first poses
	double final_yaw{0};  ///< [rad]
	mrpt::poses::CPose2D alignment;  ///< estimated frame -> ground-truth frame (best fit)
};

/** An engine whose path error is above the wheels' alone lost its way: its
 * figure says nothing fair about the sensor, and reports flag it. */
inline bool worseThanOdometry(double engine_ate, double odometry_ate) { return engine_ate > odometry_ate; }
inline constexpr const char* kWorseThanOdometry = " (worse than odometry)";

/** Compares estimated poses with the ground truth at the same times. */
PathError comparePaths(const std::vector<StampedPose>& estimated, const std::vector<StampedPose>& truth);

}  // namespace omnirange::eval
