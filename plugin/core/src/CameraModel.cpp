#include "omnirange/core/CameraModel.h"



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

/** OCamCalib: the ray at image radius rho is (rho, z(rho)), the centre's along -z. */
double ocamTheta(const std::vector<double>& poly, double rho)
{
	double z = 0;
	for (auto a = poly.rbegin(); a != poly.rend(); ++a) z = z * rho + *a;  // Horner
	return std::atan2(rho, -z);
}

/** Mei: the normalised plane's radius r with the radial distortion applied. */
double meiDistorted(const CameraParams& p, double r)
{
	const double r2 = r * r;
	return r * (1 + p.k1 * r2 + p.k2 * r2 * r2);
}

/** Mei: the normalised image radius of incidence theta, distortion included (times gamma: pixels). */
double meiRadius(const CameraParams& p, double theta)
{
	return meiDistorted(p, std::sin(theta) / (std::cos(theta) + p.xi));  // the sphere's point, projected
}

/** Mei: the inverse of meiDistorted (Newton on r (1 + k1 r^2 + k2 r^4) = rd). */
double meiUndistorted(const CameraParams& p, double rd)
{
	double r = rd;
	for (int i = 0; i < 20; ++i)
	{
		const double r2 = r * r;
		const double df = 1 + 3 * p.k1 * r2 + 5 * p.k2 * r2 * r2;
		if (df <= 0) break;
		const double step = (meiDistorted(p, r) - rd) / df;
		if (step == 0) break;  // a fixed point: the iterations left would not change r
		r -= step;
	}
	return r;
}

/** [px] The image's farthest pixel from the centre, as the model's radius (OCamCalib's ideal one, through
 * its affine terms): no radius is sought, and no model need hold, beyond it. */
double farthestPixelRadius(const CameraParams& p)
{
	if (p.mirror_model != MirrorModel::OCamCalib || p.ocam_affine.size() != 3)
		return std::hypot(std::max(p.cx, p.image_width - p.cx), std::max(p.cy, p.image_height - p.cy));
	// The ideal radius is a norm of a linear map of the pixel: largest at a corner.
	const auto& A = p.ocam_affine;
	const double det = A[0] - A[1] * A[2];
	double farthest = 0;
	for (const double u : {0.0, static_cast<double>(p.image_width)})
		for (const double v : {0.0, static_cast<double>(p.image_height)})
		{
			const double du = u - p.cx, dv = v - p.cy;
			farthest = std::max(farthest, std::hypot((dv - A[1] * du) / det, (A[0] * du - A[2] * dv) / det));
		}
	return farthest;
}
}  // namespace

std::string toString(MirrorModel m)
{
	switch (m)
	{
		case MirrorModel::Paraboloid: return "paraboloid";
		case MirrorModel::FirstOrder: return "first_order";
		case MirrorModel::Mei: return "mei";
		case MirrorModel::OCamCalib: return "ocamcalib";
	}
	throw std::logic_error("unknown MirrorModel");
}

MirrorModel mirrorModelFromString(const std::string& name)
{
	if (name == "paraboloid") return MirrorModel::Paraboloid;
	if (name == "first_order") return MirrorModel::FirstOrder;
	if (name == "mei") return MirrorModel::Mei;
	if (name == "ocamcalib") return MirrorModel::OCamCalib;
	throw std::invalid_argument("mirror_model must be 'paraboloid', 'first_order', 'mei' or 'ocamcalib', not '" + name +
								"'");
}

