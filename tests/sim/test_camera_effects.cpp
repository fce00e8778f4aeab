// The realism switches: each changes the picture the way a real camera or
// scene would, measured on rendered images; JPEG files carry 4:2:0 chroma.
#include "SimFixtures.h"

#include <omnirange_sim/CameraEffects.h>
#include <omnirange_sim/OmniRenderer.h>

#include <omnirange/io/RawlogWriter.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <fstream>
#include <iterator>

using namespace omnirange::sim;

namespace
{
/** Mean absolute horizontal gradient: how sharp an image is. */
double sharpness(const cv::Mat& bgr)
{
	cv::Mat grey, dx;
	cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
	cv::Sobel(grey, dx, CV_32F, 1, 0);
	return cv::mean(cv::abs(dx))[0];
}

/** The floor's mean colour in a small patch at (x, y) m in front of the robot at the origin. */
cv::Scalar floorPatch(const OmniRenderer& r, const cv::Mat& img, double x, double y)
{
	const auto p = r.trueCamera().pixelFromFloor({x, y});
	return cv::mean(img(cv::Rect(int(p.u) - 2, int(p.v) - 2, 5, 5)));
}
}  // namespace

TEST(CameraEffects, BlurSoftensAndVignettingDarkensTheRim)
{
	const World w = loadWorld(test::writeFile("room.world", test::roomWorld()));
	RobotParams robot = test::quietRobot();
	const cv::Mat sharp = OmniRenderer(w, robot).render({0, 0, 0}, 1);
	robot.omnicam.effects.blur_sigma = 1.5;
	const cv::Mat blurred = OmniRenderer(w, robot).render({0, 0, 0}, 1);
	EXPECT_LT(sharpness(blurred), 0.8 * sharpness(sharp));

	robot = test::quietRobot();
	robot.omnicam.effects.vignetting = 0.4;
	const OmniRenderer r(w, robot);
	const cv::Mat vignetted = r.render({0, 0, 0}, 1);
	// The floor dims by 1 - 0.4 (rho / rho_rim)^2 at its image radius rho.
	const auto& cam = r.trueCamera();
	const double rim = cam.rhoFromTheta(robot.omnicam.rim_theta);
	for (const double d : {0.7, 3.0})
	{
		const double ratio = floorPatch(r, vignetted, -d, 0)[1] / floorPatch(r, sharp, -d, 0)[1];
		EXPECT_NEAR(ratio, 1 - 0.4 * std::pow(cam.rhoFromDistance(d) / rim, 2), 0.02) << d << " m";
	}
}

TEST(CameraEffects, ExposureAndWhiteBalanceSwingAlongTheRoute)
{
	cv::Mat grey(10, 10, CV_8UC3, cv::Scalar(100, 100, 100));
	CameraEffectsParams p;
	p.exposure_drift = 0.2;
	p.white_balance_drift = 0.1;
	p.drift_period = 40;
	cv::Mat quarter = grey.clone();
	applyExposure(quarter, p, 10);  // a quarter period: the swing's peak
	const cv::Vec3b c = quarter.at<cv::Vec3b>(5, 5);
	EXPECT_NEAR(c[1], 120, 1);  // G: gain 1.2
	EXPECT_NEAR(c[2], 132, 1);  // R: 1.2 * 1.1
	EXPECT_NEAR(c[0], 108, 1);  // B: 1.2 * 0.9
	cv::Mat start = grey.clone();
	applyExposure(start, p, 0);
	EXPECT_EQ(start.at<cv::Vec3b>(5, 5), grey.at<cv::Vec3b>(5, 5));
}

TEST(CameraEffects, BayerKeepsFlatColoursAndBlursEdges)
{
	cv::Mat img(20, 20, CV_8UC3, cv::Scalar(60, 140, 70));
	img(cv::Rect(10, 0, 10, 20)).setTo(cv::Scalar(40, 60, 150));
	cv::Mat b = img.clone();
	applyBayer(b);
	EXPECT_LE(cv::norm(b.at<cv::Vec3b>(10, 4), img.at<cv::Vec3b>(10, 4)), 3.0);  // flat: kept
	EXPECT_LE(cv::norm(b.at<cv::Vec3b>(10, 15), img.at<cv::Vec3b>(10, 15)), 3.0);
	EXPECT_GT(cv::norm(b.at<cv::Vec3b>(10, 10), img.at<cv::Vec3b>(10, 10)), 10.0);  // the edge: mixed
}

