// Camera model: the paraboloid's known angles, round trips both ways, the
// image orientation convention, bad parameters.
#include "SyntheticOmni.h"

#include <omnirange/core/CameraModel.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace omnirange;

namespace
{
constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST(CameraModel, ParaboloidKnownAngles)
{
	const OmniCameraModel cam{CameraParams{}};  // R = 192, h = 0.931
	// theta = 2 atan(rho/R): rho = R is the 90-degree circle ...
	EXPECT_NEAR(cam.thetaFromRho(192.0), kPi / 2, 1e-12);
	EXPECT_TRUE(std::isinf(cam.distanceFromRho(192.0)));
	// ... and rho = R tan(pi/8) sees 45 degrees, where d = h.
	EXPECT_NEAR(cam.distanceFromRho(192.0 * std::tan(kPi / 8)), 0.931, 1e-9);
	EXPECT_DOUBLE_EQ(cam.distanceFromRho(0.0), 0.0);
	// The paper's max range, 3.8 m, lies near 151 px (its Fig. 8).
	EXPECT_NEAR(cam.rhoFromDistance(3.8), 150.6, 0.1);
}

TEST(CameraModel, RoundTripsBothModels)
{
	for (const CameraParams& p : {CameraParams{}, test::firstOrderCamera(110.0)})
	{
		const OmniCameraModel cam{p};
		for (double rho = 0.5; rho < 170; rho += 3.7)
		{
			EXPECT_NEAR(cam.rhoFromTheta(cam.thetaFromRho(rho)), rho, 1e-9);
			const double d = cam.distanceFromRho(rho);
			EXPECT_NEAR(cam.rhoFromDistance(d), rho, 1e-9);
		}
		for (double b = -3.1; b < 3.14; b += 0.37)
			for (double d : {0.2, 1.0, 3.7})
			{
				const FloorPoint f{d * std::cos(b), d * std::sin(b)};
				const auto back = cam.floorFromPixel(cam.pixelFromFloor(f));
				ASSERT_TRUE(back.has_value());
				EXPECT_NEAR(back->x, f.x, 1e-9);
				EXPECT_NEAR(back->y, f.y, 1e-9);
			}
	}
}

TEST(CameraModel, DefaultOrientationIsMirroredWithForwardAtTheLeft)
{
	const OmniCameraModel cam{CameraParams{}};
	// Forward (+x) appears on the image's left, on the centre row.
	const Pixel fwd = cam.pixelFromFloor({1.0, 0.0});
	EXPECT_LT(fwd.u, 512.0 - 50);
	EXPECT_NEAR(fwd.v, 384.0, 1e-9);
	// The robot's left (+y) appears at the top of the image.
	const Pixel left = cam.pixelFromFloor({0.0, 1.0});
	EXPECT_NEAR(left.u, 512.0, 1e-9);
	EXPECT_LT(left.v, 384.0 - 50);
	// Hence a mirror image: the right (-y) is at the bottom, behind at the right.
	EXPECT_GT(cam.pixelFromFloor({0.0, -1.0}).v, 384.0 + 50);
	EXPECT_GT(cam.pixelFromFloor({-1.0, 0.0}).u, 512.0 + 50);
}

TEST(CameraModel, UnmirroredAndRotatedMount)
{
	CameraParams p;
	p.mirrored = false;
	p.forward_azimuth = kPi / 2;  // forward at the top
	const OmniCameraModel cam{p};
	EXPECT_LT(cam.pixelFromFloor({1.0, 0.0}).v, 384.0 - 50);
	// Not mirrored: left is counter-clockwise from forward on screen.
	EXPECT_LT(cam.pixelFromFloor({0.0, 1.0}).u, 512.0 - 50);
}

TEST(CameraModel, AboveTheHorizonSeesNoFloor)
{
	const OmniCameraModel cam{CameraParams{}};
	EXPECT_FALSE(cam.floorFromPixel({512.0 + 200.0, 384.0}).has_value());
	EXPECT_TRUE(cam.floorFromPixel({512.0 + 150.0, 384.0}).has_value());
}

TEST(CameraModel, BadParametersAreRejected)
{
	CameraParams p;
	p.R = 0;
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);
	p = {};
	p.h = -1;
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);
	p = {};
	p.cx = 2000;
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);
	EXPECT_THROW(mirrorModelFromString("hyperbolic"), std::invalid_argument);
}

TEST(CameraModel, MeiWithXiOneIsTheParaboloid)
{
	CameraParams para, mei;
	mei.mirror_model = MirrorModel::Mei;
	mei.xi = 1.0, mei.gamma = para.R;
	const OmniCameraModel a(para), b(mei);
	for (double rho = 0; rho <= 400; rho += 12.5)
		EXPECT_NEAR(b.thetaFromRho(rho), a.thetaFromRho(rho), 1e-12) << rho;
	for (double rho = 0; rho < para.R; rho += 12.5)  // below the horizon
		EXPECT_NEAR(b.distanceFromRho(rho), a.distanceFromRho(rho), 1e-9) << rho;
}

