// Learning's split of the training pairs, the histogram trained for a change
// of light, and the winner's histogram trained again on every pair.

#include "../common/FactorySample.h"

#include <omnirange/train/ParameterLearning.h>
#include <omnirange/train/RawlogTraining.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include <algorithm>

using namespace omnirange;
using test::kSample;

namespace
{
int countOf(const std::vector<PairRole>& roles, PairRole role)
{
	return static_cast<int>(std::count(roles.begin(), roles.end(), role));
}

/** The factory sample's pairs before `until`. */
RawlogTrainingOptions samplePairs(int until)
{
	RawlogTrainingOptions o;
	o.input = kSample;
	o.until = until;
	return o;
}

/** A grid of one candidate (no brightness step, no shadow): what a test sets on top
 * is all that varies. */
LearningOptions oneCandidate()
{
	LearningOptions lo;
	lo.spaces = {ColourSpace::RGB}, lo.bins = {13}, lo.light_changes = {0.0}, lo.thresholds = {0.05};
	lo.obstacle_ratios = {0.0}, lo.smoothings = {0.0}, lo.Ns = {20}, lo.Ks = {2};
	lo.boundary_models = {BoundaryModel::Subpixel}, lo.step_thresholds.clear(), lo.shadow_depths.clear();
	return lo;
}

std::uint32_t occupiedBins(const ColourHistogram& h)
{
	const int n = h.binsPerChannel();
	std::uint32_t occupied = 0;
	for (std::uint32_t b = 0; b < static_cast<std::uint32_t>(n * n * n); ++b) occupied += h.count(b) > 0;
	return occupied;
}
}  // namespace

TEST(ParameterLearning, TheLaterSplitHoldsAsideTheLastQuarterOfThePairs)
{
	LearningOptions lo;
	lo.split = ValidationSplit::Later;
	const auto roles = splitPairs(lo, 12);
	ASSERT_EQ(roles.size(), 12u);
	for (int s = 0; s < 12; ++s) EXPECT_EQ(roles[s], s >= 9 ? PairRole::Validate : PairRole::Train) << s;
}

TEST(ParameterLearning, TheInterleavedSplitHoldsAsideEveryFourthPair)
{
	const auto roles = splitPairs(LearningOptions{}, 12);  // the default
	for (int s = 0; s < 12; ++s) EXPECT_EQ(roles[s], s % 4 == 3 ? PairRole::Validate : PairRole::Train) << s;
}

TEST(ParameterLearning, HeldAsidePairsAreThinnedEvenlyToTheCap)
{
	LearningOptions lo;
	lo.split = ValidationSplit::Later;
	lo.max_validation_pairs = 10;
	const auto roles = splitPairs(lo, 100);
	// 25 held aside (75..99), 10 of them kept: 75, 77, 80, 82, 85, ..., 97.
	EXPECT_EQ(countOf(roles, PairRole::Train), 75);
	EXPECT_EQ(countOf(roles, PairRole::Validate), 10);
	EXPECT_EQ(countOf(roles, PairRole::Unused), 15);
	for (int s : {75, 77, 80, 82, 85, 87, 90, 92, 95, 97}) EXPECT_EQ(roles[s], PairRole::Validate) << s;
	EXPECT_EQ(roles[99], PairRole::Unused);
}

TEST(ParameterLearning, OnePairIsNoSplit)
{
	LearningOptions lo;
	lo.split = ValidationSplit::Later;
	EXPECT_EQ(countOf(splitPairs(lo, 1), PairRole::Validate), 0);
	EXPECT_EQ(countOf(splitPairs(lo, 2), PairRole::Validate), 1);
	EXPECT_THROW(validationSplitFromString("random"), std::invalid_argument);
}

