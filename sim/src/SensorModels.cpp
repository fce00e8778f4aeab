#include "omnirange_sim/SensorModels.h"

#include <omnirange/config/SensorLabels.h>

#include <cmath>

namespace omnirange::sim
{
mrpt::obs::CObservation2DRangeScan::Ptr simulateLaser(
	const World& world, const LaserSimParams& L, const Pose2& robot, std::mt19937_64& rng)
{
	auto obs = mrpt::obs::CObservation2DRangeScan::Create();
	obs->sensorLabel = kLaserLabel;
	obs->sensorPose = L.pose;
	obs->aperture = static_cast<float>(L.fov);
	obs->rightToLeft = true;
	obs->maxRange = static_cast<float>(L.max_range);
	obs->stdError = static_cast<float>(L.sigma);
	obs->resizeScan(L.rays);

	const double c = std::cos(robot.yaw), s = std::sin(robot.yaw);
	const Vec2 origin{robot.x + c * L.pose.x() - s * L.pose.y(), robot.y + s * L.pose.x() + c * L.pose.y()};
	const double z = L.pose.z();
	std::normal_distribution<double> noise(0.0, L.sigma);
	std::vector<SolidCrossing> hits;
	for (int i = 0; i < L.rays; ++i)
	{
		const double a = robot.yaw + L.pose.yaw() - 0.5 * L.fov + i * L.fov / (L.rays - 1);
		world.castRay(origin, {std::cos(a), std::sin(a)}, L.max_range, hits);
		double range = -1;
		for (const auto& h : hits)
		{
			const Solid& solid = world.solids[h.solid];
			if (z >= solid.z0 && z <= solid.z1 && h.crossing.t_in > 0)
			{
				range = h.crossing.t_in;
				break;
			}
		}
		const double noisy = range + (L.sigma > 0 ? noise(rng) : 0.0);
		const bool valid = range > 0 && noisy < L.max_range;
		obs->setScanRange(i, static_cast<float>(valid ? std::max(0.0, noisy) : L.max_range));
		obs->setScanRangeValidity(i, valid);
	}
	return obs;
}

mrpt::obs::CObservationOdometry::Ptr OdometrySimulator::step(const Pose2& t)
{
	if (started_)
	{
		// The true increment in the previous pose's frame, made noisy.
		const mrpt::poses::CPose2D a(last_truth_.x, last_truth_.y, last_truth_.yaw);
		const mrpt::poses::CPose2D b(t.x, t.y, t.yaw);
		const mrpt::poses::CPose2D d = b - a;
		const double dist = std::hypot(d.x(), d.y());
		std::normal_distribution<double> n(0.0, 1.0);
		const double k = 1.0 + p_.sigma_dist * n(rng_);
		const double dphi = d.phi() * (1.0 + p_.sigma_turn * n(rng_)) +
			p_.yaw_drift * dist + p_.sigma_turn * 0.05 * dist * n(rng_);
		odo_ = odo_ + mrpt::poses::CPose2D(d.x() * k, d.y() * k, dphi);
	}
	started_ = true;
	last_truth_ = t;
	auto obs = mrpt::obs::CObservationOdometry::Create();
	obs->sensorLabel = kOdometryLabel;
	obs->odometry = odo_;
	return obs;
}

mrpt::obs::CObservationRobotPose::Ptr groundTruth(const Pose2& t)
{
	auto obs = mrpt::obs::CObservationRobotPose::Create();
	obs->sensorLabel = kGroundTruthLabel;
	obs->pose.mean = mrpt::poses::CPose3D(t.x, t.y, 0, t.yaw, 0, 0);
	obs->pose.cov.setZero();
	return obs;
}

}  // namespace omnirange::sim
