#pragma once
// The accuracy test (paper §IV-B, §V-A): every laser ray against the omnicam
// ray at the same bearing (pairScans), the Table II figures with the
// exclusions counted, and every pair for a CSV.

#include <omnirange/io/ObservationPairer.h>
#include <omnirange/config/SensorLabels.h>
#include <omnirange/train/LaserComparison.h>
#include <omnirange_eval/TruthComparison.h>

#include <map>
#include <string>
#include <vector>

namespace omnirange
{
class Progress;
}

namespace omnirange::eval
{
/** The Table II figures and the exclusions. */
/** How the accuracy's files begin: an existing PREFIX_pairs.csv or
 * PREFIX_table.md that does not is not one to replace (config/Output.h). */
inline constexpr char kPairsCsvBegins[] = "frame,laser_ray,omni_ray,";
inline constexpr char kAccuracyTableBegins[] = "| frames | pairs |";

struct AccuracyStats
{
	std::size_t compared{0}, laser_beyond{0}, too_different{0}, omni_rejected{0}, omni_unsure{0};
	double sum_abs{0}, sum_pct{0}, sum_signed{0};
	std::vector<double> differences;  ///< of the compared pairs

	/** Of the pairs whose laser return is within the omnicam's max range, those
	 * the omnicam claims free past it by more than kFalseFreeMargin: a ray not
	 * unsure that reads farther (or nothing), or an unsure one whose extent is
	 * farther. */
	std::size_t laser_in_range{0}, laser_false_free{0};

	void add(const RangePair& p);
	double falseFree() const { return laser_in_range ? double(laser_false_free) / laser_in_range : 0; }
	double unsure() const { return total() ? double(omni_unsure) / total() : 0; }
	std::size_t total() const { return compared + laser_beyond + too_different + omni_rejected + omni_unsure; }
	double meanAbs() const { return compared ? sum_abs / compared : 0; }
	double meanPercent() const { return compared ? sum_pct / compared : 0; }
	double meanSigned() const { return compared ? sum_signed / compared : 0; }
	/** Fraction of all pairs excluded (laser beyond max range or too different). */
	double excludedFraction() const;
};

struct AccuracyOptions
{
	std::string laser_label{kLaserLabel};
	std::string omni_label{kOmniscanLabel};
	std::string truth_label{kTruthLabel};  ///< the simulator's true boundary, where the rawlog has it
	std::string body_label{kBodyLabel};  ///< what the robot would strike, where the rawlog has it
	std::string fused_label{kFusedLabel};  ///< the fused scan, where the rawlog has it
	double max_difference{kDefaultMaxDifference};  ///< [m] pairs differing by more are excluded
	double max_dt{kDefaultMaxPairingDt};  ///< [s] largest time between paired scans
	/** Score only from this laser/omnicam pair on (0: all): the frames after
	 * the part of the route the histogram was trained on. */
	int first{0};
};

struct AccuracyResult
{
	AccuracyStats stats;
	int frames{0};  ///< scan pairs compared
	std::string csv;  ///< every ray pair, with a header line
	TruthStats truth;  ///< against the truth, when the rawlog holds it (truth.frames > 0)
	/** The laser, the omnicam and the fused scan (by sensor label) scored on
	 * the same rays, those the laser sees, out to the omnicam's max range:
	 * against the truth, and against what the robot would strike (BODY). */
	std::map<std::string, TruthStats> truth_in_view, body_in_view;
	/** The Table II-style table, in Markdown. */
	std::string table(double max_difference) const;
	/** truth_in_view and body_in_view as a Markdown section ("" without them). */
	std::string inViewTable() const;
};

/** Streams a rawlog with both scans and pairs every laser scan with the
 * omnicam scan taken with it, and, where the rawlog holds truth scans, every
 * omnicam scan with the truth. Throws std::runtime_error on a bad rawlog or
 * when no laser/omnicam pair is found. */
AccuracyResult evaluateAccuracy(const std::string& rawlog, const AccuracyOptions& options,
								Progress* progress = nullptr);

}  // namespace omnirange::eval