TEST(CameraEffects, JpegImagesCarryFourTwoZeroChroma)
{
	const std::string rawlog = test::tempDir() + "/jpeg.rawlog";
	omnirange::RawlogWriter w(rawlog, "omnirange-test");
	const cv::Mat img(64, 64, CV_8UC3, cv::Scalar(60, 140, 70));
	const auto stored = w.externalImage(img, "frame.jpg", 90);
	w.write(mrpt::obs::CObservation2DRangeScan());
	w.commit();
	std::ifstream f(omnirange::imagesDirFor(rawlog) + "/frame.jpg", std::ios::binary);
	const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	// The baseline frame header (FF C0): three components, luma sampled 2x2 (0x22)
	// against 1x1 for both chroma: 4:2:0.
	const auto sof = bytes.find("\xFF\xC0");
	ASSERT_NE(sof, std::string::npos);
	ASSERT_EQ(static_cast<unsigned char>(bytes[sof + 9]), 3u);
	EXPECT_EQ(static_cast<unsigned char>(bytes[sof + 11]), 0x22u);
	EXPECT_EQ(static_cast<unsigned char>(bytes[sof + 14]), 0x11u);
	EXPECT_EQ(static_cast<unsigned char>(bytes[sof + 17]), 0x11u);
}

TEST(SceneRealism, TilesShowGroutAndOcclusionDarkensTheFootOfWalls)
{
	const std::string base = test::roomWorld();
	RobotParams robot = test::quietRobot();
	const World plain = loadWorld(test::writeFile("plain.world", base));
	const World dark = loadWorld(test::writeFile("ao.world", base + "light occlusion=0.5 occlusion_radius=0.2\n"));
	const OmniRenderer rp(plain, robot), ro(dark, robot);
	const cv::Mat a = rp.render({0, 0, 0}, 1), b = ro.render({0, 0, 0}, 1);
	// 5 cm from the red wall's foot (x = 2): darker by about exp(-0.25) * 0.5; 1.5 m away: the same.
	EXPECT_LT(floorPatch(ro, b, 1.95, 0)[1], 0.75 * floorPatch(rp, a, 1.95, 0)[1]);
	EXPECT_NEAR(floorPatch(ro, b, 0.5, -1.0)[1], floorPatch(rp, a, 0.5, -1.0)[1], 2.0);

	std::string tiled = base;  // its floor replaced (a world names one floor)
	tiled.erase(tiled.find("floor material=concrete\n"), std::string("floor material=concrete\n").size());
	const World tiles = loadWorld(test::writeFile(
		"tiles.world", tiled + "material name=tile rgb=200,200,190 grain_contrast=0 patch_contrast=0 hue_jitter=0 "
							  "pattern=tiles pattern_size=0.5 pattern_width=0.02 pattern_rgb=60,60,60\n"
							  "floor material=tile\n"));
	const OmniRenderer rt(tiles, robot);
	const cv::Mat t = rt.render({0, 0, 0}, 1);
	// A grout line at x = 1.0 m, a tile's middle at x = 0.75 m.
	EXPECT_LT(floorPatch(rt, t, 1.005, -0.25)[1] * 1.5, floorPatch(rt, t, 0.75, -0.25)[1]);
}

TEST(SceneRealism, TheRobotsOwnShadowFallsAwayFromTheSunAndDarkensItsFoot)
{
	// The sun in the west (-x; the room's walls then cast their shadows away from the robot),
	// 0.6 rad up: the body (0.45 x 0.38 m, 0.25 m tall) shades the floor east of it out to
	// 0.225 + 0.25 / tan(0.6) = 0.59 m.
	const World w = loadWorld(test::writeFile(
		"sun.world", test::roomWorld() + "light azimuth=3.14159 elevation=0.6 ambient=0.5 diffuse=0.6 occlusion=0.3 "
										 "occlusion_radius=0.12\n"));
	RobotParams robot = test::quietRobot();
	const OmniRenderer off(w, robot);
	robot.robot.own_shadow = true;
	const OmniRenderer on(w, robot);
	const cv::Mat a = off.render({0, 0, 0}, 1), b = on.render({0, 0, 0}, 1);
	const auto ratio = [&](double x, double y) { return floorPatch(on, b, x, y)[1] / floorPatch(off, a, x, y)[1]; };
	// In the shadow, 0.225 m from the body: only the ambient light, 0.5 / (0.5 + 0.6 sin 0.6),
	// and the foot's darkening, 1 - 0.3 exp(-0.225 / 0.12).
	EXPECT_NEAR(ratio(0.45, 0), 0.5 / (0.5 + 0.6 * std::sin(0.6)) * (1 - 0.3 * std::exp(-0.225 / 0.12)), 0.03);
	// On the sunny side at the same distance: the darkening alone.
	EXPECT_NEAR(ratio(-0.45, 0), 1 - 0.3 * std::exp(-0.225 / 0.12), 0.02);
	// Beside the body, 0.11 m from its side, in the sun: darker by 0.3 exp(-0.11 / 0.12).
	EXPECT_NEAR(ratio(0, 0.30), 1 - 0.3 * std::exp(-0.11 / 0.12), 0.03);
	// Past the shadow's end, and far away: untouched.
	EXPECT_NEAR(ratio(0.75, 0), 1.0, 0.02);
	EXPECT_NEAR(ratio(-1.0, -1.0), 1.0, 0.01);
}
