#include "omnirange/PolarScanner.h"

#include "omnirange/Config.h"

#include <opencv2/core.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace omnirange
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

void validate(const PolarScannerParams& p, const OmniCameraModel& cam)
{
	const auto need = [](bool ok, const std::string& what) {
		requireParam(ok, "scanner", what);
	};
	need(p.scanlines >= 2, "scanlines must be >= 2");
	need(p.filter.N >= 1, "N (false-positive filter) must be >= 1");
	need(p.filter.K >= 0, "K (false-negative filter) must be >= 0");
	need(std::isfinite(p.base_radius) && p.base_radius >= 0,
		 "base_radius must be >= 0 px");
	need(std::isfinite(p.min_range) && p.min_range >= 0, "min_range must be >= 0 m");
	need(std::isfinite(p.max_range) && p.max_range > p.min_range,
		 "max_range must be finite and > min_range");
	need(std::isfinite(p.boundary_offset) && std::abs(p.boundary_offset) <= 1.0,
		 "boundary_offset must be within [-1, 1] px");
	need(p.base_radius < cam.rhoFromDistance(p.max_range),
		 "base_radius must be smaller than the max-range radius (" +
			 std::to_string(cam.rhoFromDistance(p.max_range)) + " px)");
}
}  // namespace

double scanAperture(int S) { return 2.0 * kPi * (S - 1) / S; }

double scanlineBearing(int i, int S)
{
	return -0.5 * scanAperture(S) + 2.0 * kPi * i / S;
}

PolarScanner::PolarScanner(const OmniCameraModel& cam, const PolarScannerParams& p)
	: p_(p), width_(cam.params().image_width), height_(cam.params().image_height)
{
	validate(p_, cam);
	max_rho_ = cam.rhoFromDistance(p_.max_range);
	const int window = p_.filter.N + p_.filter.K + 1;

	lines_.reserve(p_.scanlines);
	for (int s = 0; s < p_.scanlines; ++s)
	{
		Scanline line{scanlineBearing(s, p_.scanlines), pixel_.size(), 0, -1};
		int past_max = -1;  // first pixel whose range exceeds max range
		long prev = -1;
		double prev_rho = 0;
		// Step 1 px along the ray; rounding gives an 8-connected digital ray,
		// from which repeated pixels are dropped.
		for (double r = p_.base_radius; past_max < 0 || line.count < past_max + window;
			 r += 1.0)
		{
			const Pixel f = cam.pixelFromPolar(line.bearing, r);
			const long u = std::lround(f.u), v = std::lround(f.v);
			if (u < 0 || v < 0 || u >= width_ || v >= height_)
				throw std::invalid_argument(
					"scanner: the scan circle (max_range " +
					std::to_string(p_.max_range) + " m = " + std::to_string(max_rho_) +
					" px, plus the N+K+1 = " + std::to_string(window) +
					" px filter window) does not fit in the " + std::to_string(width_) +
					"x" + std::to_string(height_) + " image around (" +
					std::to_string(cam.params().cx) + ", " +
					std::to_string(cam.params().cy) + ")");
			const long idx = v * width_ + u;
			if (idx == prev) continue;
			prev = idx;
			const double rho =
				std::hypot(u - cam.params().cx, v - cam.params().cy);
			const double mid = line.count == 0 ? rho : 0.5 * (prev_rho + rho) + p_.boundary_offset;
			prev_rho = rho;
			const double range = cam.distanceFromRho(mid);
			pixel_.push_back(static_cast<std::int32_t>(idx));
			mid_rho_.push_back(static_cast<float>(mid));
			mid_range_.push_back(static_cast<float>(range));
			if (past_max < 0 && range > p_.max_range) past_max = line.count;
			++line.count;
		}
		line.last_candidate = past_max - 1;
		scan_radius_ = std::max(scan_radius_, prev_rho);
		lines_.push_back(line);
	}
}

std::vector<Ray> PolarScanner::scan(
	const cv::Mat& image, const FreeSpaceClassifier& classifier) const
{
	if (image.type() != CV_8UC3)
		throw std::invalid_argument("scanner: the image must be 8-bit, 3-channel BGR");
	if (image.cols != width_ || image.rows != height_)
		throw std::invalid_argument(
			"scanner: the image is " + std::to_string(image.cols) + "x" +
			std::to_string(image.rows) + " but the camera is " +
			std::to_string(width_) + "x" + std::to_string(height_));
	const cv::Mat bgr = image.isContinuous() ? image : image.clone();
	const std::uint8_t* data = bgr.ptr<std::uint8_t>();

	std::vector<Ray> rays(lines_.size());
	for (std::size_t s = 0; s < lines_.size(); ++s)
	{
		const Scanline& line = lines_[s];
		const std::int32_t* pix = pixel_.data() + line.first;
		const auto is_free = [&](int k) {
			return classifier.isFree(data + 3 * static_cast<std::size_t>(pix[k]));
		};
		const HitSearch hit = findHit(is_free, line.count, line.last_candidate, p_.filter);

		Ray& ray = rays[s];
		ray.bearing = line.bearing;
		if (hit.status != HitSearch::Status::Hit)
		{
			ray.status = RayStatus::NoHit;
			ray.range = static_cast<float>(p_.max_range);
			continue;
		}
		const float range = mid_range_[line.first + hit.index];
		ray.hit_rho = mid_rho_[line.first + hit.index];
		// The first pixel is at the base: the obstacle may start inside it.
		if (hit.index == 0 || range < p_.min_range)
		{
			ray.status = RayStatus::TooClose;
			ray.range = static_cast<float>(p_.min_range);
			continue;
		}
		ray.status = RayStatus::Hit;
		ray.range = range;
	}
	return rays;
}

std::vector<std::int32_t> PolarScanner::scanlinePixels(int s) const
{
	const Scanline& line = lines_.at(s);
	return {pixel_.begin() + line.first, pixel_.begin() + line.first + line.count};
}

}  // namespace omnirange
