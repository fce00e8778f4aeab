#include "omnirange/core/FreeSpaceClassifier.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <tuple>

namespace omnirange
{
namespace
{
/** Per bin, the largest probability of the bins whose colours darken into
 * it in light down to 1 - depth times as strong (steps of 2 %, finer than
 * a bin at the bin counts used, so no bin along the way is skipped). */
std::vector<double> inShadow(const ColourBinner& binner, const std::vector<double>& lit, double depth)
{
	std::vector<double> p(lit.size(), 0.0);
	const int steps = static_cast<int>(std::ceil(depth / 0.02));
	for (std::uint32_t b = 0; b < lit.size(); ++b)
	{
		if (lit[b] <= 0) continue;
		for (int k = 1; k <= steps; ++k)
		{
			double& q = p[binner.darkerBin(b, 1.0 - depth * k / steps)];
			q = std::max(q, lit[b]);
		}
	}
	return p;
}

/** The probability at which the floor's most likely colours, from the most
 * likely down, first hold `share` of its mass: colours at least this likely
 * are sure floor. */
double sureLevel(std::vector<double> p, double share)
{
	if (share >= 1) return 0;
	std::sort(p.begin(), p.end(), std::greater<>());
	double total = 0;
	for (double x : p) total += x;
	double held = 0;
	for (double x : p)
		if ((held += x) >= share * total) return x;
	return 0;
}
}  // namespace

FreeSpaceClassifier::FreeSpaceClassifier(const ColourModel& model, double threshold, double obstacle_ratio,
										 double smoothing, double shadow_depth, double sure_share, double sure_ratio)
	: binner_(model.floor.binner()), free_(binner_.binCount(), 0), needed_(binner_.binCount(), 0.0f)
{
	for (const auto& [key, range, value] : {std::tuple{"threshold", kThresholdRange, threshold},
											  {"shadow_depth", kShadowDepthRange, shadow_depth},
											  {"obstacle_ratio", kObstacleRatioRange, obstacle_ratio},
											  {"sure_floor_share", kSureShareRange, sure_share},
											  {"sure_obstacle_ratio", kObstacleRatioRange, sure_ratio}})
		if (!range.contains(value))
			throw std::invalid_argument(std::string(key) + " must be " + range.text() + ", not " + formatDouble(value));
	const ColourHistogram& hist = model.floor;
	if (hist.empty())
		throw std::invalid_argument(
			"the colour histogram is empty: train it before classifying");
	const bool two_class = model.hasObstacles() && obstacle_ratio > 0;
	const std::vector<double> floor = hist.smoothedProbabilities(smoothing);
	const std::vector<double> obstacle = model.hasObstacles() && (obstacle_ratio > 0 || sure_ratio > 0)
											 ? model.obstacles.smoothedProbabilities(smoothing)
											 : std::vector<double>(floor.size(), 0.0);
	const std::vector<double> shaded = shadow_depth > 0 ? inShadow(binner_, floor, shadow_depth) : std::vector<double>();
	const double sure = sureLevel(floor, sure_share);
	for (std::uint32_t b = 0; b < binner_.binCount(); ++b)
	{
		const double need = two_class ? std::max(threshold, obstacle_ratio * obstacle[b]) : threshold;
		needed_[b] = static_cast<float>(need);
		free_[b] = floor[b] >= need ? kFree : kNotFree;  // eq. (5)
		// A colour that the floor in shadow explains is free only if training
		// never saw it on an obstacle: a dark obstacle of the floor's hue is
		// no shadow, and a weaker test (the obstacles explaining it less
		// well) let bookcases and hedges through (docs/results.md).
		if (!shaded.empty() && shaded[b] > 0 && shaded[b] >= need && !(model.obstacles.probability(b) > 0))
			free_[b] = kFree;
		// Doubtful: a colour the floor rarely shows, or one the obstacles' feet show nearly as often.
		const double p = std::max(floor[b], shaded.empty() ? 0.0 : shaded[b]);
		if (free_[b] != kNotFree && (p < sure || p < sure_ratio * obstacle[b])) free_[b] = kDoubtfulFree;
	}
}

std::size_t FreeSpaceClassifier::freeBinCount() const
{
	return static_cast<std::size_t>(free_.size() - std::count(free_.begin(), free_.end(), kNotFree));
}

FreeSpaceClassifier FreeSpaceClassifier::alsoFreeUnder(const std::vector<double>& floor_probability) const
{
	if (floor_probability.size() != free_.size())
		throw std::invalid_argument("alsoFreeUnder: one probability per bin is needed");
	FreeSpaceClassifier out(*this);
	for (std::size_t b = 0; b < free_.size(); ++b)
		if (floor_probability[b] > 0 && floor_probability[b] >= needed_[b])
			out.free_[b] = kFree;  // the floor's colour now, seen around the base: sure
	return out;
}

}  // namespace omnirange