const OptionsTable<CameraParams>& CameraParams::table()
{
	using P = CameraParams;
	static const auto t = OptionsTable<P>()
		.add("image_width", "px", "width of the omnicam image; other sizes are rejected", [](P& p) -> auto& { return p.image_width; })
		.within(Range::closed(1, kMaxImageSide))
		.add("image_height", "px", "height of the omnicam image", [](P& p) -> auto& { return p.image_height; })
		.within(Range::closed(1, kMaxImageSide))
		.add("cx", "px", "column of the image centre (the mirror's axis)", [](P& p) -> auto& { return p.cx; })
		.add("cy", "px", "row of the image centre", [](P& p) -> auto& { return p.cy; })
		.add("R", "px", "radius of the 90-degree incidence circle of the paraboloid", [](P& p) -> auto& { return p.R; })
		.within(Range::openLow(0, kMaxImageSide))
		.add("h", "m", "height of the effective viewpoint above the floor", [](P& p) -> auto& { return p.h; })
		.within(Range::openLow(0, 100))
		.addEnum("mirror_model",
				 "paraboloid: theta = 2 atan(rho/R); first_order: theta = rho/alpha; mei: Mei's unified model "
				 "(xi, gamma, k1, k2, aspect, skew, p1, p2), as cv::omnidir calibrates it; ocamcalib: Scaramuzza's polynomial (ocam_poly)",
				 [](P& p) -> auto& { return p.mirror_model; }, mirrorModelFromString,
				 {MirrorModel::Paraboloid, MirrorModel::FirstOrder, MirrorModel::Mei, MirrorModel::OCamCalib})
		.add("alpha", "px/rad", "alpha of the first-order model (R/2 matches the paraboloid near the centre)",
			 [](P& p) -> auto& { return p.alpha; })
		.within(Range::above(0))
		.add("xi", "-", "mirror parameter of the mei model (1: paraboloid; between 0 and 1: hyperboloid)",
			 [](P& p) -> auto& { return p.xi; })
		.within(Range::openLow(0, 10))
		.add("gamma", "px", "generalised focal length of the mei model (cv::omnidir's fx, K(0,0))",
			 [](P& p) -> auto& { return p.gamma; })
		.within(Range::above(0))
		.add("k1", "-", "first radial distortion coefficient of the mei model", [](P& p) -> auto& { return p.k1; })
		.within(Range::finite())
		.add("k2", "-", "second radial distortion coefficient of the mei model", [](P& p) -> auto& { return p.k2; })
		.within(Range::finite())
		.add("aspect", "-", "fy / fx of the mei model (cv::omnidir's K(1,1) / K(0,0)); 1: square pixels",
			 [](P& p) -> auto& { return p.aspect; })
		.within(Range::open(0.5, 2))
		.add("skew", "px", "skew of the mei model (cv::omnidir's s, K(0,1): u = gamma x + skew y + cx)",
			 [](P& p) -> auto& { return p.skew; })
		.add("p1", "-", "first tangential distortion coefficient of the mei model", [](P& p) -> auto& { return p.p1; })
		.within(Range::open(-0.1, 0.1))
		.add("p2", "-", "second tangential distortion coefficient of the mei model", [](P& p) -> auto& { return p.p2; })
		.within(Range::open(-0.1, 0.1))
		.add("ocam_poly", "-", "OCamCalib's direct polynomial a0 a1 a2 ..., blank-separated (the ocamcalib model; "
							   "omnirange-calibrate --ocamcalib reads it from calib_results.txt)",
			 [](P& p) -> auto& { return p.ocam_poly; })
		.add("ocam_affine", "-",
			 "OCamCalib's affine terms c d e (calib_results.txt's #affine; the ocamcalib model): the ideal point "
			 "(x along rows, y along columns) lands at row cy + c x + d y, column cx + e x + y; 1 0 0: none",
			 [](P& p) -> auto& { return p.ocam_affine; })
		.addAngle("forward_azimuth",
				  "on-screen angle, counter-clockwise from the image's +u axis as the picture is viewed, where "
				  "the sensor's forward axis appears (180: the image's left)",
				  [](P& p) -> auto& { return p.forward_azimuth; })
		.within(Range::closed(-kMaxMountAngle, kMaxMountAngle))
		.add("mirrored", "bool", "bearings increase clockwise on screen, as in an image taken from below the mirror",
			 [](P& p) -> auto& { return p.mirrored; })
		.renamed("forward_azimuth", "use forward_azimuth_deg, in degrees (180 where forward_azimuth was 3.14159)");
	return t;
}

