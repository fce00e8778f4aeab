#include "omnirange_sim/OmniRenderer.h"

#include "omnirange_sim/CameraEffects.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace omnirange::sim
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = kPi / 2;
constexpr double kMaxSight = 40.0;  // [m] beyond this the view is sky
constexpr double kPenumbra = 0.05;  // [m] width of the robot's shadow's soft edge

/** The light left at `distance` [m] from the foot of something standing on the floor. */
double footLight(const Light& L, double distance)
{
	return 1.0 - L.occlusion * std::exp(-distance / L.occlusion_radius);
}

enum Surface : int
{
	kFloor = 1,
	kSky = 2,
	kRobot = 3,
	kRim = 4,
	kOutside = 5,
	kFirstSolid = 8  // + 4 * solid + face (0 side, 1 top, 2 bottom)
};

CameraParams misaligned(const RobotParams& r)
{
	CameraParams c = r.omnicam.camera;
	c.cx += r.omnicam.centre_offset_u;
	c.cy += r.omnicam.centre_offset_v;
	return c;
}

std::uint8_t clamp8(double v) { return static_cast<std::uint8_t>(std::clamp(v + 0.5, 0.0, 255.0)); }
}  // namespace

struct OmniRenderer::Frame
{
	Vec2 origin;  // the viewpoint, in the world
	double yaw;  // the sensor's yaw in the world
	std::vector<std::vector<SolidCrossing>> bins;
	Pose2 robot;  // the body's pose, for its own shadow
	double robot_cos{1}, robot_sin{0};  // of its yaw
	std::vector<cv::Point2f> own_shadow;  // the body's sun shadow on the floor (world, convex); empty: off
	double own_reach{0};  // [m] beyond this from the robot the body darkens nothing
};

OmniRenderer::OmniRenderer(const World& world, const RobotParams& robot)
	: world_(world),
	  robot_(robot),
	  cam_(misaligned(robot)),
	  tex_(robot.robot.seed * 7919u + 17u),
	  rim_rho_(cam_.rhoFromTheta(robot.omnicam.rim_theta)),
	  robot_material_(std::max(0, world.findMaterial("robot")))
{
	const auto& p = robot_.omnicam.camera;
	rays_.resize(static_cast<std::size_t>(p.image_width) * p.image_height);
	for (int v = 0; v < p.image_height; ++v)
		for (int u = 0; u < p.image_width; ++u) rays_[v * p.image_width + u] = pixelRay(u, v);

	std::mt19937 rng(robot_.robot.seed);
	std::normal_distribution<float> n(0.f, 1.f);
	noise_.resize(1u << 20);
	for (auto& x : noise_) x = n(rng);

	sun_h_ = {std::cos(world_.light.azimuth), std::sin(world_.light.azimuth)};
	buildShadowMap();
}

int OmniRenderer::binOf(double bearing) const
{
	const int b = static_cast<int>(std::lround((bearing + kPi) / (2 * kPi) * kBearingBins));
	return ((b % kBearingBins) + kBearingBins) % kBearingBins;
}

OmniRenderer::PixelRay OmniRenderer::pixelRay(double u, double v) const
{
	const auto [bearing, rho] = cam_.polarFromPixel({u, v});
	if (rho > rim_rho_ + 5) return {-1, 0, 3};
	if (rho > rim_rho_) return {-1, 0, 2};
	const double theta = cam_.thetaFromRho(rho);
	// The body: does the ray meet the body's top before the floor?
	const auto& r = robot_.robot;
	const auto& pose = robot_.omnicam.pose;
	const double h = robot_.omnicam.camera.h;
	if (theta < kHalfPi)
	{
		const double s = (h - r.height) * std::tan(theta);
		const double a = pose.yaw() + bearing;
		const double x = pose.x() + s * std::cos(a), y = pose.y() + s * std::sin(a);
		if (std::abs(x) <= r.length / 2 && std::abs(y) <= r.width / 2)
			return {binOf(bearing), static_cast<float>(theta), 1};
	}
	return {binOf(bearing), static_cast<float>(theta), 0};
}

