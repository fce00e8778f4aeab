#include "omnirange/core/ScanFusion.h"

#include "omnirange/config/SensorLabels.h"
#include "omnirange/core/Rangefinder.h"

#include <algorithm>
#include <cmath>

namespace omnirange
{
RaySeenFrom laserRaySeenFrom(const mrpt::obs::CObservation2DRangeScan& laser, std::size_t i,
							 const mrpt::poses::CPose3D& from)
{
	const double r = laser.getScanRangeValidity(i) ? laser.getScanRange(i) : laser.maxRange;
	const double a = laser.getScanAngle(i);
	mrpt::math::TPoint3D p;
	(laser.sensorPose - from).composePoint({r * std::cos(a), r * std::sin(a), 0}, p);
	return {std::atan2(p.y, p.x), std::hypot(p.x, p.y)};
}

int nearestRay(const mrpt::obs::CObservation2DRangeScan& scan, double bearing)
{
	const int S = static_cast<int>(scan.getScanSize());
	const double step = scan.aperture / (S - 1);
	const int k = static_cast<int>(std::lround((bearing + 0.5 * scan.aperture) / step));
	return ((k % S) + S) % S;  // the scan closes the circle
}

std::vector<LaserReading> laserAlong(const mrpt::obs::CObservation2DRangeScan& laser,
									 const mrpt::obs::CObservation2DRangeScan& omni)
{
	using Kind = LaserReading::Kind;
	const int S = static_cast<int>(omni.getScanSize());
	std::vector<LaserReading> along(S);
	if (S < 2) return along;
	// The nearer of two readings: a return before a no-return, an unseen ray neither.
	const auto nearer = [](const LaserReading& a, const LaserReading& b) {
		if (a.kind == Kind::Unseen) return b;
		if (b.kind == Kind::Unseen) return a;
		if (a.kind == Kind::Return && b.kind == Kind::Return) return a.range <= b.range ? a : b;
		return a.kind == Kind::Return ? a : b;
	};
	// Each laser ray seen from the omnicam, and what it reads.
	const std::size_t n = laser.getScanSize();
	std::vector<int> ray(n);
	std::vector<LaserReading> reading(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		const RaySeenFrom seen = laserRaySeenFrom(laser, i, omni.sensorPose);
		ray[i] = nearestRay(omni, seen.bearing);
		reading[i] = laser.getScanRangeValidity(i) ? LaserReading{Kind::Return, seen.range} : LaserReading{Kind::NoReturn, 0};
		along[ray[i]] = nearer(along[ray[i]], reading[i]);
	}
	// The laser sees the arc between two neighbouring rays too (the sensors' offset spreads the
	// rays unevenly over the omnicam's): each omnicam ray of it takes the nearer of the two.
	const int max_arc = S / 8;  // the shorter way round; wider is no arc of neighbours (a 360-degree laser's seam)
	std::vector<LaserReading> between(S);
	for (std::size_t i = 0; i + 1 < n; ++i)
	{
		int d = ((ray[i + 1] - ray[i]) % S + S) % S;
		int step = 1;
		if (d > S / 2) d = S - d, step = -1;
		if (d < 2 || d > max_arc) continue;
		const LaserReading r = nearer(reading[i], reading[i + 1]);
		for (int k = 1; k < d; ++k)
		{
			auto& at = between[((ray[i] + step * k) % S + S) % S];
			at = nearer(at, r);
		}
	}
	for (int k = 0; k < S; ++k)
		if (along[k].kind == Kind::Unseen) along[k] = between[k];
	return along;
}

mrpt::obs::CObservation2DRangeScan::Ptr fuseScans(const mrpt::obs::CObservation2DRangeScan& omni,
												  const mrpt::obs::CObservation2DRangeScan& laser)
{
	using Kind = LaserReading::Kind;
	auto fused = mrpt::obs::CObservation2DRangeScan::Create(omni);
	fused->sensorLabel = kFusedLabel;
	fused->maxRange = std::max(omni.maxRange, laser.maxRange);
	fused->setScanHasIntensity(true);
	const std::vector<LaserReading> along = laserAlong(laser, omni);
	const auto set = [&](std::size_t i, float range, bool valid, int intensity) {
		fused->setScanRange(i, range);
		fused->setScanRangeValidity(i, valid);
		fused->setScanIntensity(i, intensity);
	};
	for (std::size_t i = 0; i < along.size(); ++i)
	{
		const LaserReading& l = along[i];
		const bool omni_hit = omni.getScanRangeValidity(i) && !rayIsUnsure(omni, i);
		const float o = omni.getScanRange(i);
		if (l.kind == Kind::Unseen)
			set(i, o, omni.getScanRangeValidity(i),
				rayIsUnsure(omni, i) ? omni.getScanIntensity(i) : static_cast<int>(FusedSource::OmnicamAlone));
		else if (omni_hit && (l.kind == Kind::NoReturn || o < l.range))
			set(i, o, true, static_cast<int>(FusedSource::Omnicam));
		else if (l.kind == Kind::Return)
			set(i, static_cast<float>(l.range), true, static_cast<int>(FusedSource::Laser));
		else
			set(i, fused->maxRange, false, static_cast<int>(FusedSource::Laser));
	}
	return fused;
}

}  // namespace omnirange
