#include "omnirange/train/LaserComparison.h"

#include <omnirange/core/Rangefinder.h>
#include <omnirange/core/ScanFusion.h>

#include <cmath>
#include <stdexcept>

namespace omnirange
{
std::string toString(PairStatus s)
{
	switch (s)
	{
		case PairStatus::Compared: return "compared";
		case PairStatus::LaserBeyondMaxRange: return "laser_beyond_max_range";
		case PairStatus::TooDifferent: return "too_different";
		case PairStatus::OmniRejected: return "omni_rejected";
		case PairStatus::OmniUnsure: return "omni_unsure";
	}
	throw std::logic_error("unknown PairStatus");
}

std::vector<RangePair> pairScans(const mrpt::obs::CObservation2DRangeScan& laser,
								 const mrpt::obs::CObservation2DRangeScan& omni, double max_diff)
{
	std::vector<RangePair> out;
	const int S = static_cast<int>(omni.getScanSize());
	if (S < 2) return out;
	for (std::size_t i = 0; i < laser.getScanSize(); ++i)
	{
		if (!laser.getScanRangeValidity(i)) continue;  // no return: nothing to compare
		// The laser's ray seen from the omnicam (both on the robot).
		const RaySeenFrom seen = laserRaySeenFrom(laser, i, omni.sensorPose);
		const int k = nearestRay(omni, seen.bearing);
		RangePair rp{static_cast<int>(i), k, seen.bearing, seen.range, omni.getScanRange(k), PairStatus::Compared};
		const bool no_hit = !omni.getScanRangeValidity(k) && rp.omni >= omni.maxRange - 1e-4;
		if (rp.laser > omni.maxRange)
			rp.status = PairStatus::LaserBeyondMaxRange;
		else if (rayIsUnsure(omni, k))
			rp.status = PairStatus::OmniUnsure;
		else if (!omni.getScanRangeValidity(k) && !no_hit)
			rp.status = PairStatus::OmniRejected;
		else if (std::abs(rp.difference()) > max_diff)
			rp.status = PairStatus::TooDifferent;
		out.push_back(rp);
	}
	return out;
}

}  // namespace omnirange