void OmniRenderer::buildShadowMap()
{
	Vec2 lo = world_.lo, hi = world_.hi;
	for (const auto& s : world_.solids)
	{
		lo = {std::min(lo.x, s.footprint.lo().x), std::min(lo.y, s.footprint.lo().y)};
		hi = {std::max(hi.x, s.footprint.hi().x), std::max(hi.y, s.footprint.hi().y)};
	}
	lo = lo - Vec2{2, 2};
	hi = hi + Vec2{2, 2};
	shadow_lo_ = lo;
	const int w = static_cast<int>((hi.x - lo.x) / shadow_res_) + 1;
	const int h = static_cast<int>((hi.y - lo.y) / shadow_res_) + 1;
	shadow_ = cv::Mat(h, w, CV_8UC1, cv::Scalar(255));
	// A solid's shadow: its outline shifted away from the sun by z/tan(elevation)
	// for every z between z0 and z1, i.e. the hull of the two shifted outlines.
	const Vec2 away = sun_h_ * (-1.0 / std::tan(world_.light.elevation));
	for (const auto& s : world_.solids)
	{
		std::vector<cv::Point> pts, hull;
		for (double z : {s.z0, s.z1})
			for (const auto& q : s.footprint.outline())
			{
				const Vec2 p = q + away * z;
				pts.emplace_back(static_cast<int>((p.x - lo.x) / shadow_res_),
								 static_cast<int>((p.y - lo.y) / shadow_res_));
			}
		cv::convexHull(pts, hull);
		cv::fillConvexPoly(shadow_, hull, cv::Scalar(0));
	}
	cv::GaussianBlur(shadow_, shadow_, cv::Size(5, 5), 1.2);  // soft penumbra
	buildOcclusionMap();
}

