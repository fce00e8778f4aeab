#pragma once
// Scans drawn from walls whose places are known, with the omnicam's ray
// geometry, and rawlogs of drives through them: the matcher's and the
// keyframe graph's tests, and icp-slam's corridor.
#include <omnirange/core/PolarScanner.h>
#include <omnirange/config/SensorLabels.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace omnirange::test
{
using mrpt::poses::CPose2D;

struct Wall
{
	double x0, y0, x1, y1;
};
inline const std::vector<Wall> kCorridor{{-50, -1, 50, -1}, {-50, 1, 50, 1}};  // 2 m wide, no end in sight
inline const std::vector<Wall> kRoom{{-2, -2, 2, -2}, {2, -2, 2, 2}, {2, 2, -2, 2}, {-2, 2, -2, -2}};  // 4 x 4 m

// A 360-ray OMNISCAN scan of `walls` from `pose` over `aperture` (the
// rangefinder's own is scanAperture(360)), out to 3.8 m (no hit beyond).
inline mrpt::obs::CObservation2DRangeScan::Ptr drawScan(const std::vector<Wall>& walls, const CPose2D& pose, double t,
														 double aperture = 2 * M_PI)
{
	constexpr int n = 360;
	constexpr double max_range = 3.8;
	auto s = mrpt::obs::CObservation2DRangeScan::Create();
	s->sensorLabel = kOmniscanLabel;
	s->timestamp = mrpt::Clock::fromDouble(t);
	s->aperture = static_cast<float>(aperture);
	s->rightToLeft = true;
	s->maxRange = max_range;
	s->resizeScan(n);
	for (int i = 0; i < n; ++i)
	{
		const double a = pose.phi() + s->getScanAngle(i);
		const double dx = std::cos(a), dy = std::sin(a);
		double best = std::numeric_limits<double>::infinity();
		for (const auto& w : walls)
		{
			// Ray (pose + r d) against the segment (w0 + u (w1 - w0)).
			const double ex = w.x1 - w.x0, ey = w.y1 - w.y0;
			const double den = dx * ey - dy * ex;
			if (std::abs(den) < 1e-12) continue;
			const double qx = w.x0 - pose.x(), qy = w.y0 - pose.y();
			const double r = (qx * ey - qy * ex) / den, u = (qx * dy - qy * dx) / den;
			if (r > 0 && u >= 0 && u <= 1) best = std::min(best, r);
		}
		s->setScanRange(i, static_cast<float>(std::min(best, max_range)));
		s->setScanRangeValidity(i, best < max_range);
	}
	return s;
}

// Writes a drive to `file`: at each step, `dt` seconds apart, the odometry
// reading, then the scan `scan(step, time)`.
inline void writeDrive(const std::string& file, int steps, const std::function<CPose2D(int)>& odometry,
					   const std::function<mrpt::obs::CObservation2DRangeScan::Ptr(int, double)>& scan,
					   double dt = 1.0)
{
	mrpt::io::CFileGZOutputStream out(file);
	auto a = mrpt::serialization::archiveFrom(out);
	for (int i = 0; i < steps; ++i)
	{
		const double t = 1000.0 + dt * i;
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->sensorLabel = kOdometryLabel;
		odo->timestamp = mrpt::Clock::fromDouble(t);
		odo->odometry = odometry(i);
		a << *odo << *scan(i, t);
	}
}

// The same in the tests' temporary folder, removed when it goes.
struct Drive
{
	Drive(const std::string& name, int steps, const std::function<CPose2D(int)>& odometry,
		  const std::function<mrpt::obs::CObservation2DRangeScan::Ptr(int, double)>& scan)
		: file(testing::TempDir() + name)
	{
		writeDrive(file, steps, odometry, scan);
	}
	~Drive() { std::filesystem::remove(file); }
	std::string file;
};

}  // namespace omnirange::test
