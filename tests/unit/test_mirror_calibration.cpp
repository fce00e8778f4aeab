// Mirror calibration: the fits of alpha and R recover the model that made
// the pairs, and fail on no pairs.
#include "SyntheticOmni.h"

#include <omnirange/train/MirrorCalibration.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace omnirange;

TEST(MirrorCalibration, FitAlphaRecoversTheFirstOrderConstant)
{
	const OmniCameraModel truth{test::firstOrderCamera(123.4)};
	std::vector<RhoRangePair> pairs;
	for (double rho = 20; rho < 150; rho += 10)
		pairs.push_back({rho, truth.distanceFromRho(rho)});
	EXPECT_NEAR(fitAlpha(pairs, 0.931), 123.4, 1e-9);
}

TEST(MirrorCalibration, FitAlphaOnParaboloidDataIsNearHalfR)
{
	// Small angles: 2 atan(rho/R) ~ 2 rho / R, so alpha ~ R/2 = 96.
	const OmniCameraModel para{CameraParams{}};
	std::vector<RhoRangePair> pairs;
	for (double rho = 2; rho < 20; rho += 2)
		pairs.push_back({rho, para.distanceFromRho(rho)});
	EXPECT_NEAR(fitAlpha(pairs, 0.931), 96.0, 0.5);
}

TEST(MirrorCalibration, FitRRecoversTheParaboloid)
{
	CameraParams truth_params;
	truth_params.R = 210.0;
	const OmniCameraModel truth{truth_params};
	std::vector<RhoRangePair> pairs;
	for (double rho = 30; rho < 170; rho += 7) pairs.push_back({rho, truth.distanceFromRho(rho)});
	EXPECT_NEAR(fitR(pairs, 0.931), 210.0, 1e-3);
	EXPECT_NEAR(rmsRangeError(truth, pairs), 0.0, 1e-9);
	// A wrong R shows in the range error.
	EXPECT_GT(rmsRangeError(OmniCameraModel{CameraParams{}}, pairs), 0.05);
	EXPECT_THROW(fitR({}, 0.931), std::invalid_argument);
}

TEST(MirrorCalibration, NoPairsIsAnError) { EXPECT_THROW(fitAlpha({}, 0.931), std::invalid_argument); }
