// The bird's-eye view (eqs. (1)-(3)) puts a floor mark where it lies.
#include "SyntheticOmni.h"

#include <omnirange/train/BirdsEyeView.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

using namespace omnirange;

TEST(BirdsEyeView, FloorMarksLandAtTheirMetricPosition)
{
	const OmniCameraModel cam{CameraParams{}};
	// A 0.2 m wall-coloured square on the floor, 1.0 m ahead and 0.5 m left.
	const cv::Mat omni = test::drawOmni(cam, [](const FloorPoint& f) {
		return std::abs(f.x - 1.0) < 0.1 && std::abs(f.y - 0.5) < 0.1;
	});
	const BirdsEyeView view(cam, 401, 0.01);  // 4 m square, 1 cm per pixel
	const cv::Mat be = view.render(omni);
	// Independent expectation: forward is up and left is left, centre at 200.
	cv::Mat wall;
	cv::inRange(be, test::kWall, test::kWall, wall);
	const cv::Moments m = cv::moments(wall, true);
	ASSERT_GT(m.m00, 200);  // about 20 x 20 px
	EXPECT_NEAR(m.m10 / m.m00, 200 - 50, 1.5);  // column: 0.5 m left
	EXPECT_NEAR(m.m01 / m.m00, 200 - 100, 1.5);  // row: 1.0 m ahead
	EXPECT_LT(m.m00, 500);
}

TEST(BirdsEyeView, RejectsBadSizes)
{
	const OmniCameraModel cam{CameraParams{}};
	EXPECT_THROW(BirdsEyeView(cam, 0, 0.01), std::invalid_argument);
	EXPECT_THROW(BirdsEyeView(cam, 100, 0.0), std::invalid_argument);
}
