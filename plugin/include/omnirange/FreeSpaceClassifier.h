#pragma once
// Free-space classification (paper eq. (5)): a pixel is free floor when the
// histogram's P(colour) >= Theta. The decision is precomputed per bin, so
// classifying a pixel is three table look-ups and one more.

#include <omnirange/ColourHistogram.h>

#include <cstdint>
#include <vector>

namespace cv
{
class Mat;
}

namespace omnirange
{
class FreeSpaceClassifier
{
   public:
	/** Throws std::invalid_argument if the histogram is empty or the
	 * threshold is outside [0, 1]. */
	FreeSpaceClassifier(const ColourHistogram& hist, double threshold);

	double threshold() const { return threshold_; }
	const ColourBinner& binner() const { return binner_; }

	/** true when the B, G, R pixel is free floor. */
	bool isFree(const std::uint8_t* bgr) const
	{
		return free_[binner_.binOf(bgr)] != 0;
	}

	/** 8-bit mask of a BGR image: 255 free, 0 not (for diagnostics). */
	cv::Mat classify(const cv::Mat& bgr) const;

	/** Number of bins classified free. */
	std::size_t freeBinCount() const;

   private:
	ColourBinner binner_;
	double threshold_;
	std::vector<std::uint8_t> free_;  // per bin: 1 free, 0 not
};

}  // namespace omnirange
