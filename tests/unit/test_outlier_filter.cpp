// The spike filter: lone disagreeing rays go, real depth steps stay.
#include <omnirange/core/OutlierFilter.h>

#include <gtest/gtest.h>

using namespace omnirange;

namespace
{
std::vector<Ray> wall(int n, float range)
{
	std::vector<Ray> rays(n);
	for (auto& r : rays) r.range = range, r.status = RayStatus::Hit;
	return rays;
}
OutlierFilterParams spike(int width)
{
	OutlierFilterParams p;
	p.outlier_max_width = width;
	return p;
}
}  // namespace

TEST(OutlierFilter, RemovesALoneShortRay)
{
	auto rays = wall(36, 2.0f);
	rays[10].range = 0.8f;
	EXPECT_EQ(rejectOutliers(rays, spike(1)), 1);
	EXPECT_EQ(rays[10].status, RayStatus::Outlier);
	EXPECT_FLOAT_EQ(rays[10].range, 0.8f);  // kept, only flagged
	EXPECT_EQ(rays[9].status, RayStatus::Hit);
}

TEST(OutlierFilter, KeepsDepthStepsAndSmallNoise)
{
	auto rays = wall(36, 2.0f);
	for (int i = 18; i < 36; ++i) rays[i].range = 3.0f;  // a corner/doorway
	rays[5].range = 2.1f;  // within tolerance
	EXPECT_EQ(rejectOutliers(rays, spike(2)), 0);
}

TEST(OutlierFilter, WidthDecidesHowWideASpikeMayBe)
{
	auto rays = wall(36, 2.0f);
	rays[20].range = rays[21].range = 1.0f;
	auto narrow = rays;
	EXPECT_EQ(rejectOutliers(narrow, spike(1)), 0);
	EXPECT_EQ(rejectOutliers(rays, spike(2)), 2);
	EXPECT_EQ(rays[20].status, RayStatus::Outlier);
	EXPECT_EQ(rays[21].status, RayStatus::Outlier);
}

TEST(OutlierFilter, WrapsAroundTheScan)
{
	auto rays = wall(36, 2.0f);
	rays[0].range = 0.7f;
	rays[35].range = 0.7f;
	EXPECT_EQ(rejectOutliers(rays, spike(2)), 2);
	EXPECT_EQ(rays[0].status, RayStatus::Outlier);
	EXPECT_EQ(rays[35].status, RayStatus::Outlier);
}

TEST(OutlierFilter, OnlyHitsAreRejectedAndNoneDisablesIt)
{
	auto rays = wall(36, 3.8f);
	rays[7].range = 0.3f;
	rays[7].status = RayStatus::TooClose;
	EXPECT_EQ(rejectOutliers(rays, spike(1)), 0);
	rays[7].status = RayStatus::Hit;
	OutlierFilterParams off;
	off.outlier_filter = OutlierFilterKind::None;
	EXPECT_EQ(rejectOutliers(rays, off), 0);
	EXPECT_EQ(rejectOutliers(rays, spike(1)), 1);
}

TEST(OutlierFilter, ImpossibleParameters)
{
	OutlierFilterParams p;
	p.outlier_max_width = 0;
	EXPECT_THROW(p.validate(), std::invalid_argument);
	p = {};
	p.outlier_abs_tol = -1;
	EXPECT_THROW(p.validate(), std::invalid_argument);
	EXPECT_THROW(outlierFilterKindFromString("median"), std::invalid_argument);
}
