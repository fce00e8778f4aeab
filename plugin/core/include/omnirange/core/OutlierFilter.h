#pragma once
// Outlier rejection (paper §III: "an outlier rejection filter is used to
// reject the estimated distances that have a high probability of being
// inaccurate"; the paper does not say which). Ours rejects spikes: a run of
// at most max_width hit rays whose ranges disagree with both rays that flank
// it while those two agree with each other. A misclassified patch of floor
// or wall makes exactly such a spike; a corner or a doorway does not (one
// side agrees with it), so real depth steps survive. The scan wraps around:
// the last ray neighbours the first.

#include <omnirange/core/PolarScanner.h>
#include <omnirange/config/OptionsTable.h>

#include <string>
#include <vector>

namespace omnirange
{
enum class OutlierFilterKind
{
	None,
	Spike
};
std::string toString(OutlierFilterKind k);
/** "none" or "spike"; throws std::invalid_argument otherwise. */
OutlierFilterKind outlierFilterKindFromString(const std::string& name);

/** The ini keys equal the member names (one flat [rangefinder] section, so
 * each carries the filter's name). */
struct OutlierFilterParams
{
	OutlierFilterKind outlier_filter{OutlierFilterKind::Spike};
	int outlier_max_width{2};  ///< [rays] widest spike removed (>= 1)
	double outlier_abs_tol{0.15};  ///< [m] ranges within abs_tol + rel_tol * range agree
	double outlier_rel_tol{0.15};  ///< [-] relative part of that tolerance

	static const OptionsTable<OutlierFilterParams>& table();
	/** Throws std::invalid_argument on an impossible value. */
	void validate() const;
};

/** Marks spikes of `rays` as RayStatus::Outlier (their ranges are kept);
 * returns how many rays it marked. Throws on impossible parameters. */
int rejectOutliers(std::vector<Ray>& rays, const OutlierFilterParams& p);

}  // namespace omnirange
