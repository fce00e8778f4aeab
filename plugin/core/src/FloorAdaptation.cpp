#include "omnirange/core/FloorAdaptation.h"

#include "omnirange/core/ExposureCompensation.h"

#include <cmath>
#include <cstdlib>

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

FloorAdaptation::FloorAdaptation(const FreeSpaceClassifier& trained, double memory)
	: keep_(std::exp(-1.0 / memory)), counts_(trained.binner().binCount(), 0.0)
{
}

void FloorAdaptation::learn(const std::vector<cv::Vec3b>& ring, const ColourBinner& binner)
{
	const auto median = FloorRing::median(ring);
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

FreeSpaceClassifier FloorAdaptation::classifier(const FreeSpaceClassifier& trained) const
{
	if (total_ <= 0) return trained;
	std::vector<double> p(counts_.size());
	for (std::size_t b = 0; b < p.size(); ++b) p[b] = counts_[b] / total_;
	return trained.alsoFreeUnder(p);
}

}  // namespace omnirange
