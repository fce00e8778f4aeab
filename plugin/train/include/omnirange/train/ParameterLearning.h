#pragma once
// Learning the rangefinder's parameters from the laser (the paper's future
// work): the training part of a rawlog is split into pairs to train on and
// pairs held aside (every fourth); a histogram is trained per colour space
// and bin count on the first, and every candidate (those, Theta,
// obstacle_ratio, N, K, boundary model) scans the held-aside images and is
// scored against their laser scans. The best one wins, and its histogram is
// trained again on all the pairs; last, the winner's edge bias (EdgeBias.h)
// and doubt are learned with that histogram and kept if the held-aside pairs
// agree. Only the laser is used: it is what a user's training robot has.
// Other splits and light changes were measured and not adopted
// (docs/experiments.md, "Learning and validation").

#include <omnirange/core/Rangefinder.h>
#include <omnirange/train/ColourSeparation.h>
#include <omnirange/train/LaserComparison.h>
#include <omnirange/train/RawlogTraining.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace omnirange
{
class Progress;

struct LearningOptions
{
	std::vector<ColourSpace> spaces{ColourSpace::RGB, ColourSpace::Chroma};
	/** Down to 0.0001 was measured and not adopted: more of the spent worlds
	 * gained than lost, and the held-out meeting room lost 14 points
	 * (docs/results.md). */
	std::vector<double> thresholds{0.0025, 0.005, 0.01, 0.02, 0.035, 0.05, 0.075, 0.1};
	/** RangefinderParams::histogram_smoothing [bins]: as counted, or
	 * smoothed over about a bin (docs/results.md measures both). */
	std::vector<double> smoothings{0.0, 1.0};
	std::vector<double> obstacle_ratios{0.0, 1.0};  ///< 0: the one-class model
	std::vector<int> Ns{10, 20};
	std::vector<int> Ks{2, 4};
	/** Histogram bins per channel; empty: the training's bins and twice as
	 * many (at most 64). */
	std::vector<int> bins{};
	std::vector<BoundaryModel> boundary_models{BoundaryModel::Subpixel, BoundaryModel::Midpoint};
	/** PolarScannerParams::step_threshold, tried on the `step_candidates`
	 * best candidates of the grid above (scored with it off): the brightness
	 * step is for what colour cannot see, so it is tried with the colour
	 * models that do best without it. Empty: not tried. */
	std::vector<double> step_thresholds{0.15, 0.25, 0.35, 0.5};
	/** PolarScannerParams::step_sign, each tried with each threshold: which
	 * way a face differs from the floor is the deployment's (docs/method.md). */
	std::vector<StepSign> step_signs{StepSign::Either, StepSign::Brighter, StepSign::Darker};
	int step_candidates{32};
	/** Every `hold_out_every`-th selected pair is held aside to score the
	 * candidates on (every second was measured and not adopted). */
	int hold_out_every{4};
	int max_validation_pairs{40};  ///< the held-aside images are kept in memory (evenly thinned)
	/** When the lowest score is not CHROMA's and the best CHROMA candidate
	 * is behind it by no more than the held-aside frames' noise
	 * (withinNoiseOf), take the CHROMA one: the rest of a route brings
	 * changes of light the held-aside frames do not, and CHROMA is the
	 * space built to hold through them (docs/method.md, docs/results.md). */
	bool chroma_on_tie{true};
	/** Learn the winner's edge bias (EdgeBias.h) from its hits on every
	 * selected pair, scanned with the histogram it runs with, and keep it
	 * when it lowers the winner's score on the held-aside pairs. */
	bool fit_edge_bias{true};
	int edge_bias_min_samples{30};  ///< laser-confirmed hits a contrast bin needs

	/** The keys of [learning] in omnirange-train's ini: the grids of numbers
	 * and the switches above (the colour spaces, N, K and boundary models
	 * stay the code's). */
	static const OptionsTable<LearningOptions>& table();
};

/** The section of omnirange-train's ini (-c) that holds LearningOptions' keys. */
inline constexpr char kLearningSection[] = "learning";

/** One candidate and how it did on the held-aside pairs. */
struct LearnedCandidate
{
	ColourSpace space{ColourSpace::RGB};
	int bins{0};
	double threshold{0}, obstacle_ratio{0};
	double smoothing{0};  ///< [bins]
	int N{0}, K{0};
	BoundaryModel boundary{BoundaryModel::Subpixel};
	double step_threshold{0};  ///< PolarScannerParams::step_threshold; 0: off
	StepSign step_sign{StepSign::Either};  ///< PolarScannerParams::step_sign
	/** [m] mean over the laser's rays of the error: |laser - omni| where
	 * both see the boundary (at most 1.25), the false obstacle's shortfall
	 * where the laser sees nothing within max range, 1.25 for a rejected ray
	 * (a candidate that rejects what it cannot classify must not win). */
	double score{0};
	/** [m] the same error per held-aside image (in their order), for
	 * telling a difference from the frames' noise. */
	std::vector<double> frame_errors;
	/** [m] of each frame's error, the part from rays where the omnicam
	 * reads nearer than the laser (or a hit where the laser sees nothing):
	 * what an obstacle above the laser's plane, which the laser cannot
	 * see, costs a candidate that finds it. */
	std::vector<double> frame_shortfalls;
};

/** A histogram's training: colour space and bins per channel. */
using HistogramKey = std::pair<ColourSpace, int>;
inline HistogramKey histogramKeyOf(const LearnedCandidate& c) { return {c.space, c.bins}; }

/** The doubt learnDoubt chose for the winner (sure_floor_share,
 * sure_obstacle_ratio, sure_run),
 * and what it does on the held-aside pairs against the laser. */
struct DoubtChoice
{
	double sure_floor_share{1.0};
	double sure_obstacle_ratio{0.0};
	int sure_run{0};
	/** Of the laser rays whose return is within max range, the share seen
	 * through (read free more than kSeenThroughMargin past it), without any
	 * doubt and with the chosen one; of all laser rays, the share unsure. */
	double false_free_without{0}, false_free{0}, unsure{0};
};

/** What a ray read free past the laser costs against an unsure one when
 * learnDoubt weighs them: a robot collides by the first, it only slows or
 * turns by the second. */
inline constexpr double kFalseFreeCost = 10.0;
/** [m] learnDoubt counts a ray read free past the laser's return by more
 * than this: seen through, what doubt is for. A hit a few centimetres long
 * is where the edge was placed, which doubt cannot mend: weighed at 5 cm,
 * learning made 94 % of a gallery's rays unsure to cure its hits' spread. */
inline constexpr double kSeenThroughMargin = 0.25;

struct LearningResult
{
	RangefinderParams params;  ///< the start parameters with the winner's values
	ColourModel model;  ///< trained in the winner's colour space and bins, on every pair
	/** Every histogram the candidates used, trained as `model` was (on
	 * every pair): what any other candidate would have run with, for
	 * studying how the runners-up do on the rest of a route. */
	std::map<HistogramKey, ColourModel> models;
	TrainingParams training;  ///< how `model` was trained
	LearnedCandidate best;
	/** The lowest score, when a tie went to CHROMA (chroma_on_tie) and
	 * `best` is not it. */
	std::optional<LearnedCandidate> overruled;
	std::vector<LearnedCandidate> tried;
	int training_pairs{0}, validation_pairs{0};
	int refit_pairs{0};  ///< pairs the final histogram was trained on
	/** [m] the edge bias learned for the winner (empty: none learned) and
	 * the winner's score with it; `params` holds it only when that score is
	 * lower than `best.score`. */
	std::vector<double> edge_bias;
	double edge_bias_score{0};
	DoubtChoice doubt;
	ColourSeparation separation;  ///< of `model`, as `params` classify
};

/** What each selected pair is for. */
enum class PairRole
{
	Train,
	Validate,
	Unused  ///< held aside, but past max_validation_pairs
};
/** The roles of `selected` pairs in their order, as `options` split them. */
std::vector<PairRole> splitPairs(const LearningOptions& options, int selected);
/** `selected` pairs are enough for the split of `options`: some train and some validate. */
bool enoughToLearn(const LearningOptions& options, int selected);

/** One laser ray's part of LearnedCandidate::score, and whether the omnicam
 * read nearer than the laser there (LearnedCandidate::frame_shortfalls).
 * `hit`: the omnicam ray has a hit. */
struct RayError
{
	double error{0};  ///< [m]
	bool nearer{false};
};
RayError learningError(const RangePair& p, bool hit, double max_range);

/** `start` with the candidate's values: the parameters it runs with. */
RangefinderParams withCandidate(const RangefinderParams& start, const LearnedCandidate& c);

/** Throws std::runtime_error when the rawlog has too few image/laser pairs
 * (at least one to train on and one to validate). */
LearningResult learnParameters(const RangefinderParams& start, const RawlogTrainingOptions& training,
							   const LearningOptions& options = {}, Progress* progress = nullptr);

/** [m] A winner whose score is above this could not separate the floor
 * from what stands on it: on our fourteen worlds every one above it read
 * under 45 % of its rays within 5 cm of the truth (garage 0.117 m, shop
 * 0.203 m, office 0.258 m), and every one below it over 80 % but the lab
 * (51 %) and the warehouse (21 %) (docs/users.md, "What to expect"). */
inline constexpr double kPoorLearningScore = 0.10;

/** A one-line warning for a user when learning's best score is above
 * kPoorLearningScore; empty otherwise. */
std::string poorLearningWarning(const LearningResult& r);

/** The best candidate tried in another colour space than the winner's,
 * or none when only one was tried. When it scores within millimetres of
 * the winner, which of the two holds on the rest of a route is a coin
 * toss for the held-aside frames (the meeting room: 14 points,
 * docs/results.md); learnedIni names it so a user can check both. */
std::optional<LearnedCandidate> bestInOtherSpace(const LearningResult& r);
/** The `n` lowest-scoring candidates after the winner, in order: how near
 * its rivals came (a winner a few millimetres ahead of a rival with another
 * threshold is a choice the held-aside frames barely made). */
std::vector<LearnedCandidate> nearestRivals(const LearningResult& r, std::size_t n = 3);

/** Whether `a` scores no worse than `b` beyond the held-aside frames'
 * noise: over the frames both were scored on, the mean of a's error minus
 * b's is at most twice its standard error, and `a` is not worse on so many
 * more frames than better that a two-sided sign test rejects chance at 5 %
 * (false with fewer than 6 frames, with which that test cannot reject). */
bool withinNoiseOf(const LearnedCandidate& a, const LearnedCandidate& b);

/** The best CHROMA candidate of `tried` when `lowest` (the lowest score)
 * is not CHROMA and that one is within its noise (withinNoiseOf); none
 * otherwise (LearningOptions::chroma_on_tie). */
std::optional<LearnedCandidate> chromaOnTie(const std::vector<LearnedCandidate>& tried, const LearnedCandidate& lowest);

/** Every candidate tried, one CSV row each in the order tried, with its
 * score [m] and its error on each held-aside frame (space-separated): to
 * see how near the runners-up came, and on which frames. */
std::string candidatesCsv(const LearningResult& r);
/** The CSV columns that say which candidate a row is, and one candidate's
 * values for them (no line end). */
std::string candidateColumns();
std::string candidateColumns(const LearnedCandidate& c);
/** "0.012345 0.020000 ...": per-frame figures [m] in one CSV cell. */
std::string spaceSeparated(const std::vector<double>& values);

/** How learnedIni() begins: an ini that does not was written by hand, and
 * --learn does not replace it (config/Output.h's begins_with). */
inline constexpr char kLearnedIniBegins[] = "; Learned by omnirange-train --learn: ";

/** "colour space CHROMA, 13 bins, threshold 0.005, obstacle_ratio 0, smoothing 0, N 20, K 4, subpixel boundary, step 0.25". */
std::string describe(const LearnedCandidate& c);

/** The learned keys as an ini a user can read: a comment saying how they
 * were found, then the whole [rangefinder] section. */
std::string learnedIni(const LearningResult& r, const std::string& section = kRangefinderSection);

}  // namespace omnirange
