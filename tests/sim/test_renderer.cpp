// The renderer against the camera model it shares with the rangefinder: a
// wall at a known distance appears at the predicted image radius (+-1 px).
#include "SimFixtures.h"

#include <omnirange_sim/OmniRenderer.h>

#include <cmath>

using namespace omnirange::sim;

namespace
{
/** Radius [px] of the first pixel, walking out from the centre along the
 * robot's bearing, whose colour is closer to `wall` than to the floor. */
double firstWallRadius(const cv::Mat& img, const omnirange::OmniCameraModel& cam, double bearing,
					   const cv::Vec3b& floor_bgr, const cv::Vec3b& wall_bgr)
{
	for (double rho = 45; rho < 190; rho += 0.25)
	{
		const auto p = cam.pixelFromPolar(bearing, rho);
		const cv::Vec3b c = img.at<cv::Vec3b>(int(std::lround(p.v)), int(std::lround(p.u)));
		if (cv::norm(c, wall_bgr, cv::NORM_L2) < cv::norm(c, floor_bgr, cv::NORM_L2))
			return std::hypot(std::lround(p.u) - cam.params().cx, std::lround(p.v) - cam.params().cy);
	}
	return -1;
}
}  // namespace

TEST(OmniRenderer, WallsAppearAtTheRadiusTheMirrorModelPredicts)
{
	const World w = loadWorld(test::writeFile("room.world", test::roomWorld()));
	const RobotParams robot = test::quietRobot();
	const OmniRenderer r(w, robot);
	const cv::Mat img = r.render({0, 0, 0}, 1);
	const auto& cam = r.trueCamera();
	// Reference colours: a floor pixel near the robot and a wall pixel well inside each wall.
	const auto at = [&](double bearing, double d) {
		const auto p = cam.pixelFromFloor({d * std::cos(bearing), d * std::sin(bearing)});
		return img.at<cv::Vec3b>(int(std::lround(p.v)), int(std::lround(p.u)));
	};
	const cv::Vec3b floor = at(0.0, 1.0);
	const cv::Vec3b red = img.at<cv::Vec3b>(384, int(512 - cam.rhoFromDistance(2.0) - 8));
	const cv::Vec3b blue = img.at<cv::Vec3b>(int(384 - cam.rhoFromDistance(1.5) - 8), 512);
	EXPECT_GT(red[2], red[0] + 50);  // the red wall is ahead: the image's left
	EXPECT_GT(blue[0], blue[2] + 50);  // the blue one on the left: the image's top

	for (double b : {-0.3, -0.1, 0.0, 0.2, 0.35})
	{
		const double d = 2.0 / std::cos(b);  // the red wall's face is x = 2
		EXPECT_NEAR(firstWallRadius(img, cam, b, floor, red), cam.rhoFromDistance(d), 1.0) << b;
	}
	for (double b : {1.3708, 1.5708, 1.7708})
	{
		const double d = 1.5 / std::sin(b);
		EXPECT_NEAR(firstWallRadius(img, cam, b, floor, blue), cam.rhoFromDistance(d), 1.0) << b;
	}
}

TEST(OmniRenderer, MisalignedMirrorMovesTheWholeImage)
{
	const World w = loadWorld(test::writeFile("room.world", test::roomWorld()));
	RobotParams shifted = test::quietRobot();
	shifted.omnicam.centre_offset_u = 6;
	const cv::Mat a = OmniRenderer(w, test::quietRobot()).render({0, 0, 0}, 1);
	const cv::Mat b = OmniRenderer(w, shifted).render({0, 0, 0}, 1);
	// Column u of the aligned image is column u + 6 of the shifted one.
	const double diff = cv::norm(a(cv::Rect(200, 200, 600, 368)), b(cv::Rect(206, 200, 600, 368)), cv::NORM_L1);
	const double base = cv::norm(a(cv::Rect(200, 200, 600, 368)), b(cv::Rect(200, 200, 600, 368)), cv::NORM_L1);
	EXPECT_LT(diff, 0.1 * base);
}

TEST(OmniRenderer, DeterministicForASeedAndNoisy)
{
	const World w = loadWorld(test::writeFile("room.world", test::roomWorld()));
	RobotParams robot;
	robot.omnicam.noise_sigma = 3;
	const OmniRenderer r(w, robot);
	const cv::Mat a = r.render({0.3, -0.2, 0.4}, 42);
	const cv::Mat b = r.render({0.3, -0.2, 0.4}, 42);
	const cv::Mat c = r.render({0.3, -0.2, 0.4}, 43);
	EXPECT_EQ(cv::norm(a, b, cv::NORM_L1), 0.0);
	EXPECT_GT(cv::norm(a, c, cv::NORM_L1), 0.0);
	// The noise's size: about sigma per channel.
	cv::Mat diff;
	cv::absdiff(a(cv::Rect(412, 284, 200, 200)), c(cv::Rect(412, 284, 200, 200)), diff);  // no clipping there
	EXPECT_NEAR(cv::mean(diff)[1], 3 * 2 / std::sqrt(3.14159265), 0.4);  // E|X-Y|, X,Y ~ N(0, 3)
}

TEST(OmniRenderer, RobotBodyAtTheCentreAndBlackBeyondTheRim)
{
	const World w = loadWorld(test::writeFile("room.world", test::roomWorld()));
	const OmniRenderer r(w, test::quietRobot());
	const cv::Mat img = r.render({0, 0, 0}, 1);
	const cv::Vec3b centre = img.at<cv::Vec3b>(384, 512);
	EXPECT_GT(centre[2], 100);  // the red robot
	EXPECT_LT(centre[1], 60);
	EXPECT_EQ(img.at<cv::Vec3b>(10, 10), cv::Vec3b(0, 0, 0));
	EXPECT_EQ(img.at<cv::Vec3b>(384, 512 + 300), cv::Vec3b(0, 0, 0));
}
