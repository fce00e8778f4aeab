// The doubt (Rangefinder step 6): a ray whose free stretch crosses colours
// the floor rarely shows is unsure, free only up to where they start; its
// MRPT scan says so in the intensity channel; training measures how well
// colour parts the floor from its obstacles.
#include "SyntheticOmni.h"

#include <omnirange/core/Rangefinder.h>
#include <omnirange/train/ColourSeparation.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace omnirange;

namespace
{
// A floor colour training saw on 2 of every 102 floor pixels: free, but rare.
const cv::Vec3b kRare{110, 190, 120};

ColourModel floorWithARareColour()
{
	ColourHistogram h;
	for (int i = 0; i < 100; ++i) h.addPixel(&test::kFloor[0]);
	for (int i = 0; i < 2; ++i) h.addPixel(&kRare[0]);
	return ColourModel(h);
}

RangefinderParams doubting(double share, int run)
{
	RangefinderParams p;
	p.outliers.outlier_filter = OutlierFilterKind::None;
	p.walls.wall_fit = false;
	p.sensor_pose = {};
	p.threshold = 0.01;  // the rare colour (P = 0.02) is free floor
	p.sure_floor_share = share;
	p.scanner.sure_run = run;
	return p;
}

/** Floor everywhere; straight ahead a patch of the rare colour from 1.0 m to
 * `patch_end` m, then a wall from 3.0 m, 0.6 m wide. */
cv::Mat rarePatchAhead(const OmniCameraModel& cam, double patch_end)
{
	cv::Mat img = test::drawOmni(cam, [](const FloorPoint& f) { return f.x > 3.0 && std::abs(f.y) < 0.3; });
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
		{
			const auto f = cam.floorFromPixel({double(u), double(v)});
			if (f && f->x > 1.0 && f->x < patch_end && std::abs(f->y) < 0.3) img.at<cv::Vec3b>(v, u) = kRare;
		}
	return img;
}
}  // namespace

TEST(Doubt, ARareFloorColourIsFreeButDoubtfulAndEveryColourIsSureAtShareOne)
{
	const ColourModel m = floorWithARareColour();
	const FreeSpaceClassifier doubting(m, 0.01, 0, 0, 0, 0.9);
	EXPECT_EQ(doubting.classOf(&test::kFloor[0]), kFree);
	EXPECT_EQ(doubting.classOf(&kRare[0]), kDoubtfulFree);
	EXPECT_EQ(doubting.classOf(&test::kWall[0]), kNotFree);
	EXPECT_TRUE(doubting.isFree(&kRare[0]));
	const FreeSpaceClassifier sure(m, 0.01, 0, 0, 0, 1.0);
	EXPECT_EQ(sure.classOf(&kRare[0]), kFree);
}

TEST(Doubt, AStretchOfARareColourMakesTheRayUnsureFromWhereItStarts)
{
	const Rangefinder rf(doubting(0.9, 5), floorWithARareColour());
	const RangeScan scan = rf.process(rarePatchAhead(rf.camera(), 1.6));
	const Ray& ahead = scan.rays[180];
	ASSERT_EQ(ahead.status, RayStatus::Unsure);
	EXPECT_NEAR(ahead.range, 1.0, 0.05);
	EXPECT_NEAR(ahead.confidence, 1.0 / 3.0, 0.05);  // of the 3.0 m it claimed free, a third is sure
	EXPECT_EQ(scan.rays[90].status, RayStatus::NoHit);  // plain floor to the left: free, confident
	EXPECT_FLOAT_EQ(scan.rays[90].confidence, 1.0f);

	// Without doubt the same ray reads the wall behind the patch.
	const Rangefinder paper(doubting(1.0, 5), floorWithARareColour());
	const Ray& through = paper.process(rarePatchAhead(paper.camera(), 1.6)).rays[180];
	EXPECT_EQ(through.status, RayStatus::Hit);
	EXPECT_NEAR(through.range, 3.0, 0.05);
}

TEST(Doubt, AFewRarePixelsShorterThanTheRunLeaveTheRayConfident)
{
	const Rangefinder rf(doubting(0.9, 5), floorWithARareColour());
	const RangeScan scan = rf.process(rarePatchAhead(rf.camera(), 1.02));
	EXPECT_EQ(scan.rays[180].status, RayStatus::Hit);
	EXPECT_NEAR(scan.rays[180].range, 3.0, 0.05);
}

