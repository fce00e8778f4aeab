#pragma once
// Which way the robot's forward axis points in the image, and whether the
// image is mirror-reversed, found against the laser instead of guessed:
// every way of turning (1 ray's step) and reversing the omnicam's scans is
// compared with the laser's scans of the same moments, and the best one is
// the camera's orientation. The spread of the frames' own best turns says how
// sure that is.

#include <omnirange/core/Rangefinder.h>
#include <omnirange/train/MirrorCalibration.h>

namespace omnirange
{
class Progress;

struct OrientationFit
{
	double forward_azimuth{0};  ///< [rad] the fitted on-screen angle of the forward axis
	bool mirrored{true};  ///< the fitted reversal
	double error{0};  ///< [m] mean |laser - omni| (each at most 1.25 m) with the fitted orientation
	double error_as_given{0};  ///< [m] the same with the ini's orientation
	/** [rad] RMS of the frames' own best turns around the fitted one (frames
	 * whose best reversal differs count pi). */
	double spread{0};
	int frames{0};
};

/** Streams the rawlog like calibrateMirror() (every `options.every`-th
 * image/laser pair, at most 60). Throws std::runtime_error naming the file
 * when fewer than 3 frames have both a scan and laser rays to compare. */
OrientationFit fitOrientation(const Rangefinder& rangefinder, const MirrorCalibrationOptions& options,
							  Progress* progress = nullptr);

}  // namespace omnirange
