#pragma once
// omnirange-train's job as a library function: stream a rawlog, pair each
// omnicam image with the laser scan taken with it, and train the histogram
// (HistogramTrainer) on the selected pairs.

#include <omnirange/HistogramTrainer.h>
#include <omnirange/Rangefinder.h>

#include <string>

namespace omnirange
{
struct RawlogTrainingOptions
{
	std::string input;
	std::string omni_label{"OMNICAM"};
	std::string laser_label{"LASER"};
	double max_dt{0.1};  ///< [s] largest time between an image and its scan
	int every{1};  ///< use every N-th pair
	int first{0};  ///< skip the pairs before this one
	int max_frames{0};  ///< use at most this many pairs (0: all)
	int bins{ColourHistogram::kDefaultBins};
	ColourSpace space{ColourSpace::RGB};
	double laser_margin{0.10};  ///< [m]
	/** If not empty: write PREFIX_birdseye.png, PREFIX_laser.png and
	 * PREFIX_fused.png (paper Fig. 1) for the used pair `figures_frame`. */
	std::string figures_prefix;
	int figures_frame{0};
};

struct RawlogTrainingResult
{
	ColourHistogram histogram;
	int pairs{0};  ///< synchronised pairs found
	int used{0};  ///< pairs trained on
	std::size_t pixels{0};  ///< floor pixels counted
};

/** The camera, its pose and the base come from `params`. Throws
 * std::runtime_error naming the file on bad input, or when no image had a
 * laser scan (training needs both). */
RawlogTrainingResult trainFromRawlog(const RangefinderParams& params, const RawlogTrainingOptions& options,
									 const std::function<void(int)>& progress = {});

}  // namespace omnirange
