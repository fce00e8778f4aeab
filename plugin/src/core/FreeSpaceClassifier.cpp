#include "omnirange/core/FreeSpaceClassifier.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace omnirange
{
FreeSpaceClassifier::FreeSpaceClassifier(const ColourModel& model, double threshold, double obstacle_ratio)
	: binner_(model.floor.binner()), free_(binner_.binCount(), 0)
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
	for (std::uint32_t b = 0; b < binner_.binCount(); ++b)
	{
		const double p = hist.probability(b);
		free_[b] = p >= threshold && (!two_class || p >= obstacle_ratio * model.obstacles.probability(b));  // eq. (5)
	}
}

std::size_t FreeSpaceClassifier::freeBinCount() const
{
	return static_cast<std::size_t>(std::count(free_.begin(), free_.end(), 1));
}

}  // namespace omnirange
