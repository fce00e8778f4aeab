#include "omnirange/core/FloorAdaptation.h"

#include "omnirange/core/Rangefinder.h"

#include <opencv2/core.hpp>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace omnirange
{
namespace
{
/** A ring pixel is learned when each channel is within this of the ring's
 * median: a fifth of the median plus a few levels for dark floors. */
bool nearMedian(const cv::Vec3b& bgr, const std::array<double, 3>& median)
{
	for (int c = 0; c < 3; ++c)
		if (std::abs(bgr[c] - median[c]) > 0.2 * median[c] + 6.0) return false;
	return true;
}
}  // namespace

FloorAdaptation::FloorAdaptation(const Rangefinder& rangefinder, double memory)
	: rf_(rangefinder),
	  keep_(std::exp(-1.0 / memory)),
	  counts_(rangefinder.classifier().binner().binCount(), 0.0)
{
	if (!(memory >= 1.0 && memory <= 1e6)) throw std::invalid_argument("adaptation_memory must be within [1, 1e6] images");
}

void FloorAdaptation::learn(const cv::Mat& bgr)
{
	const std::vector<cv::Vec3b> ring = rf_.floorRing().colours(bgr);
	const auto median = FloorRing::median(ring);
	const ColourBinner& binner = rf_.classifier().binner();
	for (double& c : counts_) c *= keep_;
	total_ *= keep_;
	for (const cv::Vec3b& px : ring)
	{
		if (!nearMedian(px, median)) continue;
		counts_[binner.binOf(&px[0])] += 1.0;
		total_ += 1.0;
	}
	++images_;
}

FreeSpaceClassifier FloorAdaptation::classifier() const
{
	if (total_ <= 0) return rf_.classifier();
	std::vector<double> p(counts_.size());
	for (std::size_t b = 0; b < p.size(); ++b) p[b] = counts_[b] / total_;
	return rf_.classifier().alsoFreeUnder(p);
}

}  // namespace omnirange
