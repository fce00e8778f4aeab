#pragma once
// Every laser ray beside the omnicam ray at the same bearing, both seen from
// the omnicam's position on the robot (the sensors sit at different places):
// what the accuracy test (paper §IV-B) and the mirror calibration compare.

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>
#include <vector>

namespace omnirange
{
/** [m] laser/omnicam pairs differing by more are excluded (paper §IV-B). */
constexpr double kDefaultMaxDifference = 1.25;
/** [m] The largest max_difference taken. */
constexpr double kMaxRangeDifference = 100.0;

/** [m] A ray reads free floor past the truth (or the laser) when it claims
 * free floor this far beyond it: the margin of "within 5 cm". */
inline constexpr double kFalseFreeMargin = 0.05;

enum class PairStatus
{
	Compared,
	LaserBeyondMaxRange,  ///< excluded: the laser reads beyond the omni's max range
	TooDifferent,  ///< excluded: |difference| > max_difference
	OmniRejected,  ///< not compared: the omni ray is invalid but not a no-hit (too close, outlier)
	OmniUnsure  ///< not compared: the omni ray is unsure, free only to its range (rayIsUnsure)
};
std::string toString(PairStatus s);

struct RangePair
{
	int laser_ray;
	int omni_ray;
	double bearing;  ///< [rad] from the omnicam, in the omnicam's frame
	double laser;  ///< [m] the laser's hit, as a range from the omnicam
	double omni;  ///< [m]
	PairStatus status;
	double difference() const { return laser - omni; }
};

/** Pairs one laser scan with one omni scan taken at the same time on the
 * same robot. An invalid omni ray at its max range is the paper's no-hit and
 * is compared at max range. */
std::vector<RangePair> pairScans(const mrpt::obs::CObservation2DRangeScan& laser,
								 const mrpt::obs::CObservation2DRangeScan& omni,
								 double max_difference = kDefaultMaxDifference);

}  // namespace omnirange