TEST(HistogramTraining, ALightChangeCountsEveryPixelAsSeenAndInTwoOtherLights)
{
	const RangefinderParams rp;
	RawlogTrainingOptions o;
	o.input = kSample;
	o.max_frames = 2;
	const ColourHistogram plain = trainFromRawlog(rp, o).model.floor;
	o.training.light_change = 0.15;
	const ColourHistogram lit = trainFromRawlog(rp, o).model.floor;
	ASSERT_GT(plain.total(), 0u);
	EXPECT_EQ(lit.total(), 3 * plain.total());
	for (std::uint32_t b = 0; b < 13u * 13u * 13u; ++b) ASSERT_GE(lit.count(b), plain.count(b)) << b;
	EXPECT_GT(occupiedBins(lit), occupiedBins(plain));
	o.training.light_change = 1.0;
	EXPECT_THROW(trainFromRawlog(rp, o), std::invalid_argument);
}

TEST(ParameterLearning, BlocksAreRunsOfConsecutivePairsAndEveryPairTrains)
{
	LearningOptions lo;
	lo.split = ValidationSplit::Blocks;
	const std::vector<int> block = blockOfPairs(lo, 10);  // 4 blocks by default
	EXPECT_EQ(block, (std::vector<int>{0, 0, 0, 1, 1, 2, 2, 2, 3, 3}));
	lo.blocks = 20;  // never more blocks than pairs
	EXPECT_EQ(blockOfPairs(lo, 3), (std::vector<int>{0, 1, 2}));
	EXPECT_EQ(blockOfPairs(LearningOptions{}, 5), (std::vector<int>(5, 0)));  // the default split has one

	lo.max_validation_pairs = 5;
	const auto roles = splitPairs(lo, 10);
	EXPECT_EQ(countOf(roles, PairRole::Validate), 5);  // evenly: 0, 2, 4, 6, 8
	EXPECT_EQ(countOf(roles, PairRole::Unused), 0);  // the rest still train the other blocks
	for (int s : {0, 2, 4, 6, 8}) EXPECT_EQ(roles[s], PairRole::Validate) << s;
	EXPECT_EQ(validationSplitFromString("blocks"), ValidationSplit::Blocks);
	EXPECT_THROW(validationSplitFromString("folds"), std::invalid_argument);
}

TEST(ParameterLearning, WithBlocksEveryPairIsScoredAndTheHistogramHasThemAll)
{
	const RangefinderParams rp;
	RawlogTrainingOptions o = samplePairs(12);
	LearningOptions lo = oneCandidate();  // only the split matters here
	lo.split = ValidationSplit::Blocks, lo.blocks = 3;
	const LearningResult r = learnParameters(rp, o, lo);
	EXPECT_EQ(r.training_pairs, 12);
	EXPECT_EQ(r.validation_pairs, 12);
	EXPECT_EQ(r.refit_pairs, 12);
	EXPECT_EQ(r.model.floor.total(), trainFromRawlog(rp, o).model.floor.total());
	EXPECT_NE(learnedIni(r).find("3 blocks of consecutive pairs"), std::string::npos);
	lo.blocks = 1;  // a block would be scored on its own counts
	EXPECT_THROW(learnParameters(rp, o, lo), std::invalid_argument);
}

TEST(ParameterLearning, TheWinnersHistogramIsTrainedAgainOnEveryPair)
{
	const RangefinderParams rp;
	RawlogTrainingOptions o = samplePairs(12);
	LearningOptions lo = oneCandidate();  // only the split and the refit matter here
	lo.split = ValidationSplit::Later;  // train on pairs 0..8, validate on 9..11
	const LearningResult refitted = learnParameters(rp, o, lo);
	EXPECT_EQ(refitted.training_pairs, 9);
	EXPECT_EQ(refitted.validation_pairs, 3);
	EXPECT_EQ(refitted.refit_pairs, 12);
	EXPECT_EQ(refitted.model.floor.total(), trainFromRawlog(rp, o).model.floor.total());

	lo.refit = false;
	const LearningResult first = learnParameters(rp, o, lo);
	EXPECT_EQ(first.refit_pairs, 0);
	o.until = 9;  // the nine pairs before the held-aside ones
	EXPECT_EQ(first.model.floor.total(), trainFromRawlog(rp, o).model.floor.total());
}

