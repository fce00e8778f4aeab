#pragma once
// Camera/mirror model of a catadioptric (paraboloidal-mirror) omnicam looking
// down on a flat floor (paper §III-B, eq. (6); docs/method.md).

#include <omnirange/config/OptionsTable.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace omnirange
{
/** How a pixel's distance rho from the image centre maps to the incidence
 * angle theta (measured from the downward axis). */
enum class MirrorModel
{
	Paraboloid,  ///< exact paraboloid: theta = 2 atan(rho / R)
	FirstOrder,  ///< first-order Taylor model: theta ~= rho / alpha
	/** Mei's unified model (what cv::omnidir::calibrate fits). Its radial
	 * part: rho = gamma * r (1 + k1 r^2 + k2 r^4), r = sin(theta) / (cos(theta) + xi);
	 * xi = 1 is a paraboloid (gamma = R), 0 < xi < 1 a hyperboloid. With
	 * aspect, skew, p1 or p2 set the image is not radial: rho is then the
	 * radius the radial part alone would give (see OmniCameraModel). */
	Mei,
	/** Scaramuzza's OCamCalib polynomial (calib_results.txt): the ray seen
	 * at image radius rho is (rho, z) with z = a0 + a1 rho + a2 rho^2 + ...,
	 * the image centre's ray along -z: theta = atan2(rho, -z). */
	OCamCalib
};

std::string toString(MirrorModel m);
/** "paraboloid", "first_order", "mei" or "ocamcalib"; throws std::invalid_argument otherwise. */
MirrorModel mirrorModelFromString(const std::string& name);

/** Images past this many pixels are refused: readers from their header,
 * before decoding; a camera (or a simulated one) of that size in its ini. */
inline constexpr unsigned long kMaxImagePixels = 100000000;
/** [px] The widest or tallest image a camera ini may name. */
inline constexpr int kMaxImageSide = 20000;

/** Parameters of the omnicam. The ini keys equal the member names (angles:
 * the name plus "_deg", in degrees; see OptionsTable). */
struct CameraParams
{
	int image_width{1024};  ///< [px] width of the omnicam image
	int image_height{768};  ///< [px] height of the omnicam image
	double cx{512.0};  ///< [px] column of the image centre
	double cy{384.0};  ///< [px] row of the image centre
	double R{192.0};  ///< [px] radius of the 90-degree incidence circle
	double h{0.931};  ///< [m] height of the effective viewpoint above the floor
	MirrorModel mirror_model{MirrorModel::Paraboloid};
	/** [px/rad] first-order constant, theta ~= rho/alpha; used only when
	 * mirror_model = first_order (96 = R/2: the paraboloid's slope at the
	 * image centre). Fit it with omnirange-calibrate. */
	double alpha{96.0};
	/** Mei's unified model, used only when mirror_model = mei: the mirror
	 * parameter xi [-], the generalised focal length gamma [px]
	 * (cv::omnidir's fx) and the radial distortion k1, k2 [-] of its
	 * normalised image plane. The defaults are the stock paraboloid. */
	double xi{1.0};
	double gamma{192.0};
	double k1{0.0}, k2{0.0};
	/** The mei model's non-radial terms, as cv::omnidir fits them: the
	 * focal lengths fx = gamma and fy = aspect * gamma, the skew s [px]
	 * (u = fx x + s y + cx) and the tangential distortion p1, p2 [-]. */
	double aspect{1.0};
	double skew{0.0};
	double p1{0.0}, p2{0.0};
	/** OCamCalib's direct polynomial a0 a1 a2 ... [px^(1-i)], used only when
	 * mirror_model = ocamcalib (a0 < 0). For a paraboloid it is exactly
	 * -R/2, 0, 1/(2R). */
	std::vector<double> ocam_poly{};
	/** OCamCalib's affine terms c d e (calib_results.txt's #affine): the
	 * ideal image point (x along rows, y along columns) lands at row
	 * cy + c x + d y, column cx + e x + y. 1 0 0: none (the image is radial). */
	std::vector<double> ocam_affine{1.0, 0.0, 0.0};
	/** [rad] on-screen angle (counter-clockwise from the image's +u axis, as
	 * the picture is viewed) where the sensor's forward axis appears (pi:
	 * forward is at the image's left). */
	double forward_azimuth{3.14159265358979323846};
	/** true when bearings increase clockwise on screen, as in a real
	 * catadioptric image taken from below the mirror. */
	bool mirrored{true};

	/** The ini keys, units, meanings; defaults are the initialisers above. */
	static const OptionsTable<CameraParams>& table();
	/** Throws std::invalid_argument naming the offending key. */
	void validate() const;
};

/** A point on the floor in the sensor frame: x forward, y left [m]. */
struct FloorPoint
{
	double x{0}, y{0};
};

/** A pixel position in the image [px]: u column, v row. */
struct Pixel
{
	double u{0}, v{0};
};

/** Pixel <-> bearing/theta <-> metric distance, both ways.
 *
 * "rho" is a direction's radius in the ideal radial image: the image
 * radius for the radial models, and for a mei model with non-radial terms
 * (or an ocamcalib model with affine ones) the radius its radial part
 * alone would give. The pixel functions apply
 * the whole model, so a scanline stepped in rho along one bearing follows
 * the image of that floor ray, straight or not. */
class OmniCameraModel
{
   public:
	explicit OmniCameraModel(const CameraParams& p);

	const CameraParams& params() const { return p_; }

	/** Incidence angle [rad] seen by a pixel at distance rho [px]. */
	double thetaFromRho(double rho) const;
	/** Inverse of thetaFromRho(). */
	double rhoFromTheta(double theta) const;
	/** Floor distance d = h tan(theta) [m] (eq. (6)); +inf at or above the
	 * horizon. */
	double distanceFromRho(double rho) const;
	/** Image radius [px] at which a floor point at distance d [m] appears. */
	double rhoFromDistance(double d) const;
	/** Radius of the horizon (theta = 90 degrees) [px]. */
	double horizonRho() const { return rhoFromTheta(kHalfPi); }

	/** On-screen azimuth [rad] of a sensor-frame bearing [rad]. */
	double screenAzimuthFromBearing(double bearing) const;
	/** Sensor-frame bearing in (-pi, pi] of an on-screen azimuth. */
	double bearingFromScreenAzimuth(double azimuth) const;

	/** Pixel at polar position (bearing [rad], rho [px]). */
	Pixel pixelFromPolar(double bearing, double rho) const;
	/** rho [px] of a pixel (u, v): its distance from the centre when the model is radial. */
	double rhoOfPixel(const Pixel& px) const;
	/** false for a mei model with aspect, skew, p1 or p2 set, or an
	 * ocamcalib model with affine terms. */
	bool radial() const { return radial_; }
	/** (bearing [rad], rho [px]) of a pixel. */
	std::pair<double, double> polarFromPixel(const Pixel& px) const;

	/** Where a floor point appears in the image. */
	Pixel pixelFromFloor(const FloorPoint& f) const;
	/** The floor point a pixel sees, or nothing at/above the horizon. */
	std::optional<FloorPoint> floorFromPixel(const Pixel& px) const;

	static constexpr double kHalfPi = 1.57079632679489661923;

   private:
	/** The mei model's pixel of the normalised plane's point (x, y) (x along
	 * +u, y along +v), distortion included, and its inverse. */
	Pixel meiPixel(double x, double y) const;
	std::pair<double, double> meiNormalised(const Pixel& px) const;

	CameraParams p_;
	double rho_limit_{0};  ///< [px] the image's farthest pixel from the centre: no radius is sought beyond it
	bool radial_{true};
};

}  // namespace omnirange
