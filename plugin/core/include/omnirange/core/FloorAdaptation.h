#pragma once
// Adapting to new light or a new floor without a laser (the paper's future
// work, for the small robot that never has one). The floor just outside the
// robot's base is floor nearly always; its colours, image after image, form
// a second estimate of P(colour | floor) that forgets slowly. A colour is
// free when the trained histogram says so (eq. (5)) or when it makes up as
// large a share of the recent floor as eq. (5) asks of the trained one (and,
// with the two-class model, beats the obstacles by the same ratio).
//
// Only pixels near the ring's median colour are learned, so an obstacle that
// touches a few directions of the ring (the robot passing a wall) is not
// learned as floor; one that fills most of it would be (docs/method.md
// measures what that costs). Images must come in the order they were taken.
// The Rangefinder owns one (Rangefinder::learnFloor) when floor_adaptation is on.

#include <omnirange/core/FreeSpaceClassifier.h>

#include <opencv2/core/matx.hpp>

#include <cstddef>
#include <vector>

namespace omnirange
{
class FloorAdaptation
{
   public:
	/** Over the bins of `trained`; `memory` [images] (at least 1) is how
	 * many images a colour seen once takes to fade to 1/e. */
	FloorAdaptation(const FreeSpaceClassifier& trained, double memory);

	/** Learns the colours of the next image's floor ring (FloorRing::colours). */
	void learn(const std::vector<cv::Vec3b>& ring, const ColourBinner& binner);
	/** `trained` with the recent floor's colours also free. */
	FreeSpaceClassifier classifier(const FreeSpaceClassifier& trained) const;

	std::size_t imagesLearned() const { return images_; }

   private:
	double keep_;  // per image, the weight old counts keep
	std::vector<double> counts_;  // per bin, decayed
	double total_{0};
	std::size_t images_{0};
};

}  // namespace omnirange