void OmniRenderer::buildOcclusionMap()
{
	const auto& L = world_.light;
	if (L.occlusion <= 0) return;
	// Solids standing on the floor, rasterised; the distance from each floor
	// cell to the nearest one darkens it by occlusion * exp(-distance / radius).
	cv::Mat free(shadow_.size(), CV_8UC1, cv::Scalar(255));
	for (const auto& s : world_.solids)
	{
		if (s.z0 > 0.02) continue;
		std::vector<cv::Point> pts;
		for (const auto& q : s.footprint.outline())
			pts.emplace_back(static_cast<int>(std::lround((q.x - shadow_lo_.x) / shadow_res_)),
							 static_cast<int>(std::lround((q.y - shadow_lo_.y) / shadow_res_)));
		cv::fillPoly(free, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar(0));
	}
	cv::Mat dist;
	cv::distanceTransform(free, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
	occlusion_.create(dist.size(), CV_32F);
	for (int y = 0; y < dist.rows; ++y)
		for (int x = 0; x < dist.cols; ++x)
			occlusion_.at<float>(y, x) = static_cast<float>(footLight(L, dist.at<float>(y, x) * shadow_res_));
}

double OmniRenderer::floorLight(const Frame& f, const Vec2& p) const
{
	const int x = static_cast<int>((p.x - shadow_lo_.x) / shadow_res_);
	const int y = static_cast<int>((p.y - shadow_lo_.y) / shadow_res_);
	double lit = (x >= 0 && y >= 0 && x < shadow_.cols && y < shadow_.rows)
		? shadow_.at<std::uint8_t>(y, x) / 255.0
		: 1.0;
	const auto& L = world_.light;
	double occluded = 1.0;
	if (!occlusion_.empty())
	{
		// Bilinear: the occlusion fades over a few cells, which must not show as steps.
		const double fx = (p.x - shadow_lo_.x) / shadow_res_, fy = (p.y - shadow_lo_.y) / shadow_res_;
		const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
		if (x0 >= 0 && y0 >= 0 && x0 + 1 < occlusion_.cols && y0 + 1 < occlusion_.rows)
		{
			const double ax = fx - x0, ay = fy - y0;
			const auto at = [&](int y, int x) { return static_cast<double>(occlusion_.at<float>(y, x)); };
			occluded = (1 - ay) * ((1 - ax) * at(y0, x0) + ax * at(y0, x0 + 1)) +
				ay * ((1 - ax) * at(y0 + 1, x0) + ax * at(y0 + 1, x0 + 1));
		}
	}
	if (!f.own_shadow.empty()) lit = std::min(lit, ownShadow(f, p, occluded));
	return (L.ambient + L.diffuse * std::sin(L.elevation) * lit) * occluded;
}

OmniRenderer::Sample OmniRenderer::shadeFloor(const Frame& f, const Vec2& p) const
{
	auto c = shadeMaterial(world_.materials[world_.floor_material], tex_, p.x, p.y);
	const double k = floorLight(f, p);
	return {{c[0] * k, c[1] * k, c[2] * k}, kFloor};
}

void OmniRenderer::castOwnShadow(Frame& f) const
{
	if (!robot_.robot.own_shadow) return;
	const auto& r = robot_.robot;
	f.robot_cos = std::cos(f.robot.yaw), f.robot_sin = std::sin(f.robot.yaw);
	const double c = f.robot_cos, s = f.robot_sin;
	const double shift = r.height / std::tan(world_.light.elevation);  // the body's top, cast away from the sun
	std::vector<cv::Point2f> corners;
	for (double z : {0.0, shift})
		for (double qx : {-r.length / 2, r.length / 2})
			for (double qy : {-r.width / 2, r.width / 2})
				corners.emplace_back(static_cast<float>(f.robot.x + c * qx - s * qy - sun_h_.x * z),
									 static_cast<float>(f.robot.y + s * qx + c * qy - sun_h_.y * z));
	cv::convexHull(corners, f.own_shadow);
	f.own_reach = std::hypot(r.length, r.width) / 2 + shift + 6 * world_.light.occlusion_radius + kPenumbra;
}

double OmniRenderer::ownShadow(const Frame& f, const Vec2& p, double& occluded) const
{
	if (std::hypot(p.x - f.robot.x, p.y - f.robot.y) > f.own_reach) return 1.0;
	const auto& L = world_.light;
	// The body stands on the floor as a solid does: the same darkening at its foot.
	if (L.occlusion > 0)
	{
		const double c = f.robot_cos, s = f.robot_sin;
		const double dx = p.x - f.robot.x, dy = p.y - f.robot.y;
		const double qx = std::abs(c * dx + s * dy) - robot_.robot.length / 2;
		const double qy = std::abs(-s * dx + c * dy) - robot_.robot.width / 2;
		const double d = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
		occluded *= footLight(L, d);
	}
	// The sun's shadow, with about the soft edge of the solids' (5 cm).
	const double inside = cv::pointPolygonTest(f.own_shadow, cv::Point2f(static_cast<float>(p.x), static_cast<float>(p.y)), true);
	return std::clamp(0.5 - inside / kPenumbra, 0.0, 1.0);
}

OmniRenderer::Sample OmniRenderer::shadeRobot(double theta, double bearing) const
{
	auto c = shadeMaterial(world_.materials[robot_material_], tex_, theta * 3, bearing * 0.2);
	const double k = world_.light.ambient + 0.5 * world_.light.diffuse;
	return {{c[0] * k, c[1] * k, c[2] * k}, kRobot};
}

OmniRenderer::Sample OmniRenderer::trace(const Frame& f, int bin, double theta) const
{
	const double h = robot_.omnicam.camera.h;
	const double cot = std::cos(theta) / std::sin(theta);  // > 0 looking down
	const double s_floor = theta < kHalfPi ? h * std::tan(theta) : kMaxSight + 1;
	const double a = f.yaw + bin * 2 * kPi / kBearingBins - kPi;
	const Vec2 dir{std::cos(a), std::sin(a)};
	const auto& L = world_.light;
	for (const auto& sc : f.bins[bin])
	{
		const Crossing& c = sc.crossing;
		if (s_floor <= c.t_in) break;
		const Solid& s = world_.solids[sc.solid];
		const Material& m = world_.materials[s.material];
		const double z_in = h - c.t_in * cot;
		if (z_in >= s.z0 && z_in <= s.z1)
		{
			// A vertical face, lit by how much it faces the sun.
			const Vec2 p = f.origin + dir * c.t_in;
			const Vec2 tangent{-c.normal.y, c.normal.x};
			auto col = shadeMaterial(m, tex_, p.dot(tangent), z_in);
			const double k = L.ambient +
				L.diffuse * std::cos(L.elevation) * std::max(0.0, c.normal.dot(sun_h_));
			return {{col[0] * k, col[1] * k, col[2] * k}, kFirstSolid + 4 * sc.solid};
		}
		if (z_in > s.z1 && cot > 0)
		{
			const double s_top = (h - s.z1) / cot;
			if (s_top < c.t_out)
			{
				const Vec2 p = f.origin + dir * s_top;
				auto col = shadeMaterial(m, tex_, p.x, p.y);
				const double k = L.ambient + L.diffuse * std::sin(L.elevation);
				return {{col[0] * k, col[1] * k, col[2] * k}, kFirstSolid + 4 * sc.solid + 1};
			}
		}
		if (z_in < s.z0 && cot < 0)
		{
			const double s_bot = (h - s.z0) / cot;
			if (s_bot < c.t_out)
			{
				const Vec2 p = f.origin + dir * s_bot;
				auto col = shadeMaterial(m, tex_, p.x, p.y);
				const double k = 0.7 * L.ambient;
				return {{col[0] * k, col[1] * k, col[2] * k}, kFirstSolid + 4 * sc.solid + 2};
			}
		}
	}
	if (s_floor <= kMaxSight) return shadeFloor(f, f.origin + dir * s_floor);
	const auto& sky = world_.sky_rgb;
	return {{double(sky[2]), double(sky[1]), double(sky[0])}, kSky};
}

void OmniRenderer::castFrame(const Pose2& robot, Frame& f) const
{
	const auto& pose = robot_.omnicam.pose;
	f.yaw = robot.yaw + pose.yaw();
	f.origin = {robot.x + std::cos(robot.yaw) * pose.x() - std::sin(robot.yaw) * pose.y(),
				robot.y + std::sin(robot.yaw) * pose.x() + std::cos(robot.yaw) * pose.y()};
	f.robot = robot;
	castOwnShadow(f);
	f.bins.resize(kBearingBins);
	cv::parallel_for_(cv::Range(0, kBearingBins), [&](const cv::Range& r) {
		for (int b = r.start; b < r.end; ++b)
		{
			const double a = f.yaw + b * 2 * kPi / kBearingBins - kPi;
			world_.castRay(f.origin, {std::cos(a), std::sin(a)}, kMaxSight, f.bins[b]);
		}
	});
}

OmniRenderer::Sample OmniRenderer::shade(const Frame& f, const PixelRay& pr, double u, double v) const
{
	switch (pr.kind)
	{
		case 3: return {{0, 0, 0}, kOutside};
		case 2: return {{38, 38, 42}, kRim};
		case 1: return shadeRobot(pr.theta, cam_.polarFromPixel({u, v}).first);
		default: return trace(f, pr.bin, pr.theta);
	}
}

void OmniRenderer::shadePixels(const Frame& f, cv::Mat& img, cv::Mat& surf) const
{
	const int width = img.cols;
	cv::parallel_for_(cv::Range(0, img.rows), [&](const cv::Range& r) {
		for (int v = r.start; v < r.end; ++v)
		{
			auto* px = img.ptr<cv::Vec3b>(v);
			auto* id = surf.ptr<std::int32_t>(v);
			for (int u = 0; u < width; ++u)
			{
				const Sample s = shade(f, rays_[v * width + u], u, v);
				px[u] = {clamp8(s.bgr[0]), clamp8(s.bgr[1]), clamp8(s.bgr[2])};
				id[u] = s.surface;
			}
		}
	});
}

void OmniRenderer::antialias(const Frame& f, cv::Mat& img, const cv::Mat& ids) const
{
	cv::parallel_for_(cv::Range(1, img.rows - 1), [&](const cv::Range& r) {
		for (int v = r.start; v < r.end; ++v)
			for (int u = 1; u < img.cols - 1; ++u)
			{
				const int id = ids.at<std::int32_t>(v, u);
				if (id == kOutside) continue;
				if (id == ids.at<std::int32_t>(v, u + 1) && id == ids.at<std::int32_t>(v + 1, u) &&
					id == ids.at<std::int32_t>(v, u - 1) && id == ids.at<std::int32_t>(v - 1, u))
					continue;
				double acc[3] = {0, 0, 0};
				for (double du : {-0.25, 0.25})
					for (double dv : {-0.25, 0.25})
					{
						const Sample s = shade(f, pixelRay(u + du, v + dv), u + du, v + dv);
						for (int c = 0; c < 3; ++c) acc[c] += 0.25 * s.bgr[c];
					}
				img.at<cv::Vec3b>(v, u) = {clamp8(acc[0]), clamp8(acc[1]), clamp8(acc[2])};
			}
	});
}

void OmniRenderer::addNoise(cv::Mat& img, std::uint64_t seed) const
{
	const double sigma = robot_.omnicam.noise_sigma;
	const std::size_t mask = noise_.size() - 1;
	const std::size_t offset = std::mt19937_64(seed)() & mask;
	cv::parallel_for_(cv::Range(0, img.rows), [&](const cv::Range& r) {
		for (int v = r.start; v < r.end; ++v)
		{
			auto* px = img.ptr<std::uint8_t>(v);
			std::size_t k = (offset + static_cast<std::size_t>(v) * 7919u * 3u) & mask;
			for (int i = 0; i < 3 * img.cols; ++i, k = (k + 1) & mask) px[i] = clamp8(px[i] + sigma * noise_[k]);
		}
	});
}

cv::Mat OmniRenderer::render(const Pose2& robot, std::uint64_t noise_seed, int frame) const
{
	const auto& p = robot_.omnicam.camera;
	Frame f;
	castFrame(robot, f);
	cv::Mat img(p.image_height, p.image_width, CV_8UC3);
	cv::Mat surf(p.image_height, p.image_width, CV_32SC1);
	shadePixels(f, img, surf);
	if (robot_.omnicam.antialias) antialias(f, img, surf);
	// The optics (vignetting, blur) and the exposure of this frame, the sensor's
	// noise and a single-chip sensor's colour filter, demosaiced.
	const auto& fx = robot_.omnicam.effects;
	applyOptics(img, fx, p.cx + robot_.omnicam.centre_offset_u, p.cy + robot_.omnicam.centre_offset_v, rim_rho_);
	applyExposure(img, fx, frame);
	if (robot_.omnicam.noise_sigma > 0) addNoise(img, noise_seed);
	if (fx.bayer) applyBayer(img);
	return img;
}

}  // namespace omnirange::sim
