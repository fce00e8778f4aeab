#pragma once
// The accuracy test (paper §IV-B, §V-A): every laser ray against the omnicam
// ray at the same bearing, both seen from the omnicam's position on the
// robot; difference = laser - omni. Pairs where the laser reads beyond the
// omnicam's max range, or the two differ by more than 1.25 m, are excluded
// and counted.

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace omnirange
{
enum class PairStatus
{
	Compared,
	LaserBeyondMaxRange,  ///< excluded: the laser reads beyond the omni's max range
	TooDifferent,  ///< excluded: |difference| > max_difference
	OmniRejected  ///< not compared: the omni ray is invalid but not a no-hit (too close, outlier)
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
								 const mrpt::obs::CObservation2DRangeScan& omni, double max_difference = 1.25);

/** The Table II figures and the exclusions. */
struct AccuracyStats
{
	std::size_t compared{0}, laser_beyond{0}, too_different{0}, omni_rejected{0};
	double sum_abs{0}, sum_pct{0}, sum_signed{0};
	std::vector<double> differences;  ///< of the compared pairs

	void add(const RangePair& p);
	std::size_t total() const { return compared + laser_beyond + too_different + omni_rejected; }
	double meanAbs() const { return compared ? sum_abs / compared : 0; }
	double meanPercent() const { return compared ? sum_pct / compared : 0; }
	double meanSigned() const { return compared ? sum_signed / compared : 0; }
	/** Fraction of all pairs excluded (laser beyond max range or too different). */
	double excludedFraction() const;
};

struct AccuracyOptions
{
	std::string laser_label{"LASER"};
	std::string omni_label{"OMNISCAN"};
	double max_difference{1.25};  ///< [m] pairs differing by more are excluded
	double max_dt{0.1};  ///< [s] largest time between paired scans
};

struct AccuracyResult
{
	AccuracyStats stats;
	int frames{0};  ///< scan pairs compared
	std::string csv;  ///< every ray pair, with a header line
	/** The Table II-style table, in Markdown. */
	std::string table(double max_difference) const;
};

/** Streams a rawlog with both scans and pairs every laser scan with the
 * omnicam scan taken with it. Throws std::runtime_error on a bad rawlog or
 * when no pair is found. */
AccuracyResult evaluateAccuracy(const std::string& rawlog, const AccuracyOptions& options);

/** A bar chart of the differences like paper Fig. 9 (bins of `bin` m over
 * [-range, range]), as an 8-bit BGR image. */
cv::Mat differenceHistogram(const std::vector<double>& d, const std::string& title, double range = 1.25,
							double bin = 0.05);

}  // namespace omnirange
