// The sub-pixel boundary: a step between two colours, blurred or mixed,
// is placed where it really is; without contrast, at the midpoint.
#include "SyntheticOmni.h"

#include <omnirange/core/BoundaryRefinement.h>
#include <omnirange/core/FreeSpaceClassifier.h>
#include <omnirange/core/PolarScanner.h>

#include <opencv2/imgproc.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace omnirange;

namespace
{
/** A 1-row image: floor colour up to `edge` (a pixel index boundary,
 * pixel k spanning [k - 0.5, k + 0.5]), obstacle after, each pixel the
 * area-weighted mix; then blurred with sigma (0: none). */
cv::Mat scanline(double edge, double sigma, int n = 40)
{
	cv::Mat row(1, n, CV_32FC3);
	for (int k = 0; k < n; ++k)
	{
		const double floor_part = std::clamp(edge - (k - 0.5), 0.0, 1.0);
		const cv::Vec3f f(60, 140, 70), o(40, 60, 150);
		row.at<cv::Vec3f>(0, k) = f * static_cast<float>(floor_part) + o * static_cast<float>(1 - floor_part);
	}
	if (sigma > 0) cv::GaussianBlur(row, row, cv::Size(0, 1), sigma, 0, cv::BORDER_REPLICATE);
	cv::Mat out;
	row.convertTo(out, CV_8UC3);
	return out;
}
}  // namespace

TEST(BoundaryRefinement, FindsABlurredStepToATenthOfAPixel)
{
	std::vector<std::int32_t> pix(40);
	std::iota(pix.begin(), pix.end(), 0);
	for (const double edge : {19.5, 19.8, 20.25, 20.6})
		for (const double sigma : {0.0, 0.7, 1.2})
		{
			const cv::Mat row = scanline(edge, sigma);
			// The classifier's hit: the first pixel more obstacle than floor-coloured.
			int hit = 0;
			while (row.at<cv::Vec3b>(0, hit)[1] > 100) ++hit;
			EXPECT_NEAR(refineBoundary(row.ptr<std::uint8_t>(), pix.data(), 40, hit), edge, 0.1)
				<< "edge " << edge << " sigma " << sigma << " hit " << hit;
		}
}

TEST(BoundaryRefinement, AnEdgePastTheHitIsReachedUpToTheReach)
{
	// The classifier stopped two pixels early (the floor's last pixels were
	// darkened, as at a wall's foot): the colours' edge is at 21.3, the hit 19.
	std::vector<std::int32_t> pix(40);
	std::iota(pix.begin(), pix.end(), 0);
	EXPECT_NEAR(refineBoundary(scanline(21.3, 0).ptr<std::uint8_t>(), pix.data(), 40, 19), 21.3, 0.1);
	// Blurred, the obstacle's reference pixels (22 to 24) start too near the
	// edge to be pure: 21.1 measured.
	const cv::Mat row = scanline(21.3, 0.7);
	EXPECT_NEAR(refineBoundary(row.ptr<std::uint8_t>(), pix.data(), 40, 19), 21.3, 0.25);
	EXPECT_DOUBLE_EQ(refineBoundary(row.ptr<std::uint8_t>(), pix.data(), 40, 19, 1.0), 20.0);  // the earlier limit
	EXPECT_DOUBLE_EQ(refineBoundary(row.ptr<std::uint8_t>(), pix.data(), 40, 19, 0.0), 19.0);
	// Never past what its mixed pixels can see: an edge 3.5 px on is placed 2.5 px on.
	const cv::Mat far = scanline(22.5, 0);
	EXPECT_NEAR(refineBoundary(far.ptr<std::uint8_t>(), pix.data(), 40, 19), 21.5, 1e-9);
	// A reach beyond that is refused by the scanner's options.
	PolarScannerParams p;
	p.boundary_reach = 3.0;
	EXPECT_THROW(p.validate(OmniCameraModel{CameraParams{}}), std::invalid_argument);
	p.boundary_reach = kMaxBoundaryReach;
	EXPECT_NO_THROW(p.validate(OmniCameraModel{CameraParams{}}));
}

TEST(BoundaryRefinement, WithoutContrastOrRoomItKeepsTheMidpoint)
{
	std::vector<std::int32_t> pix(40);
	std::iota(pix.begin(), pix.end(), 0);
	const cv::Mat flat(1, 40, CV_8UC3, cv::Scalar(60, 140, 70));
	EXPECT_DOUBLE_EQ(refineBoundary(flat.ptr<std::uint8_t>(), pix.data(), 40, 20), 19.5);
	const cv::Mat row = scanline(2.3, 0);
	EXPECT_DOUBLE_EQ(refineBoundary(row.ptr<std::uint8_t>(), pix.data(), 40, 2), 1.5);  // too near the start
}

TEST(BoundaryRefinement, TheScannerPlacesABlurredDiscsEdgeWhereItIs)
{
	const OmniCameraModel cam{CameraParams{}};
	const FreeSpaceClassifier classifier{test::floorHistogram(), 0.05};
	PolarScannerParams sub, mid;
	sub.boundary_model = BoundaryModel::Subpixel;
	mid.boundary_model = BoundaryModel::Midpoint;
	const PolarScanner midpoint(cam, mid), subpixel(cam, sub);
	// A disc of floor with a smooth edge at 111.3 px, blurred like a lens.
	const double rho = 111.3;
	cv::Mat img(768, 1024, CV_32FC3);
	for (int v = 0; v < img.rows; ++v)
		for (int u = 0; u < img.cols; ++u)
		{
			const double f = std::clamp(rho - std::hypot(u - 512.0, v - 384.0) + 0.5, 0.0, 1.0);
			img.at<cv::Vec3f>(v, u) = cv::Vec3f(60, 140, 70) * float(f) + cv::Vec3f(40, 60, 150) * float(1 - f);
		}
	cv::GaussianBlur(img, img, cv::Size(), 0.8);
	cv::Mat bgr;
	img.convertTo(bgr, CV_8UC3);
	const double truth = cam.distanceFromRho(rho);
	double err_mid = 0, err_sub = 0;
	const auto a = midpoint.scan(bgr, classifier), b = subpixel.scan(bgr, classifier);
	for (std::size_t i = 0; i < a.size(); ++i)
	{
		ASSERT_EQ(b[i].status, RayStatus::Hit);
		err_mid += std::abs(a[i].range - truth) / a.size();
		err_sub += std::abs(b[i].range - truth) / b.size();
	}
	const double px = cam.distanceFromRho(rho + 1) - truth;  // one pixel, in metres, here
	EXPECT_LT(err_sub, 0.25 * px) << "midpoint's error " << err_mid;
	EXPECT_LT(err_sub, err_mid);
}
