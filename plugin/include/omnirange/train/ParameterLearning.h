#pragma once
// Learning the rangefinder's parameters from the laser (the paper's future
// work): the training part of a rawlog is split into pairs to train on and
// pairs held aside; a histogram is trained per colour space and bin count on
// the first, and every candidate (colour space, bins, Theta, obstacle_ratio,
// N, K, boundary model) scans the held-aside images and is scored against
// their laser scans. The best one
// wins. Only the laser is used: it is what a user's training robot has.

#include <omnirange/core/Rangefinder.h>
#include <omnirange/train/RawlogTraining.h>

#include <string>
#include <vector>

namespace omnirange
{
class Progress;

struct LearningOptions
{
	std::vector<ColourSpace> spaces{ColourSpace::RGB, ColourSpace::Chroma};
	std::vector<double> thresholds{0.0025, 0.005, 0.01, 0.02, 0.035, 0.05, 0.075, 0.1};
	std::vector<double> obstacle_ratios{0.0, 1.0};  ///< 0: the one-class model
	std::vector<int> Ns{10, 20};
	std::vector<int> Ks{2, 4};
	/** Histogram bins per channel; empty: the training's bins and twice as
	 * many (at most 64). */
	std::vector<int> bins{};
	std::vector<BoundaryModel> boundary_models{BoundaryModel::Subpixel, BoundaryModel::Midpoint};
	int hold_out_every{4};  ///< every n-th selected pair is held aside for validation
	int max_validation_pairs{40};  ///< the held-aside images are kept in memory
};

/** One candidate and how it did on the held-aside pairs. */
struct LearnedCandidate
{
	ColourSpace space{ColourSpace::RGB};
	int bins{0};
	double threshold{0}, obstacle_ratio{0};
	int N{0}, K{0};
	BoundaryModel boundary{BoundaryModel::Subpixel};
	/** [m] mean over the laser's rays of the error: |laser - omni| where
	 * both see the boundary (at most 1.25), the false obstacle's shortfall
	 * where the laser sees nothing within max range, 1.25 for a rejected ray
	 * (a candidate that rejects what it cannot classify must not win). */
	double score{0};
};

struct LearningResult
{
	RangefinderParams params;  ///< the start parameters with the winner's values
	ColourModel model;  ///< trained in the winner's colour space
	LearnedCandidate best;
	std::vector<LearnedCandidate> tried;
	int training_pairs{0}, validation_pairs{0};
};

/** Throws std::runtime_error when the rawlog has too few image/laser pairs
 * (at least one to train on and one to validate). */
LearningResult learnParameters(const RangefinderParams& start, const RawlogTrainingOptions& training,
							   const LearningOptions& options = {}, Progress* progress = nullptr);

/** "colour space CHROMA, 13 bins, threshold 0.005, obstacle_ratio 0, N 20, K 4, subpixel boundary". */
std::string describe(const LearnedCandidate& c);

/** The learned keys as an ini a user can read: a comment saying how they
 * were found, then the whole [rangefinder] section. */
std::string learnedIni(const LearningResult& r, const std::string& section = "rangefinder");

}  // namespace omnirange