void CameraParams::validate() const
{
	table().requireRanges(*this);
	require(static_cast<unsigned long>(image_width) * static_cast<unsigned long>(image_height) <= kMaxImagePixels,
			"image_width x image_height must be at most 100 megapixels (no reader takes more)");
	require(cx >= 0 && cx < image_width && cy >= 0 && cy < image_height,
			"the image centre (cx, cy) must lie inside the image");
	require(std::abs(skew) < 0.1 * gamma, "skew must be smaller than a tenth of gamma");
	if (mirror_model == MirrorModel::OCamCalib)
	{
		require(ocam_poly.size() >= 2 && ocam_poly.size() <= 20, "ocam_poly needs 2 to 20 coefficients a0 a1 ...");
		require(ocam_poly[0] < 0, "ocam_poly's a0 must be < 0 (OCamCalib's image centre looks along -z)");
		require(ocam_affine.size() == 3, "ocam_affine needs three numbers, c d e");
		require(std::abs(ocam_affine[0] - ocam_affine[1] * ocam_affine[2] - 1) < 0.5,
				"ocam_affine's c - d e must be within 0.5 of 1 (it scales the image)");
		// theta must grow with rho out to the image's farthest pixel (or to 170
		// degrees); past the image a real calibration's polynomial may turn back.
		const double limit = farthestPixelRadius(*this);
		double last = 0;
		for (double rho = 1; rho <= limit; rho += 1)
		{
			const double theta = ocamTheta(ocam_poly, rho);
			require(theta > last, "ocam_poly's incidence angle must grow with the image radius (it turns back at " +
									  std::to_string(static_cast<int>(rho)) + " px)");
			if (theta > 2.967) break;  // 170 degrees: far past anything on the floor
			last = theta;
		}
	}
	if (mirror_model == MirrorModel::Mei)
	{
		// The image radius must grow with theta up to the horizon, or a radius
		// would stand for two incidence angles.
		double last = 0;
		for (int i = 1; i <= 90; ++i)
		{
			const double now = meiRadius(*this, i * kPi / 180);
			require(now > last, "the mei model's image radius must grow with the incidence angle up to 90 degrees "
								"(check xi, k1, k2)");
			last = now;
		}
	}
}

OmniCameraModel::OmniCameraModel(const CameraParams& p) : p_(p)
{
	p_.validate();
	rho_limit_ = farthestPixelRadius(p_);
	if (p_.mirror_model == MirrorModel::Mei)
		radial_ = p_.aspect == 1.0 && p_.skew == 0.0 && p_.p1 == 0.0 && p_.p2 == 0.0;
	if (p_.mirror_model == MirrorModel::OCamCalib)
		radial_ = p_.ocam_affine == std::vector<double>{1.0, 0.0, 0.0};
}

Pixel OmniCameraModel::meiPixel(double x, double y) const
{
	const double r2 = x * x + y * y;
	const double radial = 1 + p_.k1 * r2 + p_.k2 * r2 * r2;
	const double xd = x * radial + 2 * p_.p1 * x * y + p_.p2 * (r2 + 2 * x * x);
	const double yd = y * radial + p_.p1 * (r2 + 2 * y * y) + 2 * p_.p2 * x * y;
	return {p_.gamma * xd + p_.skew * yd + p_.cx, p_.aspect * p_.gamma * yd + p_.cy};
}

std::pair<double, double> OmniCameraModel::meiNormalised(const Pixel& px) const
{
	// Newton on meiPixel(x, y) = px from the undistorted guess; the
	// distortion is smooth and small, a few steps reach 1e-12 px.
	const double yd = (px.v - p_.cy) / (p_.aspect * p_.gamma);
	const double xd = (px.u - p_.cx - p_.skew * yd) / p_.gamma;
	double x = xd, y = yd;
	for (int i = 0; i < 30; ++i)
	{
		const Pixel f = meiPixel(x, y);
		const double eu = f.u - px.u, ev = f.v - px.v;
		if (std::abs(eu) + std::abs(ev) < 1e-12) break;
		const double e = 1e-7;
		const Pixel fx = meiPixel(x + e, y), fy = meiPixel(x, y + e);
		const double a = (fx.u - f.u) / e, b = (fy.u - f.u) / e, c = (fx.v - f.v) / e, d = (fy.v - f.v) / e;
		const double det = a * d - b * c;
		if (std::abs(det) < 1e-12) break;
		x -= (d * eu - b * ev) / det;
		y -= (a * ev - c * eu) / det;
	}
	return {x, y};
}