TEST(Doubt, TheScanWritesAnUnsureRayAsAnObstacleOrInvalidWithItsConfidence)
{
	RangefinderParams p = doubting(0.9, 5);
	const Rangefinder as_obstacle(p, floorWithARareColour());
	const RangeScan scan = as_obstacle.process(rarePatchAhead(as_obstacle.camera(), 1.6));
	const auto nav = as_obstacle.toObservation(scan, mrpt::Clock::now());
	ASSERT_TRUE(nav->hasIntensity());
	EXPECT_TRUE(nav->getScanRangeValidity(180));  // a navigator stops at the extent
	EXPECT_NEAR(nav->getScanRange(180), 1.0, 0.05);
	EXPECT_LT(nav->getScanIntensity(180), kFullConfidence);
	EXPECT_TRUE(rayIsUnsure(*nav, 180));
	EXPECT_EQ(nav->getScanIntensity(90), kFullConfidence);
	EXPECT_FALSE(nav->getScanRangeValidity(90));  // free to max range: no return, as a laser's
	EXPECT_FALSE(rayIsUnsure(*nav, 90));

	p.unsure_rays = UnsureRays::Invalid;
	const Rangefinder as_invalid(p, floorWithARareColour());
	const auto map = as_invalid.toObservation(scan, mrpt::Clock::now());
	EXPECT_FALSE(map->getScanRangeValidity(180));
	EXPECT_NEAR(map->getScanRange(180), 1.0, 0.05);
	EXPECT_TRUE(rayIsUnsure(*map, 180));
}

TEST(Doubt, SeparationIsOneForDisjointColoursAndOneHalfForTheSame)
{
	ColourHistogram floor, feet;
	for (int i = 0; i < 50; ++i) floor.addPixel(&test::kFloor[0]), feet.addPixel(&test::kWall[0]);
	const ColourModel apart(floor, feet);
	const ColourSeparation a = colourSeparation(apart, FreeSpaceClassifier(apart, 0.05), 0);
	ASSERT_TRUE(a.known);
	EXPECT_DOUBLE_EQ(a.auc, 1.0);
	EXPECT_DOUBLE_EQ(a.feet_read_free, 0.0);
	EXPECT_NE(separationLine(a).find("well"), std::string::npos);

	const ColourModel same(floor, floor);
	const ColourSeparation s = colourSeparation(same, FreeSpaceClassifier(same, 0.05), 0);
	EXPECT_DOUBLE_EQ(s.auc, 0.5);
	EXPECT_DOUBLE_EQ(s.feet_read_free, 1.0);
	EXPECT_NE(separationLine(s).find("poorly here (AUC 0.50; 100 % of the obstacles' feet read as floor): expect many "
									 "unsure rays"),
			  std::string::npos)
		<< separationLine(s);

	EXPECT_FALSE(colourSeparation(ColourModel(floor), FreeSpaceClassifier(ColourModel(floor), 0.05), 0).known);
}

TEST(Doubt, AHitAlreadyWithinTheConfidentExtentStaysAHit)
{
	// The edge bias or the wall fit can move a hit in past where the doubt starts: it then claims no doubtful floor.
	Ray moved_in;
	moved_in.status = RayStatus::Hit, moved_in.range = 1.9f, moved_in.sure_end = 40, moved_in.sure_range = 2.0f;
	markUnsure(moved_in, 0.4);
	EXPECT_EQ(moved_in.status, RayStatus::Hit);
	EXPECT_FLOAT_EQ(moved_in.range, 1.9f);
	EXPECT_FLOAT_EQ(moved_in.confidence, 1.0f);

	Ray past;
	past.status = RayStatus::Hit, past.range = 3.0f, past.sure_end = 40, past.sure_range = 1.5f;
	markUnsure(past, 0.4);
	EXPECT_EQ(past.status, RayStatus::Unsure);
	EXPECT_FLOAT_EQ(past.range, 1.5f);
	EXPECT_FLOAT_EQ(past.confidence, 0.5f);

	Ray free_near_base;  // its sure floor ends inside min range: unsure at min range
	free_near_base.status = RayStatus::NoHit, free_near_base.range = 3.8f, free_near_base.sure_end = 0;
	free_near_base.sure_range = 0.2f;
	markUnsure(free_near_base, 0.4);
	EXPECT_EQ(free_near_base.status, RayStatus::Unsure);
	EXPECT_FLOAT_EQ(free_near_base.range, 0.4f);
}
