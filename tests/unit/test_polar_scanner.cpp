// Polar scanner on drawn images: ranges within the one-pixel quantisation
// bound, the max/min range cases, scanline geometry and bad input.
#include "SyntheticOmni.h"

#include <omnirange/core/FreeSpaceClassifier.h>
#include <omnirange/core/PolarScanner.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace omnirange;

namespace
{
constexpr double kPi = 3.14159265358979323846;

struct Fixture
{
	OmniCameraModel cam{CameraParams{}};
	FreeSpaceClassifier classifier{test::floorHistogram(), 0.05};
	PolarScanner scanner{cam, PolarScannerParams{}};
};

/** The range step one pixel further out makes at image radius rho: the
 * quantisation bound (d is convex in rho, so the step inwards is smaller). */
double onePixelBound(const OmniCameraModel& cam, double rho)
{
	return cam.distanceFromRho(rho + 1) - cam.distanceFromRho(rho);
}
}  // namespace

class FloorDisc : public testing::TestWithParam<double>
{
};

TEST_P(FloorDisc, EveryRayWithinOnePixelOfTheTrueDistance)
{
	Fixture f;
	const double rho = GetParam();
	const auto rays = f.scanner.scan(test::drawFloorDisc(f.cam, rho), f.classifier);
	ASSERT_EQ(rays.size(), 360u);
	const double truth = f.cam.distanceFromRho(rho);
	const double bound = onePixelBound(f.cam, rho);
	double worst = 0;
	for (const Ray& r : rays)
	{
		ASSERT_EQ(r.status, RayStatus::Hit) << "bearing " << r.bearing;
		worst = std::max(worst, std::abs(r.range - truth));
	}
	EXPECT_LE(worst, bound) << "true " << truth << " m at " << rho << " px";
}

// From just outside the base (40 px) to just inside max range (150.6 px).
INSTANTIATE_TEST_SUITE_P(
	Radii, FloorDisc, testing::Values(43.0, 51.5, 64.2, 90.0, 111.7, 130.3, 149.0));

TEST(PolarScanner, BoundaryOffsetMovesEveryHitOutwards)
{
	Fixture f;
	PolarScannerParams p;
	p.boundary_offset = 0.5;
	const PolarScanner shifted(f.cam, p);
	const cv::Mat img = test::drawFloorDisc(f.cam, 100.0);
	const auto a = f.scanner.scan(img, f.classifier), b = shifted.scan(img, f.classifier);
	for (std::size_t i = 0; i < a.size(); ++i)
	{
		ASSERT_EQ(b[i].status, RayStatus::Hit);
		EXPECT_NEAR(b[i].hit_rho, a[i].hit_rho + 0.5, 1e-4);
		EXPECT_NEAR(b[i].range, f.cam.distanceFromRho(b[i].hit_rho), 1e-4);
	}
	p.boundary_offset = 2;
	EXPECT_THROW(PolarScanner(f.cam, p), std::invalid_argument);
}

TEST(PolarScanner, NoHitBeforeMaxRangeReportsMaxRange)
{
	Fixture f;
	const auto rays = f.scanner.scan(test::drawFloorDisc(f.cam, 165.0), f.classifier);
	for (const Ray& r : rays)
	{
		ASSERT_EQ(r.status, RayStatus::NoHit);
		ASSERT_FLOAT_EQ(r.range, 3.8f);
	}
}

TEST(PolarScanner, WallInsideTheBaseReportsMinRange)
{
	Fixture f;
	const auto rays = f.scanner.scan(test::drawFloorDisc(f.cam, 30.0), f.classifier);
	for (const Ray& r : rays)
	{
		ASSERT_EQ(r.status, RayStatus::TooClose);
		ASSERT_FLOAT_EQ(r.range, 0.40f);
	}
}

TEST(PolarScanner, HitCloserThanMinRangeReportsMinRange)
{
	Fixture f;
	PolarScannerParams p;
	p.min_range = 1.0;
	const PolarScanner scanner(f.cam, p);
	const double rho = f.cam.rhoFromDistance(0.8);
	for (const Ray& r : scanner.scan(test::drawFloorDisc(f.cam, rho), f.classifier))
		ASSERT_EQ(r.status, RayStatus::TooClose);
}

