#pragma once
// Calibrating the mirror against a laser (paper §IV-D): for every laser ray,
// the image radius where the omnicam's floor ends at the same bearing,
// paired with the laser's range; R (paraboloid) and alpha (first-order
// model) fitted to those pairs, the viewpoint's height h with the given
// camera (any model), and where the boundary sits.

#include <omnirange/core/Rangefinder.h>
#include <omnirange/io/ObservationPairer.h>
#include <omnirange/config/SensorLabels.h>

#include <string>
#include <vector>

namespace omnirange
{
class Progress;

/** One calibration pair: image radius of a floor boundary and the laser's
 * range to it (same bearing, same origin). */
struct RhoRangePair
{
	double rho;  ///< [px]
	double range;  ///< [m]
	int frame{0};  ///< which image it came from
};

/** Least-squares fit of the first-order constant alpha (theta ~= rho/alpha)
 * from (rho, laser range) pairs, with theta = atan(range/h). Minimises the
 * squared error in theta, which has the closed form
 * 1/alpha = sum(rho*theta) / sum(rho^2). Throws on no usable pair. */
double fitAlpha(const std::vector<RhoRangePair>& pairs, double h);

/** Least-squares fit of the paraboloid's R [px] (theta = 2 atan(rho/R)) from
 * the same pairs, minimising the squared error in theta (a 1-D search over
 * R in [10, 10000] px). Throws on no usable pair. */
double fitR(const std::vector<RhoRangePair>& pairs, double h);

/** The viewpoint's height h [m] that best explains the pairs with `camera`'s
 * theta(rho): least squares on d = h tan(theta) (pairs below 85 degrees),
 * refitted once without the pairs over 3x the median residual. */
struct HeightFit
{
	double h{0};
	/** [m] the standard error of h over the images: the spread of each
	 * image's own fit over the square root of their number (neighbouring
	 * rays' errors are not independent; images are nearly so). */
	double std_error{0};
	std::size_t used{0};
	int frames{0};  ///< images with at least 10 of the kept pairs
};
/** Throws std::invalid_argument on fewer than 2 usable pairs. */
HeightFit fitHeight(const OmniCameraModel& camera, const std::vector<RhoRangePair>& pairs);

/** RMS of the difference [m] between the pairs' ranges and the floor
 * distances `camera` gives their rho (pairs beyond the horizon count as
 * errors of 10 m). */
double rmsRangeError(const OmniCameraModel& camera, const std::vector<RhoRangePair>& pairs);

struct MirrorCalibrationOptions
{
	std::string input;  ///< rawlog with omnicam images and laser scans
	std::string omni_label{kOmnicamLabel};
	std::string laser_label{kLaserLabel};
	double max_dt{kDefaultMaxPairingDt};  ///< [s] largest time between an image and its scan
	int every{5};  ///< use every N-th image/scan pair
};

struct MirrorCalibration
{
	std::size_t pairs{0};  ///< (rho, laser range) pairs with an omnicam hit
	std::size_t kept{0};  ///< of them, kept after dropping residuals over 3x the median
	double R{0}, rms_R{0};  ///< [px] the paraboloid's fitted R, its RMS range error [m]
	double rms_given{0};  ///< [m] RMS range error of the given camera
	double alpha{0}, rms_alpha{0};  ///< [px/rad] the first-order fit, its RMS range error [m]
	HeightFit height;  ///< h fitted with the given camera's theta(rho)
	double rms_height{0};  ///< [m] RMS range error of the given camera with that h
	/** [px] median of how far (in image radius) the laser's boundary lies
	 * beyond where the omnicam put it, with the given camera. */
	double boundary_px{0};
	/** boundary_offset that would remove that median, clamped to the
	 * scanner's [-1, 1] px; `clamped` says when it was. */
	double suggested_boundary_offset{0};
	bool clamped{false};
};

/** Streams the rawlog, scans the chosen images with `rangefinder`, pairs
 * their hits with the laser and fits both mirror models. Throws
 * std::runtime_error naming the file when it holds fewer than 10 pairs. */
MirrorCalibration calibrateMirror(const Rangefinder& rangefinder, const MirrorCalibrationOptions& options,
								  Progress* progress = nullptr);

}  // namespace omnirange