TEST(CameraModel, MeiHyperboloidKnownRadii)
{
	// xi 0.5, gamma 100, no distortion: r = sin(theta) / (cos(theta) + 0.5), worked by hand.
	CameraParams p;
	p.mirror_model = MirrorModel::Mei;
	p.xi = 0.5, p.gamma = 100;
	const OmniCameraModel m(p);
	EXPECT_NEAR(m.rhoFromTheta(kPi / 3), 100 * std::sqrt(3.0) / 2, 1e-9);  // sin 60 / (0.5 + 0.5)
	EXPECT_NEAR(m.horizonRho(), 200, 1e-9);  // 1 / 0.5
	EXPECT_NEAR(m.thetaFromRho(200), kPi / 2, 1e-12);
	EXPECT_NEAR(m.thetaFromRho(0), 0, 1e-12);
	// With distortion: rho = gamma r (1 + k1 r^2 + k2 r^4); at the horizon r = 2.
	p.k1 = -0.05, p.k2 = 0.004;
	const OmniCameraModel d(p);
	EXPECT_NEAR(d.horizonRho(), 200 * (1 - 0.05 * 4 + 0.004 * 16), 1e-9);
	for (double theta = 0.05; theta < 1.85; theta += 0.1)
		EXPECT_NEAR(d.thetaFromRho(d.rhoFromTheta(theta)), theta, 1e-10) << theta;
}

TEST(CameraModel, MeiThatFoldsBackIsRejected)
{
	CameraParams p;
	p.mirror_model = MirrorModel::Mei;
	p.xi = 0.8, p.gamma = 160;
	EXPECT_NO_THROW(OmniCameraModel{p});
	p.k1 = -1.0;  // r (1 - r^2) turns back at r = 0.58, before the horizon (r = 1.25)
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);
	p.k1 = 0, p.xi = 0;
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);
	EXPECT_EQ(mirrorModelFromString("mei"), MirrorModel::Mei);
	EXPECT_EQ(toString(MirrorModel::Mei), "mei");
}

TEST(CameraModel, OCamCalibsPolynomialOfAParaboloidIsTheParaboloid)
{
	// z = -R/2 + rho^2 / (2R): tan(theta) = rho / -z = 2 rho R / (R^2 - rho^2) = tan(2 atan(rho/R)).
	CameraParams para, ocam;
	ocam.mirror_model = MirrorModel::OCamCalib;
	ocam.ocam_poly = {-para.R / 2, 0.0, 1 / (2 * para.R)};
	const OmniCameraModel a(para), b(ocam);
	for (double rho = 0; rho <= 400; rho += 12.5) EXPECT_NEAR(b.thetaFromRho(rho), a.thetaFromRho(rho), 1e-12) << rho;
	for (double theta = 0; theta < 2.5; theta += 0.1) EXPECT_NEAR(b.rhoFromTheta(theta), a.rhoFromTheta(theta), 1e-6) << theta;
	EXPECT_NEAR(b.horizonRho(), para.R, 1e-6);
	EXPECT_NEAR(b.distanceFromRho(100), a.distanceFromRho(100), 1e-9);
}

TEST(CameraModel, OCamCalibsAffineTermsPlacePixelsAsTheToolboxDoes)
{
	// The toolbox's world2cam: the ideal point (x along rows, y along
	// columns) lands at row cy + c x + d y, column cx + e x + y. Worked by hand for a direction straight "up" on screen
	// (x = -rho, y = 0) and one to the right (x = 0, y = rho).
	CameraParams p;
	p.mirror_model = MirrorModel::OCamCalib;
	p.ocam_poly = {-p.R / 2, 0.0, 1 / (2 * p.R)};
	EXPECT_TRUE(OmniCameraModel(p).radial());
	p.ocam_affine = {1.02, 0.004, -0.003};
	const OmniCameraModel m(p);
	EXPECT_FALSE(m.radial());
	const Pixel up = m.pixelFromPolar(m.bearingFromScreenAzimuth(M_PI / 2), 100);
	EXPECT_NEAR(up.v, p.cy - 1.02 * 100, 1e-9);
	EXPECT_NEAR(up.u, p.cx + 0.003 * 100, 1e-9);
	const Pixel right = m.pixelFromPolar(m.bearingFromScreenAzimuth(0), 100);
	EXPECT_NEAR(right.v, p.cy + 0.004 * 100, 1e-9);
	EXPECT_NEAR(right.u, p.cx + 100, 1e-9);
	// ...and back, all round.
	for (double b = -3; b < 3.1; b += 0.37)
		for (double rho = 20; rho < 300; rho += 40)
		{
			const auto [b2, rho2] = m.polarFromPixel(m.pixelFromPolar(b, rho));
			EXPECT_NEAR(std::remainder(b2 - b, 2 * M_PI), 0.0, 1e-12);
			EXPECT_NEAR(rho2, rho, 1e-9);
		}
	p.ocam_affine = {1.0, 0.0};
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);  // three numbers
	p.ocam_affine = {3.0, 0.0, 0.0};
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);  // not a camera's
}

