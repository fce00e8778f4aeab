#include "omnirange/core/FreeSpaceClassifier.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace omnirange
{
FreeSpaceClassifier::FreeSpaceClassifier(
	const ColourHistogram& hist, double threshold)
	: binner_(hist.binner()), free_(binner_.binCount(), 0)
{
	if (!(threshold >= 0.0 && threshold <= 1.0))
		throw std::invalid_argument(
			"threshold (Theta) must be within [0, 1], not " +
			std::to_string(threshold));
	if (hist.empty())
		throw std::invalid_argument(
			"the colour histogram is empty: train it before classifying");
	for (std::uint32_t b = 0; b < binner_.binCount(); ++b)
		free_[b] = hist.probability(b) >= threshold ? 1 : 0;  // eq. (5)
}

std::size_t FreeSpaceClassifier::freeBinCount() const
{
	return static_cast<std::size_t>(std::count(free_.begin(), free_.end(), 1));
}

}  // namespace omnirange