TEST(PolarScanner, MisclassifiedSpecksDoNotStopAScanline)
{
	Fixture f;
	cv::Mat img = test::drawFloorDisc(f.cam, 120.0);
	// Wall-coloured specks of one pixel on the floor along the forward ray
	// (image left): the N filter must ignore them.
	for (int u = 512 - 100; u > 512 - 110; u -= 3)
		for (int v = 382; v <= 386; ++v) img.at<cv::Vec3b>(v, u) = test::kWall;
	const auto rays = f.scanner.scan(img, f.classifier);
	const double truth = f.cam.distanceFromRho(120.0);
	for (int i : {179, 180})  // the two rays either side of straight ahead
		EXPECT_NEAR(rays[i].range, truth, onePixelBound(f.cam, 120.0));
}

TEST(PolarScanner, ScanlineBearingsFollowMrptsRayAngles)
{
	// S rays over 2 pi (S-1)/S: -pi (S-1)/S first, +pi (S-1)/S last, 2 pi/S apart.
	EXPECT_NEAR(scanlineBearing(0, 360), -kPi * 359 / 360, 1e-12);
	EXPECT_NEAR(scanlineBearing(359, 360), kPi * 359 / 360, 1e-12);
	EXPECT_NEAR(scanlineBearing(180, 360) - scanlineBearing(179, 360), kPi / 180, 1e-12);
	EXPECT_NEAR(scanlineBearing(179, 360), -kPi / 360, 1e-12);  // just right of ahead
	EXPECT_NEAR(scanAperture(4), 1.5 * kPi, 1e-12);
}

TEST(PolarScanner, ScanlinesAreConnectedAndOutward)
{
	Fixture f;
	for (int s : {0, 45, 179, 359})
	{
		const auto px = f.scanner.scanlinePixels(s);
		ASSERT_GT(px.size(), 120u);
		for (std::size_t k = 1; k < px.size(); ++k)
		{
			const int du = px[k] % 1024 - px[k - 1] % 1024;
			const int dv = px[k] / 1024 - px[k - 1] / 1024;
			ASSERT_LE(std::max(std::abs(du), std::abs(dv)), 1) << "gap at " << k;
			ASSERT_FALSE(du == 0 && dv == 0) << "repeated pixel at " << k;
		}
	}
	EXPECT_GT(f.scanner.scanRadius(), f.scanner.maxRangeRho() + 20);  // N + K window
}

TEST(PolarScanner, ImpossibleParametersAreRejected)
{
	const OmniCameraModel cam{CameraParams{}};
	const auto rejects = [&](auto edit) {
		PolarScannerParams p;
		edit(p);
		EXPECT_THROW(PolarScanner(cam, p), std::invalid_argument);
	};
	rejects([](PolarScannerParams& p) { p.filter.N = 0; });
	rejects([](PolarScannerParams& p) { p.filter.K = -1; });
	rejects([](PolarScannerParams& p) { p.scanlines = 1; });
	rejects([](PolarScannerParams& p) { p.max_range = 0.1; });  // below min_range
	rejects([](PolarScannerParams& p) { p.base_radius = 160; });  // beyond max range
	rejects([](PolarScannerParams& p) { p.max_range = std::nan(""); });
	rejects([](PolarScannerParams& p) { p.step_threshold = -0.1; });
	rejects([](PolarScannerParams& p) { p.step_threshold = std::nan(""); });
	rejects([](PolarScannerParams& p) { p.step_window = 0; });
}

TEST(PolarScanner, ScanCircleLargerThanTheImageIsRejected)
{
	CameraParams small;
	small.image_width = 300;
	small.image_height = 300;
	small.cx = small.cy = 150;
	const OmniCameraModel cam{small};
	try
	{
		PolarScanner(cam, PolarScannerParams{});
		FAIL() << "accepted a scan circle larger than the image";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("300x300"), std::string::npos) << e.what();
	}
}

TEST(PolarScanner, ImageOfTheWrongSizeOrTypeIsRejected)
{
	Fixture f;
	EXPECT_THROW(f.scanner.scan(cv::Mat(480, 640, CV_8UC3), f.classifier), std::invalid_argument);
	EXPECT_THROW(f.scanner.scan(cv::Mat(768, 1024, CV_8UC1), f.classifier), std::invalid_argument);
}

namespace
{
/** Another free-space model through the scanner's seam: free where green dominates. */
class GreenIsFree final : public PixelClassifier
{
   public:
	void classify(const std::uint8_t* bgr, const std::int32_t* pixels, int count, std::uint8_t* out) const override
	{
		for (int k = 0; k < count; ++k)
		{
			const std::uint8_t* p = bgr + 3 * static_cast<std::size_t>(pixels[k]);
			out[k] = p[1] > p[2] ? 1 : 0;
		}
	}
};
}  // namespace

