// Learning's split of the training pairs, the histogram trained for a change
// of light, and the winner's histogram trained again on every pair.

#include "../common/FactorySample.h"

#include <omnirange/train/EdgeBiasLearning.h>
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

/** A grid of one candidate (no brightness step): what a test sets on top
 * is all that varies. */
LearningOptions oneCandidate()
{
	LearningOptions lo;
	lo.spaces = {ColourSpace::RGB}, lo.bins = {13}, lo.thresholds = {0.05};
	lo.obstacle_ratios = {0.0}, lo.smoothings = {0.0}, lo.Ns = {20}, lo.Ks = {2};
	lo.boundary_models = {BoundaryModel::Subpixel}, lo.step_thresholds.clear();
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

TEST(ParameterLearning, EveryFourthPairIsHeldAside)
{
	const auto roles = splitPairs(LearningOptions{}, 12);  // the default
	ASSERT_EQ(roles.size(), 12u);
	for (int s = 0; s < 12; ++s) EXPECT_EQ(roles[s], s % 4 == 3 ? PairRole::Validate : PairRole::Train) << s;
}

TEST(ParameterLearning, HeldAsidePairsAreThinnedEvenlyToTheCap)
{
	LearningOptions lo;
	lo.max_validation_pairs = 10;
	const auto roles = splitPairs(lo, 100);
	// 25 held aside (3, 7, ..., 99), 10 of them kept: the 0th, 2nd, 5th, 7th, 10th, ... of them.
	EXPECT_EQ(countOf(roles, PairRole::Train), 75);
	EXPECT_EQ(countOf(roles, PairRole::Validate), 10);
	EXPECT_EQ(countOf(roles, PairRole::Unused), 15);
	for (int j : {0, 2, 5, 7, 10, 12, 15, 17, 20, 22}) EXPECT_EQ(roles[4 * j + 3], PairRole::Validate) << j;
	EXPECT_EQ(roles[99], PairRole::Unused);
}

TEST(ParameterLearning, EnoughToLearnMeansSomePairsTrainAndSomeValidate)
{
	// The check an experiment makes before its simulation.
	LearningOptions lo;  // every fourth pair validates
	EXPECT_FALSE(enoughToLearn(lo, 3));
	EXPECT_TRUE(enoughToLearn(lo, 4));
	lo.hold_out_every = 2;
	EXPECT_FALSE(enoughToLearn(lo, 1));
	EXPECT_TRUE(enoughToLearn(lo, 2));
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

TEST(ParameterLearning, TheWinnersHistogramIsTrainedAgainOnEveryPair)
{
	const RangefinderParams rp;
	RawlogTrainingOptions o = samplePairs(12);
	const LearningResult r = learnParameters(rp, o, oneCandidate());  // pairs 3, 7 and 11 validate
	EXPECT_EQ(r.training_pairs, 9);
	EXPECT_EQ(r.validation_pairs, 3);
	EXPECT_EQ(r.refit_pairs, 12);
	EXPECT_EQ(r.model.floor.total(), trainFromRawlog(rp, o).model.floor.total());
	EXPECT_NE(learnedIni(r).find("trained again on all 12 pairs"), std::string::npos);
}

TEST(ParameterLearning, TheBrightnessStepIsTriedOnTheGridsBestAndWinsOnlyByItsScore)
{
	const RangefinderParams rp;
	RawlogTrainingOptions o = samplePairs(12);
	LearningOptions lo = oneCandidate();
	lo.thresholds = {0.01, 0.075};
	lo.step_thresholds = {0.25, 0.5}, lo.step_candidates = 1, lo.step_signs = {StepSign::Either};
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
	// The CSV of candidates: a header, then one row per candidate in the order tried.
	const std::string csv = candidatesCsv(r);
	EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
	EXPECT_EQ(csv.rfind("colour_space,bins,", 0), 0u);
	const std::string last_row = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
	char step_and_score[64];
	std::snprintf(step_and_score, sizeof step_and_score, ",0.5,either,%.6f,", r.tried[3].score);
	EXPECT_NE(last_row.find(step_and_score), std::string::npos) << last_row;
	const std::string frames = last_row.substr(last_row.rfind(',') + 1);
	EXPECT_EQ(static_cast<std::size_t>(std::count(frames.begin(), frames.end(), ' ')) + 1,
			  r.tried[3].frame_errors.size());
	// Each frame's error has a part from rays that read nearer than the
	// laser; the frames' errors average to the score (every frame has the
	// laser's 181 rays); every histogram tried is kept, the winner's too.
	for (const LearnedCandidate& c : r.tried)
	{
		ASSERT_EQ(c.frame_shortfalls.size(), c.frame_errors.size());
		double mean = 0;
		for (std::size_t f = 0; f < c.frame_errors.size(); ++f)
		{
			EXPECT_GE(c.frame_shortfalls[f], 0.0);
			EXPECT_LE(c.frame_shortfalls[f], c.frame_errors[f] + 1e-12);
			mean += c.frame_errors[f] / static_cast<double>(c.frame_errors.size());
		}
		EXPECT_NEAR(mean, c.score, 1e-9);
		EXPECT_EQ(r.models.count(histogramKeyOf(c)), 1u);
	}

	lo.step_thresholds.clear();  // not tried
	EXPECT_EQ(learnParameters(rp, o, lo).tried.size(), 2u);
}

TEST(ParameterLearning, EachStepThresholdIsTriedWithEachSignAndTheWinnersSignIsLearned)
{
	const RangefinderParams rp;
	RawlogTrainingOptions o = samplePairs(12);
	LearningOptions lo = oneCandidate();
	lo.step_thresholds = {0.25}, lo.step_candidates = 1;
	lo.step_signs = {StepSign::Darker, StepSign::Brighter, StepSign::Darker};
	const LearningResult r = learnParameters(rp, o, lo);
	ASSERT_EQ(r.tried.size(), 3u);  // the grid's one, then the step once per sign
	EXPECT_EQ(r.tried[1].step_sign, StepSign::Brighter);
	EXPECT_EQ(r.tried[2].step_sign, StepSign::Darker);
	EXPECT_EQ(r.params.scanner.step_sign, r.best.step_sign);
	EXPECT_NE(candidatesCsv(r).find(",0.25,darker,"), std::string::npos);
	EXPECT_NE(describe(r.tried[1]).find("step 0.25 brighter"), std::string::npos);
	EXPECT_NE(describe(r.tried[0]).find("step 0"), std::string::npos);
	lo.step_signs.clear();  // no sign: the step is not tried
	EXPECT_EQ(learnParameters(rp, o, lo).tried.size(), 1u);
}

TEST(ParameterLearning, TheEdgeBiasIsLearnedForTheWinnerAndKeptOnlyWhenItLowersItsScore)
{
	RangefinderParams rp;
	RawlogTrainingOptions o = samplePairs(12);
	LearningOptions lo = oneCandidate();
	lo.fit_edge_bias = false;
	const LearningResult without = learnParameters(rp, o, lo);
	EXPECT_TRUE(without.edge_bias.empty());
	EXPECT_TRUE(without.params.scanner.edge_bias.empty());
	EXPECT_EQ(learnedIni(without).find("Edge bias"), std::string::npos);
	// A start ini that carries an edge bias (an earlier learning's) does not
	// enter the candidates' scores: it is learned again for the winner.
	rp.scanner.edge_bias.assign(kEdgeContrastBins, 0.3);
	lo.fit_edge_bias = true;
	const LearningResult r = learnParameters(rp, o, lo);
	ASSERT_EQ(r.tried.size(), 1u);
	EXPECT_EQ(r.tried[0].score, without.tried[0].score);
	ASSERT_FALSE(r.edge_bias.empty());  // the factory sample's hits fill a contrast bin
	for (const double b : r.edge_bias) EXPECT_LE(std::abs(b), kEdgeBiasMaxDifference);
	const bool kept = r.edge_bias_score < r.best.score;
	EXPECT_EQ(r.params.scanner.edge_bias, kept ? r.edge_bias : std::vector<double>());
	const std::string ini = learnedIni(r);
	EXPECT_NE(ini.find(kept ? "; Edge bias" : "not kept"), std::string::npos) << ini;
	EXPECT_EQ(ini.find("\nedge_bias = \n") == std::string::npos, kept) << ini;
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

TEST(ParameterLearning, TheIniNamesTheNearestRivalsAndHowFarBehindThey)
{
	LearningResult r;
	const auto candidate = [](double threshold, double score) {
		LearnedCandidate c;
		c.bins = 13, c.threshold = threshold, c.score = score;
		return c;
	};
	r.tried = {candidate(0.005, 0.2580), candidate(0.04, 0.2610), candidate(0.01, 0.2585),
			   candidate(0.08, 0.3000), candidate(0.02, 0.2599)};
	r.best = r.tried[0];
	const auto rivals = nearestRivals(r);
	ASSERT_EQ(rivals.size(), 3u);  // the winner is not its own rival; the worst is left out
	EXPECT_EQ(rivals[0].threshold, 0.01);
	EXPECT_EQ(rivals[1].threshold, 0.02);
	EXPECT_EQ(rivals[2].threshold, 0.04);
	const std::string ini = learnedIni(r);
	const auto line = ini.find(";   +0.5 mm: colour space RGB, 13 bins, threshold 0.01,");
	ASSERT_NE(line, std::string::npos) << ini;
	EXPECT_LT(ini.find("; The nearest rivals"), line);
	EXPECT_NE(ini.find(";   +3.0 mm: "), std::string::npos) << ini;
	EXPECT_EQ(ini.find(";   +42.0 mm: "), std::string::npos) << ini;
	EXPECT_LT(line, ini.find("[rangefinder]"));
	r.tried = {r.best};
	EXPECT_EQ(learnedIni(r).find("nearest rivals"), std::string::npos);
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

TEST(ParameterLearning, WithinNoiseIsTwiceTheStandardErrorOfThePairedDifference)
{
	LearnedCandidate a, b;
	b.frame_errors = {0.05, 0.06, 0.04, 0.05, 0.05, 0.06};
	a.frame_errors = {0.051, 0.061, 0.041, 0.051, 0.051, 0.061};  // 1 mm worse on every frame: no noise at all
	EXPECT_FALSE(withinNoiseOf(a, b));
	a.frame_errors = {0.06, 0.052, 0.052, 0.044, 0.06, 0.052};  // 1 mm worse on average, frames disagreeing by ~1 cm
	EXPECT_TRUE(withinNoiseOf(a, b));
	a.frame_errors = {0.04, 0.05, 0.03, 0.04, 0.04, 0.05};  // better: within noise whatever the noise
	EXPECT_TRUE(withinNoiseOf(a, b));
	a.frame_errors = {0.2, 0.3, 0.25, 0.2, 0.2, 0.3};
	EXPECT_FALSE(withinNoiseOf(a, b));
	a.frame_errors.resize(5), b.frame_errors.resize(5);  // five frames: too few for the sign test
	a.frame_errors = {0.04, 0.05, 0.03, 0.04, 0.04};
	EXPECT_FALSE(withinNoiseOf(a, b));
	// Worse on 10 of 12 frames, by a little, with two frames far better:
	// the mean is within noise, the sign test is not (p = 0.039).
	b.frame_errors.assign(12, 0.05);
	a.frame_errors.assign(10, 0.06);
	a.frame_errors.push_back(0.0), a.frame_errors.push_back(0.0);
	EXPECT_FALSE(withinNoiseOf(a, b));
	a.frame_errors[9] = 0.0;  // worse on 9 of 12 (p = 0.146): chance
	EXPECT_TRUE(withinNoiseOf(a, b));
}

TEST(ParameterLearning, ATieGoesToTheBestChromaCandidate)
{
	LearnedCandidate rgb, chroma_best, chroma_other;
	rgb.space = ColourSpace::RGB, rgb.frame_errors = {0.05, 0.06, 0.04, 0.05, 0.05, 0.06}, rgb.score = 0.0517;
	chroma_best.space = ColourSpace::Chroma, chroma_best.threshold = 0.01;
	chroma_best.frame_errors = {0.06, 0.052, 0.052, 0.044, 0.06, 0.052}, chroma_best.score = 0.0533;
	chroma_other.space = ColourSpace::Chroma, chroma_other.threshold = 0.05;
	chroma_other.frame_errors = {0.3, 0.3, 0.3, 0.3, 0.3, 0.3}, chroma_other.score = 0.3;
	const std::vector<LearnedCandidate> tried{chroma_other, rgb, chroma_best};
	const auto kept = chromaOnTie(tried, rgb);
	ASSERT_TRUE(kept);
	EXPECT_EQ(kept->threshold, 0.01);  // the best CHROMA candidate, not the first
	EXPECT_FALSE(chromaOnTie(tried, chroma_best));  // CHROMA already
	EXPECT_FALSE(chromaOnTie({rgb, chroma_other}, rgb));  // CHROMA far behind
	EXPECT_FALSE(chromaOnTie({rgb}, rgb));  // no CHROMA candidate
}

TEST(ParameterLearning, LearningKeepsTheLowestScoreWhenChromaIsClearlyBehind)
{
	// The maze sample: RGB scores lowest and CHROMA is worse on every
	// held-aside frame, so the rule changes nothing; the wiring of a tie is
	// the test above.
	const RangefinderParams rp = RangefinderParams::loadFromFile(test::kSource + "/ini/maze.ini", "rangefinder");
	RawlogTrainingOptions o = samplePairs(12);
	o.input = test::kSource + "/rawlogs/maze-sample.rawlog";
	LearningOptions lo = oneCandidate();
	lo.spaces = {ColourSpace::RGB, ColourSpace::Chroma}, lo.thresholds = {0.01}, lo.smoothings = {1.0}, lo.Ns = {10};
	lo.hold_out_every = 2;  // six frames to validate on: the fewest the rule decides with
	const LearningResult r = learnParameters(rp, o, lo);
	ASSERT_GE(r.validation_pairs, 6);
	for (const auto& c : r.tried) EXPECT_EQ(c.frame_errors.size(), static_cast<std::size_t>(r.validation_pairs));
	ASSERT_EQ(r.tried.size(), 2u);
	const LearnedCandidate& rgb = r.tried[0].space == ColourSpace::RGB ? r.tried[0] : r.tried[1];
	const LearnedCandidate& chroma = r.tried[0].space == ColourSpace::RGB ? r.tried[1] : r.tried[0];
	ASSERT_LT(rgb.score, chroma.score);
	EXPECT_FALSE(withinNoiseOf(chroma, rgb));
	EXPECT_EQ(r.best.space, ColourSpace::RGB);
	EXPECT_FALSE(r.overruled);
	EXPECT_EQ(learnedIni(r).find("CHROMA was kept"), std::string::npos);
	// The same learning run with an RGB candidate the rule must overrule:
	// CHROMA's own errors, a hair lower on one frame and higher on another.
	LearnedCandidate twin = chroma;
	twin.space = ColourSpace::RGB, twin.frame_errors[0] -= 0.001, twin.frame_errors[1] += 0.0005;
	EXPECT_TRUE(chromaOnTie({twin, chroma}, twin));
}

TEST(ParameterLearning, EachLaserRaysErrorAndWhetherTheOmnicamReadNearer)
{
	const auto pair = [](double laser, double omni, PairStatus status) {
		return RangePair{0, 0, 0.0, laser, omni, status};
	};
	const double max_range = 3.8;
	// Both see a boundary: the omnicam 0.5 m short of the laser, then 0.3 m past it.
	RayError e = learningError(pair(2.0, 1.5, PairStatus::Compared), true, max_range);
	EXPECT_NEAR(e.error, 0.5, 1e-12);
	EXPECT_TRUE(e.nearer);
	e = learningError(pair(1.5, 1.8, PairStatus::Compared), true, max_range);
	EXPECT_NEAR(e.error, 0.3, 1e-12);
	EXPECT_FALSE(e.nearer);
	// More than 1.25 m apart: capped, on either side.
	e = learningError(pair(3.5, 1.0, PairStatus::TooDifferent), true, max_range);
	EXPECT_EQ(e.error, 1.25);
	EXPECT_TRUE(e.nearer);
	EXPECT_FALSE(learningError(pair(1.0, 3.8, PairStatus::TooDifferent), false, max_range).nearer);
	// The laser sees nothing within range: a hit at 3.0 m falls 0.8 m short; no hit costs nothing.
	e = learningError(pair(10.0, 3.0, PairStatus::LaserBeyondMaxRange), true, max_range);
	EXPECT_NEAR(e.error, 0.8, 1e-12);
	EXPECT_TRUE(e.nearer);
	EXPECT_EQ(learningError(pair(10.0, 3.8, PairStatus::LaserBeyondMaxRange), false, max_range).error, 0.0);
	// A rejected ray costs the cap and is not a reading nearer than the laser.
	e = learningError(pair(2.0, 0.4, PairStatus::OmniRejected), false, max_range);
	EXPECT_EQ(e.error, 1.25);
	EXPECT_FALSE(e.nearer);
}

TEST(ParameterLearning, TheDoubtIsLearnedForTheWinnerAndNeverEntersTheCandidatesScores)
{
	RangefinderParams rp;
	const RawlogTrainingOptions o = samplePairs(12);
	const LearningOptions lo = oneCandidate();
	const LearningResult r = learnParameters(rp, o, lo);
	// A start ini that doubts hard (an earlier learning's, or a user's) scores the grid as one that does not.
	rp.sure_floor_share = 0.5, rp.scanner.sure_run = 5;
	const LearningResult hard = learnParameters(rp, o, lo);
	ASSERT_EQ(r.tried.size(), 1u);
	EXPECT_EQ(hard.tried[0].score, r.tried[0].score);
	// The doubt chosen is the same from either start, and the parameters and the ini carry it.
	EXPECT_EQ(hard.doubt.sure_floor_share, r.doubt.sure_floor_share);
	EXPECT_EQ(hard.doubt.sure_run, r.doubt.sure_run);
	EXPECT_EQ(r.params.sure_floor_share, r.doubt.sure_floor_share);
	EXPECT_EQ(r.params.sure_obstacle_ratio, r.doubt.sure_obstacle_ratio);
	EXPECT_EQ(r.params.scanner.sure_run, r.doubt.sure_run);
	EXPECT_GE(r.doubt.unsure, 0.0);
	EXPECT_LE(r.doubt.unsure, 1.0);
	const std::string ini = learnedIni(r);
	EXPECT_NE(ini.find("; Doubt (docs/method.md): sure_floor_share "), std::string::npos) << ini;
	EXPECT_NE(ini.find("colour separates floor from obstacles"), std::string::npos) << ini;
	EXPECT_NE(ini.find("\nsure_run = " + std::to_string(r.doubt.sure_run) + "\n"), std::string::npos) << ini;
}
