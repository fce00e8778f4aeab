#include "omnirange_eval/Trajectory.h"

#include <omnirange/io/RawlogProcessor.h>

#include <omnirange/io/GzObject.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace omnirange::eval
{
std::vector<StampedPose> groundTruthPath(const std::string& rawlog, const std::string& label)
{
	using mrpt::obs::CObservationRobotPose;
	RawlogProcessor loop(rawlog);
	std::vector<StampedPose> out;
	loop.on<CObservationRobotPose>(label, [&](const CObservationRobotPose::Ptr& gt) {
		out.push_back({mrpt::Clock::toDouble(gt->timestamp), mrpt::poses::CPose2D(gt->pose.mean)});
	});
	loop.run();
	if (out.empty()) throw std::runtime_error("no " + label + " pose in '" + rawlog + "' (" + loop.describeLabels() + ")");
	return out;
}

std::vector<StampedPose> odometryPath(const std::string& rawlog, const std::string& label)
{
	using mrpt::obs::CObservationOdometry;
	RawlogProcessor loop(rawlog);
	std::vector<StampedPose> out;
	loop.on<CObservationOdometry>(label, [&](const CObservationOdometry::Ptr& odo) {
		out.push_back({mrpt::Clock::toDouble(odo->timestamp), odo->odometry});
	});
	loop.run();
	if (out.empty()) throw std::runtime_error("no " + label + " odometry in '" + rawlog + "' (" + loop.describeLabels() + ")");
	return out;
}

mrpt::poses::CPose2D poseAt(const std::vector<StampedPose>& path, double t)
{
	const auto it = std::lower_bound(path.begin(), path.end(), t, [](const StampedPose& p, double v) { return p.t < v; });
	if (it == path.end()) return path.back().pose;
	if (it == path.begin() || std::abs(it->t - t) < std::abs((it - 1)->t - t)) return it->pose;
	return (it - 1)->pose;
}

mrpt::maps::CSimpleMap loadSimplemap(const std::string& file)
{
	return readGzObject<mrpt::maps::CSimpleMap>(file, "simplemap");
}

std::vector<StampedPose> simplemapKeyframes(const mrpt::maps::CSimpleMap& sm)
{
	std::vector<StampedPose> out;
	for (std::size_t i = 0; i < sm.size(); ++i)
	{
		const auto [pdf, sf] = sm.get(i);
		if (!pdf || !sf || sf->size() == 0) continue;
		out.push_back({mrpt::Clock::toDouble(sf->getObservationByIndex(0)->timestamp),
					   mrpt::poses::CPose2D(pdf->getMeanVal())});
	}
	return out;
}

PathError comparePaths(const std::vector<StampedPose>& est, const std::vector<StampedPose>& truth)
{
	PathError e;
	if (est.size() < 2 || truth.empty()) throw std::runtime_error("too few poses to compare paths");
	std::vector<mrpt::poses::CPose2D> a, b;  // estimated, true
	for (const auto& p : est) a.push_back(p.pose), b.push_back(poseAt(truth, p.t));
	// Best rigid 2D alignment (least squares, no scale) of a onto b.
	double ax = 0, ay = 0, bx = 0, by = 0;
	for (std::size_t i = 0; i < a.size(); ++i) ax += a[i].x(), ay += a[i].y(), bx += b[i].x(), by += b[i].y();
	const double n = static_cast<double>(a.size());
	ax /= n, ay /= n, bx /= n, by /= n;
	double sxx = 0, sxy = 0;
	for (std::size_t i = 0; i < a.size(); ++i)
	{
		const double pax = a[i].x() - ax, pay = a[i].y() - ay, pbx = b[i].x() - bx, pby = b[i].y() - by;
		sxx += pax * pbx + pay * pby;
		sxy += pax * pby - pay * pbx;
	}
	const double th = std::atan2(sxy, sxx), c = std::cos(th), s = std::sin(th);
	e.alignment = mrpt::poses::CPose2D(bx - (c * ax - s * ay), by - (s * ax + c * ay), th);
	double se = 0;
	for (std::size_t i = 0; i < a.size(); ++i)
	{
		const auto p = e.alignment + a[i];
		se += std::pow(p.x() - b[i].x(), 2) + std::pow(p.y() - b[i].y(), 2);
	}
	e.poses = static_cast<int>(a.size());
	e.ate_rmse = std::sqrt(se / n);
	// Final pose: both paths start together, how far apart do they end?
	const auto first = b.front() + (-a.front());
	const auto last = first + a.back();
	e.final_xy = std::hypot(last.x() - b.back().x(), last.y() - b.back().y());
	e.final_yaw = std::abs(mrpt::math::wrapToPi(last.phi() - b.back().phi()));
	return e;
}

}  // namespace omnirange::eval