TEST(CameraModel, MeisNonRadialTermsRoundTripAndMoveTheFloorsRays)
{
	CameraParams p;
	p.mirror_model = MirrorModel::Mei;
	p.xi = 0.8, p.gamma = 160;
	p.aspect = 1.03, p.skew = -3, p.p1 = 0.003, p.p2 = -0.002;
	const OmniCameraModel m(p);
	EXPECT_FALSE(m.radial());
	for (double b = -3; b < 3.1; b += 0.37)
		for (double rho = 20; rho < 200; rho += 30)
		{
			const auto [b2, rho2] = m.polarFromPixel(m.pixelFromPolar(b, rho));
			EXPECT_NEAR(std::remainder(b2 - b, 2 * M_PI), 0.0, 1e-9);
			EXPECT_NEAR(rho2, rho, 1e-7);
		}
	// The floor's rays are not where the radial part alone puts them: at
	// 2 m, fy = 1.03 fx alone moves the pixels along v by 3 % of their
	// radius (about 4 px); the floor point comes back from its pixel.
	CameraParams radial_part = p;
	radial_part.aspect = 1, radial_part.skew = 0, radial_part.p1 = 0, radial_part.p2 = 0;
	const OmniCameraModel r(radial_part);
	double worst = 0;
	for (double b = -3; b < 3.1; b += 0.5)
	{
		const Pixel x = m.pixelFromFloor({2 * std::cos(b), 2 * std::sin(b)});
		const Pixel y = r.pixelFromFloor({2 * std::cos(b), 2 * std::sin(b)});
		worst = std::max(worst, std::hypot(x.u - y.u, x.v - y.v));
	}
	EXPECT_GT(worst, 3.0);
	const Pixel c = m.pixelFromFloor({3.0, 3.0});
	const auto f = m.floorFromPixel(c);
	ASSERT_TRUE(f.has_value());
	EXPECT_NEAR(f->x, 3.0, 1e-6);
	EXPECT_NEAR(f->y, 3.0, 1e-6);
}

TEST(CameraModel, OCamCalibPolynomialsThatCannotBeAMirrorAreRejected)
{
	CameraParams p;
	p.mirror_model = MirrorModel::OCamCalib;
	p.ocam_poly = {};
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);  // none given
	p.ocam_poly = {96.0, 0.0, 1 / 384.0};
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);  // a0 > 0: the centre would look up
	p.ocam_poly = {-96.0, 0.0, 1 / 384.0, -1e-5};  // z falls again: theta turns back inside the image
	EXPECT_THROW(OmniCameraModel{p}, std::invalid_argument);
	EXPECT_EQ(mirrorModelFromString("ocamcalib"), MirrorModel::OCamCalib);
}

TEST(CameraModel, AnOCamCalibPolynomialNeedHoldOnlyOverTheImagesPixels)
{
	// theta = atan2(rho, -z), z = -100 + 0.001 rho^2 - 1e-6 rho^3: grows to
	// about 94 degrees near 620 px and turns back after. A 640 x 480 image
	// centred on the axis reaches 400 px: the polynomial is good over all of
	// it, though not out to the image's diagonal (800 px), as real fits are not.
	CameraParams p;
	p.mirror_model = MirrorModel::OCamCalib;
	p.image_width = 640, p.image_height = 480, p.cx = 320, p.cy = 240;
	p.ocam_poly = {-100, 0, 0.001, -1e-6};
	p.ocam_affine = {1, 0, 0};
	EXPECT_NO_THROW(p.validate());
	p.image_width = 1600, p.image_height = 1200, p.cx = 800, p.cy = 600;  // now 1000 px: past the turn
	EXPECT_THROW(p.validate(), std::invalid_argument);
}

TEST(CameraModel, AnOCamCalibPolynomialIsCheckedOutToTheIdealRadiusOfTheImagesCorners)
{
	// z = -96 + rho^2 / 384 - 2e-6 rho^3 turns theta back at about 701 px. On
	// a 1024 x 768 image centred on the axis the farthest corner is 640 px
	// away in pixels; with c = 0.6 (rows squeezed) it is about 820 px away as
	// the model's ideal radius, past the turn.
	CameraParams p;
	p.mirror_model = MirrorModel::OCamCalib;
	p.image_width = 1024, p.image_height = 768, p.cx = 512, p.cy = 384;
	p.ocam_poly = {-96, 0, 1 / 384.0, -2e-6};
	p.ocam_affine = {1, 0, 0};
	EXPECT_NO_THROW(p.validate());
	p.ocam_affine = {0.6, 0, 0};
	EXPECT_THROW(p.validate(), std::invalid_argument);
}