TEST(PolarScanner, AnotherClassifierPlugsInThroughTheSeam)
{
	Fixture f;
	const double rho = 90.0;
	const auto image = test::drawFloorDisc(f.cam, rho);
	const auto with_histogram = f.scanner.scan(image, f.classifier);
	const auto with_green = f.scanner.scan(image, GreenIsFree{});
	ASSERT_EQ(with_green.size(), with_histogram.size());
	for (std::size_t i = 0; i < with_green.size(); ++i)
	{
		EXPECT_EQ(with_green[i].status, RayStatus::Hit);
		EXPECT_FLOAT_EQ(with_green[i].range, with_histogram[i].range);
		EXPECT_EQ(with_green[i].search.status, HitSearch::Status::Hit);
		EXPECT_EQ(with_green[i].search.rejected_by_K, 0);
	}
	// All floor: every ray is a no-hit, and the search says there was no candidate.
	const cv::Mat floor(image.size(), CV_8UC3, cv::Scalar(test::kFloor));
	for (const Ray& r : f.scanner.scan(floor, GreenIsFree{}))
	{
		EXPECT_EQ(r.status, RayStatus::NoHit);
		EXPECT_EQ(r.search.status, HitSearch::Status::NoCandidate);
	}
}

namespace
{
/** The floor disc out to `rho`, its first pixels darkened out to `shadow_rho`
 * (a colour the floor histogram does not hold): the robot's own shadow. */
cv::Mat drawShadowAtTheBase(const OmniCameraModel& cam, double rho, double shadow_rho)
{
	cv::Mat img = test::drawFloorDisc(cam, rho);
	const auto& p = cam.params();
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
			if (std::hypot(u - p.cx, v - p.cy) <= shadow_rho) img.at<cv::Vec3b>(v, u) = {25, 60, 30};
	return img;
}
}  // namespace

TEST(PolarScanner, TheRobotsOwnShadowAtTheBaseIsPassed)
{
	Fixture f;
	const double wall = 120.0, base = PolarScannerParams{}.base_radius;
	// Dark floor from the base out to 0.7 m, floor to the wall: the wall's range on every ray.
	const cv::Mat img = drawShadowAtTheBase(f.cam, wall, f.cam.rhoFromDistance(0.7));
	for (const Ray& r : f.scanner.scan(img, f.classifier))
	{
		ASSERT_EQ(r.status, RayStatus::Hit) << "bearing " << r.bearing;
		ASSERT_NEAR(r.range, f.cam.distanceFromRho(wall), onePixelBound(f.cam, wall));
		ASSERT_GT(r.past_base, 0);
	}
	// Off, as the paper had it: every ray too close.
	PolarScannerParams off;
	off.base_shadow = 0;
	for (const Ray& r : PolarScanner(f.cam, off).scan(img, f.classifier)) ASSERT_EQ(r.status, RayStatus::TooClose);
	// A run that reaches further than base_shadow from the first pixel is an obstacle.
	const double far = f.cam.distanceFromRho(base) + PolarScannerParams{}.base_shadow + 0.1;
	for (const Ray& r : f.scanner.scan(drawShadowAtTheBase(f.cam, 165.0, f.cam.rhoFromDistance(far)), f.classifier))
		ASSERT_EQ(r.status, RayStatus::TooClose);
	// Fewer than N free pixels behind the run do not make floor.
	const int N = PolarScannerParams{}.filter.N;
	for (const Ray& r : f.scanner.scan(drawShadowAtTheBase(f.cam, 80.0 + N / 2, 80.0), f.classifier))
		ASSERT_EQ(r.status, RayStatus::TooClose);
}

TEST(PolarScanner, AViewpointHeightThatPutsEveryRangeAtTheHorizonIsRefused)
{
	const PolarScannerParams p;  // 0.4 to 3.8 m
	EXPECT_NO_THROW(p.validate(OmniCameraModel{CameraParams{}}));  // h = 0.931 m: about 110 px of scanline
	// 1 mm (a typo for 1 m): every range from 0.4 to 3.8 m within 1 px of the horizon, and every ray "too close".
	CameraParams low;
	low.h = 0.001;
	EXPECT_THROW(p.validate(OmniCameraModel{low}), std::invalid_argument);
	low.h = 1e-300;
	EXPECT_THROW(p.validate(OmniCameraModel{low}), std::invalid_argument);
}
