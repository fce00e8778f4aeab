#include "omnirange/core/FreeSpaceClassifier.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace omnirange
{
FreeSpaceClassifier::FreeSpaceClassifier(const ColourModel& model, double threshold, double obstacle_ratio,
										 double smoothing)
	: binner_(model.floor.binner()), free_(binner_.binCount(), 0), needed_(binner_.binCount(), 0.0f)
{
	if (!(threshold >= 0.0 && threshold <= 1.0))
		throw std::invalid_argument(
			"threshold (Theta) must be within [0, 1], not " +
			std::to_string(threshold));
	if (!(obstacle_ratio >= 0.0 && obstacle_ratio <= 1000.0))
		throw std::invalid_argument("obstacle_ratio must be within [0, 1000], not " + std::to_string(obstacle_ratio));
	const ColourHistogram& hist = model.floor;
	if (hist.empty())
		throw std::invalid_argument(
			"the colour histogram is empty: train it before classifying");
	const bool two_class = model.hasObstacles() && obstacle_ratio > 0;
	const std::vector<double> floor = hist.smoothedProbabilities(smoothing);
	const std::vector<double> obstacle =
		two_class ? model.obstacles.smoothedProbabilities(smoothing) : std::vector<double>(floor.size(), 0.0);
	for (std::uint32_t b = 0; b < binner_.binCount(); ++b)
	{
		const double need = two_class ? std::max(threshold, obstacle_ratio * obstacle[b]) : threshold;
		needed_[b] = static_cast<float>(need);
		free_[b] = floor[b] >= need;  // eq. (5)
	}
}

std::size_t FreeSpaceClassifier::freeBinCount() const
{
	return static_cast<std::size_t>(std::count(free_.begin(), free_.end(), 1));
}

FreeSpaceClassifier FreeSpaceClassifier::alsoFreeUnder(const std::vector<double>& floor_probability) const
{
	if (floor_probability.size() != free_.size())
		throw std::invalid_argument("alsoFreeUnder: one probability per bin is needed");
	FreeSpaceClassifier out(*this);
	for (std::size_t b = 0; b < free_.size(); ++b)
		out.free_[b] |= static_cast<std::uint8_t>(floor_probability[b] > 0 && floor_probability[b] >= needed_[b]);
	return out;
}

}  // namespace omnirange
