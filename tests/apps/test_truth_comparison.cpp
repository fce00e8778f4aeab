// Scoring against the truth: each omnicam ray against the true boundary at
// its bearing, counted into the right band and outcome.
#include <omnirange_eval/Experiment.h>
#include <omnirange_eval/ExperimentConfig.h>
#include <omnirange_eval/TruthComparison.h>
#include <omnirange_sim/RobotParams.h>

#include <omnirange/core/PolarScanner.h>
#include <omnirange/core/Rangefinder.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace omnirange;
using mrpt::obs::CObservation2DRangeScan;

namespace
{
CObservation2DRangeScan scan(const std::string& label, const std::vector<float>& ranges,
							 const std::vector<bool>& valid, float max_range)
{
	CObservation2DRangeScan s;
	s.sensorLabel = label;
	s.aperture = static_cast<float>(scanAperture(static_cast<int>(ranges.size())));
	s.maxRange = max_range;
	s.resizeScan(ranges.size());
	for (std::size_t i = 0; i < ranges.size(); ++i) s.setScanRange(i, ranges[i]), s.setScanRangeValidity(i, valid[i]);
	return s;
}
}  // namespace

TEST(TruthComparison, EachRayLandsInItsBandAndOutcome)
{
	// Eight rays; the truth: 1.5, 1.5, 2.5, 2.5, 3.5, open, open, 0.5 m.
	const auto truth = scan("TRUTH", {1.5f, 1.5f, 2.5f, 2.5f, 3.5f, 10, 10, 0.5f},
							{true, true, true, true, true, false, false, true}, 10);
	// The omnicam: 1 cm off, 4 cm off, no hit (at max range), 20 cm short,
	// rejected (too close, at min range), a false obstacle, open, exact.
	const auto omni = scan("OMNISCAN", {1.51f, 1.46f, 3.8f, 2.3f, 0.4f, 2.0f, 3.8f, 0.5f},
						   {true, true, false, true, false, true, false, true}, 3.8f);
	eval::TruthStats t;
	t.add(truth, omni);
	const auto all = t.all();
	EXPECT_EQ(all.rays, 6u);
	EXPECT_EQ(all.within_2cm, 2u);  // 1.51 and the exact 0.5
	EXPECT_EQ(all.within_5cm, 3u);  // and 1.46
	EXPECT_EQ(all.missed_no_hit, 1u);
	EXPECT_EQ(all.missed_rejected, 1u);
	EXPECT_NEAR(all.meanAbs(), (0.01 + 0.04 + 0.2 + 0) / 4, 1e-6);
	EXPECT_NEAR(all.meanSigned(), (0.01 - 0.04 - 0.2 + 0) / 4, 1e-6);
	EXPECT_EQ(t.bands[0].rays, 1u);  // 0.5 m
	EXPECT_EQ(t.bands[1].rays, 2u);  // 1.5 m
	EXPECT_EQ(t.bands[2].rays, 2u);  // 2.5 m
	EXPECT_EQ(t.bands[3].rays, 1u);  // 3.5 m
	EXPECT_EQ(t.open_rays, 2u);
	EXPECT_EQ(t.false_obstacles, 1u);
	EXPECT_NE(t.table().find("| all | 6 | 33.3 % | 50.0 % |"), std::string::npos) << t.table();
}

TEST(TruthComparison, UnsureRaysAreNeitherHitsNorFalseFreeUnlessTheirExtentIsPastTheTruth)
{
	// Six rays, the truth 2.0 m on each but the last (open). The omnicam: a
	// hit 20 cm past the truth (false free), no hit (false free), unsure at
	// 1.2 m (short of the truth: safe), unsure at 2.5 m (past it: false free),
	// an exact hit, and an unsure open ray.
	const auto truth = scan("TRUTH", {2, 2, 2, 2, 2, 10}, {true, true, true, true, true, false}, 10);
	auto omni = scan("OMNISCAN", {2.2f, 3.8f, 1.2f, 2.5f, 2.0f, 1.0f}, {true, false, true, true, true, true}, 3.8f);
	omni.setScanHasIntensity(true);
	for (std::size_t i = 0; i < 6; ++i) omni.setScanIntensity(i, kFullConfidence);
	omni.setScanIntensity(2, 60), omni.setScanIntensity(3, 65), omni.setScanIntensity(5, 26);
	eval::TruthStats t;
	t.add(truth, omni);
	const auto all = t.all();
	EXPECT_EQ(all.rays, 5u);
	EXPECT_EQ(all.unsure, 2u);
	EXPECT_EQ(all.false_free, 3u);  // 2.2 m, no hit, unsure to 2.5 m
	EXPECT_EQ(all.within_5cm, 1u);  // the exact hit; an unsure ray is never within
	EXPECT_EQ(all.missed_no_hit, 1u);
	EXPECT_EQ(t.open_unsure, 1u);
	EXPECT_EQ(t.false_obstacles, 0u);  // an unsure ray is no obstacle
	EXPECT_EQ(t.allUnsure(), 3u);
	EXPECT_EQ(t.allRays(), 6u);
}

TEST(TruthComparison, ScansFromDifferentPosesAreRefused)
{
	auto truth = scan("TRUTH", {1, 1}, {true, true}, 10);
	auto omni = scan("OMNISCAN", {1, 1}, {true, true}, 3.8f);
	omni.sensorPose = mrpt::poses::CPose3D(0.2, 0, 0, 0, 0, 0);
	eval::TruthStats t;
	EXPECT_THROW(t.add(truth, omni), std::invalid_argument);
}

TEST(TruthComparison, ACameraThatMadeTheImagesUnlikeTheOneThatReadsThemIsNamed)
{
	// The stock experiments read their images with their robot's camera; another robot's mirror
	// (the hyperbolic one under the factory's paraboloid ini) is named key by key.
	const std::string ini = OMNIRANGE_SOURCE_DIR "/ini/";
	const auto factory = eval::ExperimentConfig::load(ini + "factory.ini");
	EXPECT_EQ(eval::cameraMismatch(sim::RobotParams::loadFile(factory.robot).omnicam.camera, factory.rangefinder.camera),
			  std::vector<std::string>{});
	const auto other = eval::cameraMismatch(sim::RobotParams::loadFile(ini + "robot-hyperbolic.ini").omnicam.camera,
											factory.rangefinder.camera);
	EXPECT_NE(std::find(other.begin(), other.end(), "mirror_model"), other.end());
}
