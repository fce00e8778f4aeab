#pragma once
// omnirange-train's job as a library function: stream a rawlog, pair each
// omnicam image with the laser scan taken with it, and train the histogram
// (HistogramTrainer) on the selected pairs.

#include <omnirange/core/Rangefinder.h>
#include <omnirange/io/ObservationPairer.h>
#include <omnirange/config/SensorLabels.h>
#include <omnirange/train/HistogramTrainer.h>

#include <string>
#include <utility>
#include <vector>

namespace omnirange
{
class Progress;

/** The section of omnirange-train's ini (-c) that holds the histogram's
 * keys: what a floor's training fixes once. The command line says which
 * log, its labels and which of its pairs a run uses. */
inline constexpr char kTrainingSection[] = "training";

struct RawlogTrainingOptions
{
	std::string input;
	std::string omni_label{kOmnicamLabel};
	std::string laser_label{kLaserLabel};
	double max_dt{kDefaultMaxPairingDt};  ///< [s] largest time between an image and its scan
	int every{1};  ///< use every N-th pair
	int first{0};  ///< skip the pairs before this one
	int max_frames{0};  ///< use at most this many pairs (0: all)
	int until{0};  ///< use only pairs before this one (0: to the end): train on a route's first part
	TrainingParams training;
	/** If not empty: keep the figures of the used pair `figures_frame`
	 * (RawlogTrainingResult::figures), for figureFiles() PREFIX_*.png. */
	std::string figures_prefix;
	int figures_frame{0};

	/** Whether the k-th image/laser pair of the rawlog is used (first, every, until). */
	bool selects(int k) const { return !((until > 0 && k >= until) || k < first || (k - first) % every != 0); }
	/** Throws std::invalid_argument on an impossible value. */
	void validate() const;
};

struct RawlogTrainingResult
{
	ColourModel model;  ///< the floor's colours, and the obstacles' where obstacle_band > 0
	int pairs{0};  ///< synchronised pairs seen
	int used{0};  ///< pairs trained on
	std::size_t pixels{0};  ///< floor pixels counted
	std::size_t obstacle_pixels{0};  ///< obstacle pixels counted
	/** The pair figures_frame's (paper Fig. 1), when figures_prefix is set:
	 * written by the caller with the histogram, all or none. */
	TrainingFrame figures;
};

/** The figures' files: PREFIX_birdseye.png, PREFIX_laser.png and PREFIX_fused.png with their images. */
std::vector<std::pair<std::string, cv::Mat>> figureFiles(const RawlogTrainingResult& r, const std::string& prefix);

/** The camera, its pose and the base come from `params`. Throws
 * std::runtime_error naming the file on bad input, or when no image had a
 * laser scan (training needs both). */
RawlogTrainingResult trainFromRawlog(const RangefinderParams& params, const RawlogTrainingOptions& options,
									 Progress* progress = nullptr);

}  // namespace omnirange
