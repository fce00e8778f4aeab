#include "omnirange/CameraModel.h"

#include "omnirange/Config.h"

#include <mrpt/config/CConfigFileBase.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace omnirange
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

double wrapToPi(double a)
{
	a = std::fmod(a + kPi, 2 * kPi);
	if (a <= 0) a += 2 * kPi;
	return a - kPi;  // (-pi, pi]
}
}  // namespace

std::string toString(MirrorModel m)
{
	return m == MirrorModel::Paraboloid ? "paraboloid" : "first_order";
}

MirrorModel mirrorModelFromString(const std::string& name)
{
	if (name == "paraboloid") return MirrorModel::Paraboloid;
	if (name == "first_order") return MirrorModel::FirstOrder;
	throw std::invalid_argument(
		"mirror_model must be 'paraboloid' or 'first_order', not '" + name +
		"'");
}

std::vector<std::string> CameraParams::keys()
{
	return {"image_width",	"image_height", "cx",
			"cy",			"R",			"h",
			"mirror_model", "alpha",		"forward_azimuth",
			"mirrored"};
}

void CameraParams::loadFromConfig(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	image_width = c.read_int(s, "image_width", image_width);
	image_height = c.read_int(s, "image_height", image_height);
	cx = c.read_double(s, "cx", cx);
	cy = c.read_double(s, "cy", cy);
	R = c.read_double(s, "R", R);
	h = c.read_double(s, "h", h);
	mirror_model = mirrorModelFromString(
		c.read_string(s, "mirror_model", toString(mirror_model)));
	alpha = c.read_double(s, "alpha", alpha);
	forward_azimuth = c.read_double(s, "forward_azimuth", forward_azimuth);
	mirrored = c.read_bool(s, "mirrored", mirrored);
}

void CameraParams::validate() const
{
	const auto need = [](bool ok, const std::string& what) {
		requireParam(ok, "camera", what);
	};
	need(image_width > 0 && image_height > 0,
		 "image_width and image_height must be > 0");
	need(std::isfinite(R) && R > 0, "R must be > 0 px");
	need(std::isfinite(h) && h > 0, "h must be > 0 m");
	need(std::isfinite(alpha) && alpha > 0, "alpha must be > 0 px/rad");
	need(cx >= 0 && cx < image_width && cy >= 0 && cy < image_height,
		 "the image centre (cx, cy) must lie inside the image");
	need(std::isfinite(forward_azimuth), "forward_azimuth must be finite");
}

OmniCameraModel::OmniCameraModel(const CameraParams& p) : p_(p)
{
	p_.validate();
}

double OmniCameraModel::thetaFromRho(double rho) const
{
	if (p_.mirror_model == MirrorModel::Paraboloid)
		return 2.0 * std::atan(rho / p_.R);
	return rho / p_.alpha;
}

double OmniCameraModel::rhoFromTheta(double theta) const
{
	if (p_.mirror_model == MirrorModel::Paraboloid)
		return p_.R * std::tan(0.5 * theta);
	return theta * p_.alpha;
}

double OmniCameraModel::distanceFromRho(double rho) const
{
	const double theta = thetaFromRho(rho);
	if (theta >= kHalfPi) return std::numeric_limits<double>::infinity();
	return p_.h * std::tan(theta);  // eq. (6)
}

double OmniCameraModel::rhoFromDistance(double d) const
{
	return rhoFromTheta(std::atan2(d, p_.h));
}

double OmniCameraModel::screenAzimuthFromBearing(double bearing) const
{
	return wrapToPi(p_.forward_azimuth + (p_.mirrored ? -bearing : bearing));
}

double OmniCameraModel::bearingFromScreenAzimuth(double azimuth) const
{
	const double rel = azimuth - p_.forward_azimuth;
	return wrapToPi(p_.mirrored ? -rel : rel);
}

Pixel OmniCameraModel::pixelFromPolar(double bearing, double rho) const
{
	const double a = screenAzimuthFromBearing(bearing);
	// Rows grow downwards, so the on-screen counter-clockwise angle flips v.
	return {p_.cx + rho * std::cos(a), p_.cy - rho * std::sin(a)};
}

std::pair<double, double> OmniCameraModel::polarFromPixel(const Pixel& px) const
{
	const double du = px.u - p_.cx, dv = px.v - p_.cy;
	return {bearingFromScreenAzimuth(std::atan2(-dv, du)), std::hypot(du, dv)};
}

Pixel OmniCameraModel::pixelFromFloor(const FloorPoint& f) const
{
	return pixelFromPolar(
		std::atan2(f.y, f.x), rhoFromDistance(std::hypot(f.x, f.y)));
}

std::optional<FloorPoint> OmniCameraModel::floorFromPixel(const Pixel& px) const
{
	const auto [bearing, rho] = polarFromPixel(px);
	const double d = distanceFromRho(rho);
	if (!std::isfinite(d)) return std::nullopt;
	return FloorPoint{d * std::cos(bearing), d * std::sin(bearing)};
}

double fitAlpha(const std::vector<RhoRangePair>& pairs, double h)
{
	if (!(h > 0)) throw std::invalid_argument("fitAlpha: h must be > 0 m");
	double s_rt = 0, s_rr = 0;
	for (const auto& p : pairs)
	{
		if (!(p.rho > 0) || !(p.range > 0) || !std::isfinite(p.range)) continue;
		const double theta = std::atan2(p.range, h);
		s_rt += p.rho * theta;
		s_rr += p.rho * p.rho;
	}
	if (s_rt <= 0)
		throw std::invalid_argument(
			"fitAlpha: no (rho > 0, range > 0) pair to fit alpha from");
	return s_rr / s_rt;
}

double fitR(const std::vector<RhoRangePair>& pairs, double h)
{
	if (!(h > 0)) throw std::invalid_argument("fitR: h must be > 0 m");
	std::vector<std::pair<double, double>> rt;  // rho, theta
	for (const auto& p : pairs)
		if (p.rho > 0 && p.range > 0 && std::isfinite(p.range)) rt.emplace_back(p.rho, std::atan2(p.range, h));
	if (rt.empty()) throw std::invalid_argument("fitR: no (rho > 0, range > 0) pair to fit R from");
	const auto cost = [&](double logR) {
		const double R = std::exp(logR);
		double c = 0;
		for (const auto& [rho, theta] : rt) c += std::pow(2.0 * std::atan(rho / R) - theta, 2);
		return c;
	};
	// Golden-section search on log R: the cost is unimodal in R for these pairs.
	double a = std::log(10.0), b = std::log(10000.0);
	const double g = 0.5 * (std::sqrt(5.0) - 1);
	double x1 = b - g * (b - a), x2 = a + g * (b - a), f1 = cost(x1), f2 = cost(x2);
	for (int i = 0; i < 200 && b - a > 1e-10; ++i)
		if (f1 < f2)
			b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = cost(x1);
		else
			a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = cost(x2);
	return std::exp(0.5 * (a + b));
}

double rmsRangeError(const OmniCameraModel& camera, const std::vector<RhoRangePair>& pairs)
{
	if (pairs.empty()) return 0;
	double s = 0;
	for (const auto& p : pairs)
	{
		const double d = camera.distanceFromRho(p.rho);
		s += std::isfinite(d) ? std::pow(d - p.range, 2) : 100.0;
	}
	return std::sqrt(s / pairs.size());
}

}  // namespace omnirange
