#pragma once
// Scoring the omnicam against the truth the simulator knows (sim/FloorTruth.h):
// for every omnicam ray, the true distance at which the floor ends along the
// same bearing. Reported beside the paper's laser comparison: rays within
// 2 and 5 cm, mean and median absolute error, rays missed (the floor ends
// within range but the ray has no hit), false free (missed, or a hit more than
// 5 cm past the truth, on a ray not unsure), unsure rays, false obstacles (a hit
// where the floor goes on past the max range), overall and by range band.

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <array>
#include <string>
#include <vector>

namespace omnirange::eval
{
/** The counts for the rays whose true boundary lies in one band of range. */
/** How TruthStats::table() begins (config/Output.h's begins_with). */
inline constexpr char kTruthTableBegins[] = "| true distance | rays |";

struct TruthBand
{
	explicit TruthBand(double lo_ = 0, double hi_ = 0) : lo(lo_), hi(hi_) {}

	double lo, hi;  ///< [m] the true distance's band
	std::size_t rays{0};  ///< rays whose floor ends in the band
	std::size_t within_2cm{0}, within_5cm{0};  ///< of them, hits that close to the truth
	std::size_t missed_no_hit{0};  ///< of them, rays that report no hit
	std::size_t missed_rejected{0};  ///< of them, rays rejected (too close, outlier filter)
	std::size_t unsure{0};  ///< of them, rays free only to their confident extent
	/** of them, rays that claim free floor more than 5 cm past the truth (the
	 * error a robot collides by): no valid hit (no hit, too close or rejected,
	 * all invalid in the MRPT scan), a hit beyond it, or an unsure ray whose
	 * confident extent is beyond it */
	std::size_t false_free{0};
	std::vector<double> abs_errors;  ///< [m] of the hits
	double sum_signed{0};  ///< [m] sum of omnicam minus truth over the hits

	std::size_t missed() const { return missed_no_hit + missed_rejected; }
	double meanAbs() const;
	double medianAbs() const;
	double meanSigned() const { return abs_errors.empty() ? 0 : sum_signed / abs_errors.size(); }
};

struct TruthStats
{
	/** Bands of true distance [m]; the last ends at the omnicam's max range. */
	std::array<TruthBand, 4> bands{TruthBand(0, 1), TruthBand(1, 2), TruthBand(2, 3), TruthBand(3, 1e9)};
	std::size_t open_rays{0};  ///< rays whose floor goes on past the max range
	std::size_t false_obstacles{0};  ///< of them, rays with a hit
	std::size_t open_unsure{0};  ///< of them, unsure rays
	int frames{0};

	/** All bands together. */
	TruthBand all() const;
	/** Rays scored: those whose floor ends within range and the open ones. */
	std::size_t allRays() const { return all().rays + open_rays; }
	/** Of all rays scored, the unsure ones. */
	std::size_t allUnsure() const { return all().unsure + open_unsure; }
	/** Adds one omnicam scan against the truth scan of the same moment. Throws
	 * std::invalid_argument if the two were not taken from the same pose on the robot. */
	void add(const mrpt::obs::CObservation2DRangeScan& truth, const mrpt::obs::CObservation2DRangeScan& omni)
	{
		add(truth, omni, {}, omni.maxRange);
	}
	/** Adds the rays i of `scan` with scored[i] (all when empty), scored out
	 * to `max_range` [m] whatever the scan's own reach: two sensors compared on
	 * the same rays and the same range. */
	void add(const mrpt::obs::CObservation2DRangeScan& truth, const mrpt::obs::CObservation2DRangeScan& scan,
			 const std::vector<char>& scored, double max_range);
	/** The Markdown table: overall, then a row per band. */
	std::string table() const;
};

}  // namespace omnirange::eval