double OmniCameraModel::thetaFromRho(double rho) const
{
	switch (p_.mirror_model)
	{
		case MirrorModel::Paraboloid: return 2.0 * std::atan(rho / p_.R);
		case MirrorModel::FirstOrder: return rho / p_.alpha;
		case MirrorModel::OCamCalib: return ocamTheta(p_.ocam_poly, rho);
		case MirrorModel::Mei: break;
	}
	// Undo the distortion, then lift the point of the normalised plane onto
	// the unit sphere (Mei's model).
	const double r = meiUndistorted(p_, rho / p_.gamma);
	const double disc = 1 + (1 - p_.xi * p_.xi) * r * r;
	if (disc < 0) return kPi;  // beyond the mirror's image
	const double lift = (p_.xi + std::sqrt(disc)) / (r * r + 1);
	return std::atan2(lift * r, lift - p_.xi);
}

double OmniCameraModel::rhoFromTheta(double theta) const
{
	switch (p_.mirror_model)
	{
		case MirrorModel::Paraboloid: return p_.R * std::tan(0.5 * theta);
		case MirrorModel::FirstOrder: return theta * p_.alpha;
		case MirrorModel::OCamCalib:
		{
			// theta(rho) grows (validate() checks it): bisection, to 1e-9 px.
			double lo = 0, hi = rho_limit_;
			if (ocamTheta(p_.ocam_poly, hi) < theta) return std::numeric_limits<double>::infinity();
			while (hi - lo > 1e-9)
			{
				const double mid = 0.5 * (lo + hi);
				(ocamTheta(p_.ocam_poly, mid) < theta ? lo : hi) = mid;
			}
			return 0.5 * (lo + hi);
		}
		case MirrorModel::Mei: break;
	}
	return p_.gamma * meiRadius(p_, theta);
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
	if (radial_) return {p_.cx + rho * std::cos(a), p_.cy - rho * std::sin(a)};
	if (p_.mirror_model == MirrorModel::OCamCalib)
	{
		const double x = -rho * std::sin(a), y = rho * std::cos(a);  // along rows, along columns
		const auto& A = p_.ocam_affine;
		return {p_.cx + A[2] * x + y, p_.cy + A[0] * x + A[1] * y};
	}
	const double r = meiUndistorted(p_, rho / p_.gamma);  // the normalised plane's radius
	return meiPixel(r * std::cos(a), -r * std::sin(a));
}

double OmniCameraModel::rhoOfPixel(const Pixel& px) const { return polarFromPixel(px).second; }

std::pair<double, double> OmniCameraModel::polarFromPixel(const Pixel& px) const
{
	if (radial_)
	{
		const double du = px.u - p_.cx, dv = px.v - p_.cy;
		return {bearingFromScreenAzimuth(std::atan2(-dv, du)), std::hypot(du, dv)};
	}
	if (p_.mirror_model == MirrorModel::OCamCalib)
	{
		const auto& A = p_.ocam_affine;
		const double dv = px.v - p_.cy, du = px.u - p_.cx;
		const double det = A[0] - A[1] * A[2];
		const double x = (dv - A[1] * du) / det, y = (A[0] * du - A[2] * dv) / det;
		return {bearingFromScreenAzimuth(std::atan2(-x, y)), std::hypot(x, y)};
	}
	const auto [x, y] = meiNormalised(px);
	// The radial part's radius of the same direction.
	return {bearingFromScreenAzimuth(std::atan2(-y, x)), p_.gamma * meiDistorted(p_, std::hypot(x, y))};
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

}  // namespace omnirange
