#pragma once
// Free-space classification (paper eq. (5)): a pixel is free floor when the
// histogram's P(colour) >= Theta. The decision is precomputed per bin, so
// classifying a pixel is three table look-ups and one more.

#include <omnirange/core/ColourModel.h>
#include <omnirange/core/PixelClassifier.h>
#include <omnirange/config/OptionsTable.h>

#include <cstdint>
#include <vector>

namespace cv
{
class Mat;
}

namespace omnirange
{
/** The values the classifier takes; the rangefinder's options table gives
 * its keys these ranges (threshold, obstacle_ratio, shadow_depth). */
inline constexpr Range kThresholdRange = Range::closed(0, 1);
inline constexpr Range kObstacleRatioRange = Range::closed(0, 1000);
inline constexpr Range kShadowDepthRange = Range::closed(0, 0.9);
inline constexpr Range kSureShareRange = Range::openLow(0, 1);

class FreeSpaceClassifier final : public PixelClassifier
{
   public:
	/** A colour is free when P(colour | floor) >= threshold (eq. (5)) and,
	 * with obstacle colours in the model and obstacle_ratio > 0, when also
	 * P(colour | floor) >= obstacle_ratio * P(colour | obstacle); both
	 * probabilities after a Gaussian of `smoothing` bins over the histogram
	 * (ColourHistogram::smoothedProbabilities). With shadow_depth > 0 a
	 * colour is also free when it is a floor colour in light down to
	 * 1 - shadow_depth times as strong that passes the same test (its
	 * P(colour | floor) is then the largest of the colours it darkens from)
	 * and that training never saw on an obstacle: the floor in shadow. A
	 * free colour is sure floor (kFree) when it is among the floor's most
	 * common colours that together hold `sure_share` of its training pixels,
	 * and, with obstacle colours in the model, P(colour | floor) >=
	 * sure_ratio * P(colour | obstacle); else doubtful (kDoubtfulFree).
	 * sure_share 1 and sure_ratio 0: every free colour is sure. Throws
	 * std::invalid_argument if the floor histogram is empty or a parameter
	 * is out of range. */
	FreeSpaceClassifier(const ColourModel& model, double threshold, double obstacle_ratio = 0.0,
						double smoothing = 0.0, double shadow_depth = 0.0, double sure_share = 1.0,
						double sure_ratio = 0.0);

	const ColourBinner& binner() const { return binner_; }

	/** true when the B, G, R pixel is free floor. */
	bool isFree(const std::uint8_t* bgr) const
	{
		return free_[binner_.binOf(bgr)] != kNotFree;
	}
	/** kNotFree, kFree or kDoubtfulFree for the B, G, R pixel. */
	std::uint8_t classOf(const std::uint8_t* bgr) const { return free_[binner_.binOf(bgr)]; }

	void classify(const std::uint8_t* bgr, const std::int32_t* pixels, int count, std::uint8_t* out) const override
	{
		for (int k = 0; k < count; ++k) out[k] = free_[binner_.binOf(bgr + 3 * static_cast<std::size_t>(pixels[k]))];
	}

	/** Whether colour bin `bin` is free floor. */
	bool isFreeBin(std::uint32_t bin) const { return free_.at(bin) != kNotFree; }
	/** Number of bins classified free. */
	std::size_t freeBinCount() const;

	/** A copy in which a bin is also free when `floor_probability[bin]`
	 * (another estimate of P(colour | floor), e.g. the recent floor's,
	 * FloorAdaptation.h) passes the same test as the trained one. */
	FreeSpaceClassifier alsoFreeUnder(const std::vector<double>& floor_probability) const;

   private:
	ColourBinner binner_;
	std::vector<std::uint8_t> free_;  // per bin: kNotFree, kFree or kDoubtfulFree
	std::vector<float> needed_;  // per bin: the P(colour | floor) it takes to be free
};

}  // namespace omnirange
