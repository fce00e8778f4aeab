#pragma once
// Which way the robot's forward axis points in the image, and whether the
// image is mirror-reversed, found against the laser instead of guessed:
// every way of turning (1 ray's step) and reversing the omnicam's scans is
// compared with the laser's scans of the same moments, and the best one is
// the camera's orientation. How many frames' own best turns lie near it says
// how sure that is: with a wrong mirror scale every frame's best is a
// different turn.

#include <omnirange/core/Rangefinder.h>
#include <omnirange/train/MirrorCalibration.h>

#include <string>

namespace omnirange
{
class Progress;

struct OrientationFit
{
	double forward_azimuth{0};  ///< [rad] the fitted on-screen angle of the forward axis
	bool mirrored{true};  ///< the fitted reversal
	double error{0};  ///< [m] mean |laser - omni| (each at most 1.25 m) with the fitted orientation
	double error_as_given{0};  ///< [m] the same with the ini's orientation
	int frames{0};
	/** Frames whose own best turn is within kAgreeingTurn of the fitted one,
	 * with the same reversal. A frame in a symmetric corridor may prefer the
	 * turn half a circle away, so not all agree even when the fit is right. */
	int agreeing{0};
};

/** [rad] a frame's best turn this near the fitted one agrees with it. */
constexpr double kAgreeingTurn = 5 * 3.14159265358979323846 / 180;
/** Fewer frames agreeing than this share, or than kMinAgreeingFrames: the
 * orientation is not pinned down. Measured on twelve simulated worlds with the
 * right camera keys: 35 % (the archive, whose colours fail most) to 98 % of 60
 * frames agree; with R, the orientation or cx wrong: 5 to 18 % when the fit
 * was wrong (docs/experiments.md, "How sure the orientation is"). */
constexpr double kMinAgreeingShare = 0.25;
constexpr int kMinAgreeingFrames = 3;

inline bool pinnedDown(const OrientationFit& f)
{
	return f.agreeing >= kMinAgreeingFrames && f.agreeing >= kMinAgreeingShare * f.frames;
}

/** Streams the rawlog like calibrateMirror() (every `options.every`-th
 * image/laser pair, at most 60). Throws std::runtime_error naming the file
 * when fewer than 3 frames have both a scan and laser rays to compare. */
OrientationFit fitOrientation(const Rangefinder& rangefinder, const MirrorCalibrationOptions& options,
							  Progress* progress = nullptr);

/** The orientation and the scale it was found at: R for a paraboloid, alpha
 * for the first order, h for a calibrated shape (mei, ocamcalib). */
struct ScaledOrientationFit
{
	OrientationFit fit;
	double scale{0};  ///< the scale key's value the fit was made at
	std::string scale_key;  ///< "R", "alpha" or "h"
};

/** fitOrientation() at the ini's scale, at `fitted_scale` (what the laser
 * in `fitted` with the ini's orientation) and at steps from 0.6 to 1.67 times the
 * ini's; the least mean error over turn, reversal and scale wins. With the
 * scale and the orientation both wrong, the scale fitted with the wrong
 * orientation is wrong too, and the frames can agree on a wrong turn at it. */
ScaledOrientationFit fitOrientationAndScale(const RangefinderParams& params, const ColourModel& colours,
											const MirrorCalibration& fitted, const MirrorCalibrationOptions& options);

}  // namespace omnirange
