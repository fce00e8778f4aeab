#include "omnirange_sim/FloorTruth.h"

#include <omnirange/core/PolarScanner.h>
#include <omnirange/config/SensorLabels.h>

#include <cmath>
#include <limits>

namespace omnirange::sim
{
double hiddenFloorDistance(const World& world, const std::vector<SolidCrossing>& crossings, double h)
{
	// The sight line to the floor point at distance d is at height h (1 - t / d)
	// at distance t. It meets a solid spanning [t_in, t_out] x [z0, z1] when it
	// is below z1 somewhere in the span and above z0 at its entry, i.e. for d in
	// [t_in h / (h - z0), t_out h / (h - z1)] (the upper end infinite when z1 >= h).
	double first = std::numeric_limits<double>::infinity();
	for (const auto& c : crossings)
	{
		const Solid& s = world.solids[c.solid];
		if (s.z0 >= h) continue;  // entirely above the camera: never in a downward sight line
		const double d_from = c.crossing.t_in * h / (h - s.z0);
		const double d_to = s.z1 >= h ? std::numeric_limits<double>::infinity() : c.crossing.t_out * h / (h - s.z1);
		if (d_from <= d_to) first = std::min(first, d_from);
	}
	return first;
}

double struckDistance(const World& world, const std::vector<SolidCrossing>& crossings, double strike_height)
{
	double first = std::numeric_limits<double>::infinity();
	for (const auto& c : crossings)
	{
		const Solid& s = world.solids[c.solid];
		if (s.z0 < strike_height && s.z1 > 0) first = std::min(first, c.crossing.t_in);
	}
	return first;
}

namespace
{
/** A scan labelled `label` from the omnicam's foot, ray i at scanlineBearing(i, rays),
 * each ray `distance(crossings)` [m] over the solids it crosses within `max_range`. */
template <class Distance>
mrpt::obs::CObservation2DRangeScan::Ptr truthScan(const char* label, const World& world, const OmnicamSimParams& cam,
												  const Pose2& robot, int rays, double max_range,
												  const Distance& distance)
{
	auto obs = mrpt::obs::CObservation2DRangeScan::Create();
	obs->sensorLabel = label;
	obs->sensorPose = cam.pose;
	obs->aperture = static_cast<float>(scanAperture(rays));
	obs->rightToLeft = true;
	obs->maxRange = static_cast<float>(max_range);
	obs->stdError = 0;
	obs->resizeScan(rays);
	const double c = std::cos(robot.yaw), s = std::sin(robot.yaw);
	const Vec2 foot{robot.x + c * cam.pose.x() - s * cam.pose.y(), robot.y + s * cam.pose.x() + c * cam.pose.y()};
	std::vector<SolidCrossing> crossings;
	for (int i = 0; i < rays; ++i)
	{
		const double a = robot.yaw + cam.pose.yaw() + scanlineBearing(i, rays);
		// A solid hides or stops nothing nearer than its entry, so nothing beyond max_range matters.
		world.castRay(foot, {std::cos(a), std::sin(a)}, max_range, crossings);
		const double d = distance(crossings);
		const bool valid = d <= max_range;
		obs->setScanRange(i, static_cast<float>(valid ? d : max_range));
		obs->setScanRangeValidity(i, valid);
	}
	return obs;
}
}  // namespace

mrpt::obs::CObservation2DRangeScan::Ptr floorTruth(const World& world, const OmnicamSimParams& cam,
												   const Pose2& robot, int rays, double max_range)
{
	return truthScan(kTruthLabel, world, cam, robot, rays, max_range,
					 [&](const auto& crossings) { return hiddenFloorDistance(world, crossings, cam.camera.h); });
}

mrpt::obs::CObservation2DRangeScan::Ptr bodyTruth(const World& world, const OmnicamSimParams& cam, const Pose2& robot,
												  int rays, double max_range, double strike_height)
{
	return truthScan(kBodyLabel, world, cam, robot, rays, max_range,
					 [&](const auto& crossings) { return struckDistance(world, crossings, strike_height); });
}

}  // namespace omnirange::sim