TEST(ParameterLearning, TheBrightnessStepIsTriedOnTheGridsBestAndWinsOnlyByItsScore)
{
	const RangefinderParams rp;
	RawlogTrainingOptions o = samplePairs(12);
	LearningOptions lo = oneCandidate();
	lo.thresholds = {0.01, 0.075};
	lo.step_thresholds = {0.25, 0.5}, lo.step_candidates = 1;
	const LearningResult r = learnParameters(rp, o, lo);
	ASSERT_EQ(r.tried.size(), 4u);  // the grid of two, then the step twice on its better one
	const double grid_best = std::min(r.tried[0].score, r.tried[1].score);
	EXPECT_EQ(r.tried[0].step_threshold, 0.0);
	EXPECT_EQ(r.tried[1].step_threshold, 0.0);
	for (std::size_t i = 2; i < 4; ++i)
	{
		// The step went to a grid candidate with the best score (either one, on a tie).
		const LearnedCandidate& base = r.tried[i].threshold == r.tried[0].threshold ? r.tried[0] : r.tried[1];
		EXPECT_EQ(r.tried[i].threshold, base.threshold);
		EXPECT_EQ(base.score, grid_best);
		EXPECT_EQ(r.tried[i].step_threshold, lo.step_thresholds[i - 2]);
	}
	lo.step_thresholds = {0.0};
	EXPECT_THROW(learnParameters(rp, o, lo), std::invalid_argument);  // 0 is the grid itself
	lo.step_thresholds = {0.5, 0.25, 0.5};
	EXPECT_EQ(learnParameters(rp, o, lo).tried.size(), 4u);  // each threshold scored once
	double lowest = 1e9;
	for (const auto& c : r.tried) lowest = std::min(lowest, c.score);
	EXPECT_EQ(r.best.score, lowest);
	EXPECT_EQ(r.params.scanner.step_threshold, r.best.step_threshold);
	EXPECT_NE(learnedIni(r).find("\nstep_threshold = "), std::string::npos);

	lo.step_thresholds.clear();  // not tried
	EXPECT_EQ(learnParameters(rp, o, lo).tried.size(), 2u);
}

TEST(ParameterLearning, TheFloorInShadowIsTriedOnTheGridsBestEachDepthOnce)
{
	const RangefinderParams rp;
	RawlogTrainingOptions o = samplePairs(12);
	LearningOptions lo = oneCandidate();
	lo.thresholds = {0.01, 0.075};
	lo.step_candidates = 1, lo.shadow_depths = {0.5, 0.3, 0.5};
	const LearningResult r = learnParameters(rp, o, lo);
	ASSERT_EQ(r.tried.size(), 4u);  // the grid of two, then two depths on its better one
	const double grid_best = std::min(r.tried[0].score, r.tried[1].score);
	for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(r.tried[i].shadow_depth, 0.0);
	EXPECT_EQ(r.tried[2].shadow_depth, 0.3);
	EXPECT_EQ(r.tried[3].shadow_depth, 0.5);
	for (std::size_t i = 2; i < 4; ++i)
	{
		const LearnedCandidate& base = r.tried[i].threshold == r.tried[0].threshold ? r.tried[0] : r.tried[1];
		EXPECT_EQ(base.score, grid_best);
		EXPECT_EQ(r.tried[i].step_threshold, 0.0);
	}
	EXPECT_EQ(r.params.shadow_depth, r.best.shadow_depth);
	EXPECT_NE(learnedIni(r).find("\nshadow_depth = "), std::string::npos);
	EXPECT_NE(describe(r.tried[3]).find("shadow 0.5"), std::string::npos) << describe(r.tried[3]);
	// The CSV of candidates: a header, then one row per candidate in the order tried.
	const std::string csv = candidatesCsv(r);
	EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
	EXPECT_EQ(csv.rfind("colour_space,bins,", 0), 0u);
	char last[64];
	std::snprintf(last, sizeof last, ",0.5,%.6f\n", r.tried[3].score);
	EXPECT_EQ(csv.substr(csv.size() - std::strlen(last)), last) << csv;
	lo.shadow_depths = {0.95};
	EXPECT_THROW(learnParameters(rp, o, lo), std::invalid_argument);
}

