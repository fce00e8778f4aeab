// Thin walls: noisy hits on straight walls come closer to the walls; a
// corner stays a corner and an object before a wall stays where it is.
#include <omnirange/core/WallFit.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace omnirange;

namespace
{
// A 4 m x 3 m room around the sensor, with a box 1 m ahead on the left.
double trueRange(double b)
{
	const double c = std::cos(b), s = std::sin(b);
	double r = 1e9;
	if (c > 1e-9) r = std::min(r, 2.0 / c);
	if (c < -1e-9) r = std::min(r, -2.0 / c);
	if (s > 1e-9) r = std::min(r, 1.5 / s);
	if (s < -1e-9) r = std::min(r, -1.5 / s);
	return r;
}

struct Scan
{
	std::vector<Ray> rays;
	std::vector<double> truth;
};

Scan noisyScan(const OmniCameraModel& cam, unsigned seed)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> unit(0.0, 1.0);
	Scan s;
	for (int i = 0; i < 360; ++i)
	{
		Ray r;
		r.bearing = scanlineBearing(i, 360);
		double t = trueRange(r.bearing);
		if (i >= 200 && i < 215) t = 1.0;  // the box: a step of about a metre
		const double sigma = rangeSigma(cam, cam.rhoFromDistance(t), 0.5);
		r.range = static_cast<float>(t + sigma * unit(rng));
		r.hit_rho = static_cast<float>(cam.rhoFromDistance(r.range));
		r.status = RayStatus::Hit;
		s.rays.push_back(r);
		s.truth.push_back(t);
	}
	s.rays[300].status = RayStatus::NoHit;  // a doorway: not a hit, not moved
	s.rays[300].range = 3.8f;
	return s;
}

double rmsError(const Scan& s, int from, int to)
{
	double sum = 0;
	int n = 0;
	for (int i = from; i < to; ++i)
		if (s.rays[i].status == RayStatus::Hit) sum += std::pow(s.rays[i].range - s.truth[i], 2), ++n;
	return std::sqrt(sum / n);
}
}  // namespace

TEST(WallFit, RangeUncertaintyGrowsWithDistanceAsThePixelsDo)
{
	const OmniCameraModel cam{CameraParams{}};
	// A pixel of the stock paraboloid is about 1.8 cm of floor at 1 m and
	// 11 cm at 3.8 m (d = h tan(2 atan(rho / R))).
	EXPECT_NEAR(rangeSigma(cam, cam.rhoFromDistance(1.0), 1.0), 0.0176, 0.001);
	EXPECT_NEAR(rangeSigma(cam, cam.rhoFromDistance(3.8), 1.0), 0.106, 0.005);
	EXPECT_NEAR(rangeSigma(cam, 100, 0.5), 0.5 * rangeSigma(cam, 100, 1.0), 1e-12);
}

TEST(WallFit, NoisyWallsComeCloserAndStepsStay)
{
	const OmniCameraModel cam{CameraParams{}};
	WallFitParams p;
	p.wall_fit = true;
	Scan s = noisyScan(cam, 7);
	const double before = rmsError(s, 0, 360);
	const double box_before = rmsError(s, 200, 215);
	const int moved = fitWalls(s.rays, cam, p, 0.4, 3.8);
	EXPECT_GT(moved, 300);
	EXPECT_LT(rmsError(s, 0, 360), before / 2);
	// The box stays a box: its rays are near 1 m, not pulled to the wall.
	EXPECT_LT(rmsError(s, 200, 215), std::max(box_before, 0.02));
	EXPECT_EQ(s.rays[300].status, RayStatus::NoHit);
	EXPECT_FLOAT_EQ(s.rays[300].range, 3.8f);
	// The corners stay corners: no ray ends up much worse than it was.
	Scan again = noisyScan(cam, 7);
	fitWalls(again.rays, cam, p, 0.4, 3.8);
	const Scan raw = noisyScan(cam, 7);
	for (int i = 0; i < 360; ++i)
	{
		const double sigma = rangeSigma(cam, cam.rhoFromDistance(raw.truth[i]), 0.5);
		EXPECT_LT(std::abs(again.rays[i].range - again.truth[i]),
				  std::abs(raw.rays[i].range - raw.truth[i]) + 3 * sigma + 1e-6)
			<< i;
	}
}

TEST(WallFit, AScanOfHitsAllRoundIsFittedAcrossItsWrapAndKeptInRange)
{
	// No ray without a hit (the doorway closed): the wall straight behind,
	// across the scan's first and last rays, is fitted too; a fitted range
	// never leaves [min_range, max_range].
	const OmniCameraModel cam{CameraParams{}};
	WallFitParams p;
	p.wall_fit = true;
	Scan s = noisyScan(cam, 11);
	s.rays[300].status = RayStatus::Hit;
	s.rays[300].range = static_cast<float>(s.truth[300]);
	s.rays[300].hit_rho = static_cast<float>(cam.rhoFromDistance(s.truth[300]));
	const Scan raw = s;
	fitWalls(s.rays, cam, p, 0.4, 3.8);
	int moved_behind = 0;
	for (int i : {355, 356, 357, 358, 359, 0, 1, 2, 3, 4}) moved_behind += s.rays[i].range != raw.rays[i].range;
	EXPECT_GE(moved_behind, 8);
	Scan near = noisyScan(cam, 11);
	fitWalls(near.rays, cam, p, 0.4, 2.0);  // a max range inside the room
	const Scan near_raw = noisyScan(cam, 11);
	for (int i = 0; i < 360; ++i)
	{
		if (near.rays[i].range > 2.0f)
		{
			EXPECT_EQ(near.rays[i].range, near_raw.rays[i].range) << i;
		}
	}
}

TEST(WallFit, ACurvedWallIsMovedByNoMoreThanTheTolerance)
{
	// A round room 1.33 m across, no noise: pieces of the circle pass as
	// lines while their sagitta is within the tolerance, so a range may be
	// moved, but by at most wall_fit_tolerance of its sigma.
	const OmniCameraModel cam{CameraParams{}};
	WallFitParams p;
	p.wall_fit = true;
	std::vector<Ray> rays(360);
	for (int i = 0; i < 360; ++i)
	{
		rays[i].bearing = scanlineBearing(i, 360);
		rays[i].range = 1.33f;
		rays[i].hit_rho = static_cast<float>(cam.rhoFromDistance(1.33));
		rays[i].status = RayStatus::Hit;
	}
	fitWalls(rays, cam, p, 0.4, 3.8);
	const double sigma = rangeSigma(cam, cam.rhoFromDistance(1.33), p.boundary_sigma);
	for (const Ray& r : rays) EXPECT_LE(std::abs(r.range - 1.33), p.wall_fit_tolerance * sigma + 1e-6);
}

TEST(WallFit, OffMovesNothingAndBadParametersAreRefused)
{
	const OmniCameraModel cam{CameraParams{}};
	Scan s = noisyScan(cam, 3);
	const Scan raw = s;
	WallFitParams off;
	off.wall_fit = false;
	EXPECT_EQ(fitWalls(s.rays, cam, off, 0.4, 3.8), 0);
	for (int i = 0; i < 360; ++i) EXPECT_EQ(s.rays[i].range, raw.rays[i].range);
	WallFitParams p;
	p.wall_fit = true;
	p.wall_fit_min_rays = 2;
	EXPECT_THROW(fitWalls(s.rays, cam, p, 0.4, 3.8), std::invalid_argument);
	p.wall_fit_min_rays = 6;
	p.boundary_sigma = 0;
	EXPECT_THROW(fitWalls(s.rays, cam, p, 0.4, 3.8), std::invalid_argument);
}
