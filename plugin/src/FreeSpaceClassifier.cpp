#include "omnirange/FreeSpaceClassifier.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace omnirange
{
FreeSpaceClassifier::FreeSpaceClassifier(
	const ColourHistogram& hist, double threshold)
	: binner_(hist.binner()), threshold_(threshold), free_(binner_.binCount(), 0)
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

cv::Mat FreeSpaceClassifier::classify(const cv::Mat& bgr) const
{
	if (bgr.type() != CV_8UC3)
		throw std::invalid_argument("classification needs an 8-bit BGR image");
	cv::Mat out(bgr.size(), CV_8UC1);
	for (int r = 0; r < bgr.rows; ++r)
	{
		const auto* px = bgr.ptr<std::uint8_t>(r);
		auto* o = out.ptr<std::uint8_t>(r);
		for (int c = 0; c < bgr.cols; ++c) o[c] = isFree(px + 3 * c) ? 255 : 0;
	}
	return out;
}

std::size_t FreeSpaceClassifier::freeBinCount() const
{
	return static_cast<std::size_t>(std::count(free_.begin(), free_.end(), 1));
}

}  // namespace omnirange