TEST(ParameterLearning, APoorWinnerIsNamedInTheIniAndOnlyThen)
{
	LearningResult r;
	r.best.score = 0.2027;  // the shop's
	const std::string poor = learnedIni(r);
	const auto warning = poor.find("; WARNING: ");
	ASSERT_NE(warning, std::string::npos);
	EXPECT_NE(poor.find("0.203 m"), std::string::npos);
	EXPECT_LT(warning, poor.find("[rangefinder]"));  // a comment before the section, not inside it
	EXPECT_FALSE(poorLearningWarning(r).empty());
	r.best.score = 0.0460;  // the hallway's
	EXPECT_EQ(learnedIni(r).find("WARNING"), std::string::npos);
	EXPECT_TRUE(poorLearningWarning(r).empty());
}

TEST(ParameterLearning, TheIniNamesTheBestInTheOtherColourSpace)
{
	// The meeting room's near tie: RGB won by 1.8 mm over CHROMA.
	LearningResult r;
	const auto candidate = [](ColourSpace space, double threshold, double score) {
		LearnedCandidate c;
		c.space = space, c.bins = 13, c.threshold = threshold, c.score = score;
		return c;
	};
	r.tried = {candidate(ColourSpace::RGB, 0.0001, 0.0450), candidate(ColourSpace::Chroma, 0.005, 0.0490),
			   candidate(ColourSpace::Chroma, 0.02, 0.0468), candidate(ColourSpace::RGB, 0.01, 0.0455)};
	r.best = r.tried[0];
	const auto other = bestInOtherSpace(r);
	ASSERT_TRUE(other.has_value());
	EXPECT_EQ(other->space, ColourSpace::Chroma);
	EXPECT_EQ(other->threshold, 0.02);
	const std::string ini = learnedIni(r);
	const auto line = ini.find("; The best in another colour space: colour space CHROMA");
	ASSERT_NE(line, std::string::npos) << ini;
	EXPECT_NE(ini.find("(1.8 mm more)"), std::string::npos) << ini;
	EXPECT_LT(line, ini.find("[rangefinder]"));

	r.tried.erase(r.tried.begin() + 1, r.tried.begin() + 3);  // RGB only
	EXPECT_FALSE(bestInOtherSpace(r).has_value());
	EXPECT_EQ(learnedIni(r).find("another colour space"), std::string::npos);
}

TEST(ParameterLearning, AFilterWindowTheImageCannotHoldIsNoCandidate)
{
	// A camera whose centre sits high in the frame leaves room above the
	// scan circle for N = 10's window but not for N = 20's.
	RangefinderParams rp;
	rp.scanner.filter.N = 10;
	const auto fits = [&](int N) {
		PolarScannerParams s = rp.scanner;
		s.filter.N = N;
		try
		{
			PolarScanner(OmniCameraModel(rp.camera), s);
			return true;
		}
		catch (const std::invalid_argument&)
		{
			return false;
		}
	};
	for (rp.camera.cy = 100; rp.camera.cy < 384 && !(fits(10) && !fits(20));) rp.camera.cy += 1;
	ASSERT_TRUE(fits(10) && !fits(20)) << "no centre row separates the two windows";

	RawlogTrainingOptions o = samplePairs(8);
	LearningOptions lo = oneCandidate();
	lo.Ns = {10, 20};
	const LearningResult r = learnParameters(rp, o, lo);
	ASSERT_EQ(r.tried.size(), 1u);
	EXPECT_EQ(r.tried[0].N, 10);

	lo.Ns = {20};
	EXPECT_THROW(learnParameters(rp, o, lo), std::invalid_argument);
}
