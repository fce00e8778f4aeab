#include "omnirange/core/PolarScanner.h"

#include "omnirange/core/BrightnessStep.h"
#include "omnirange/config/OptionsTable.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace omnirange
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
// [px] The shortest stretch of scanline that ranges from min_range to max_range: a real rig has a hundred or more.
constexpr double kMinScanRing = 5.0;
/** Pixels classified per call to the classifier: short, so the search's
 * early decisions still skip most of a scanline. */
constexpr int kClassifyRun = 16;
}  // namespace

std::string toString(RayStatus s)
{
	switch (s)
	{
		case RayStatus::Hit: return "hit";
		case RayStatus::NoHit: return "no_hit";
		case RayStatus::TooClose: return "too_close";
		case RayStatus::Outlier: return "outlier";
		case RayStatus::Unsure: return "unsure";
	}
	throw std::logic_error("unknown RayStatus");
}

std::string toString(BoundaryModel m)
{
	switch (m)
	{
		case BoundaryModel::Midpoint: return "midpoint";
		case BoundaryModel::Subpixel: return "subpixel";
	}
	throw std::logic_error("unknown BoundaryModel");
}

BoundaryModel boundaryModelFromString(const std::string& name)
{
	if (name == "midpoint") return BoundaryModel::Midpoint;
	if (name == "subpixel") return BoundaryModel::Subpixel;
	throw std::invalid_argument("boundary_model must be 'midpoint' or 'subpixel', not '" + name + "'");
}

std::string toString(HitSearch::Status s)
{
	switch (s)
	{
		case HitSearch::Status::Hit: return "hit";
		case HitSearch::Status::NoCandidate: return "no_candidate";
		case HitSearch::Status::Unconfirmed: return "unconfirmed";
	}
	throw std::logic_error("unknown HitSearch::Status");
}

namespace
{
/** The keys of the brightness step and the edge bias: what ends a ray
 * besides colour, and a correction of where its end is put. */
void addStepKeys(OptionsTable<PolarScannerParams>& t)
{
	using P = PolarScannerParams;
	t.add("step_threshold", "-",
			 "a brightness step along a scanline, before the colour's hit, ends the ray when the mean brightness "
			 "(B + G + R) of step_window pixels either side differs by a ratio of at least e^step_threshold "
			 "(0: off; omnirange-train --learn tries it)",
			 [](P& p) -> auto& { return p.step_threshold; })
		.within(Range::closed(0, 5))
		.add("step_window", "px", "pixels averaged on each side of a brightness step",
			 [](P& p) -> auto& { return p.step_window; })
		.within(Range::closed(1, 100))
		.addEnum("step_sign",
				 "which brightness steps end a ray: either; brighter (what lies beyond is brighter: shadows on the "
				 "floor never count); darker (omnirange-train --learn tries all three)",
				 [](P& p) -> auto& { return p.step_sign; }, stepSignFromString,
				 {StepSign::Either, StepSign::Brighter, StepSign::Darker})
		.add("base_shadow", "m",
			 "a non-free run from a scanline's first pixel that ends within this distance of it, with N free "
			 "pixels behind it (runs of at most K non-free negated), is the robot's own shadow or body and is "
			 "passed (0: the ray is too close)",
			 [](P& p) -> auto& { return p.base_shadow; })
		.within(Range::atLeast(0))
		.add("edge_bias", "m",
			 "added to a hit's range, one value per bin of the hit's contrast (the natural log of its pixel's "
			 "brightness over the floor's 4 to 8 pixels before it; bins of 0.05 from -0.5, at most 20 values, each at "
			 "its bin's centre and linear between centres): "
			 "the darkened floor before an obstacle's foot, learned against the laser by omnirange-train --learn "
			 "(docs/method.md); empty: none",
			 [](P& p) -> auto& { return p.edge_bias; })
		.within(Range::closed(-kMaxEdgeBias, kMaxEdgeBias))
		.add("sure_run", "px",
			 "doubtful pixels in a row (colours outside the floor's sure_floor_share; runs of at most K sure ones "
			 "negated) that end the stretch a ray claims free: the ray is unsure, free only up to where they start "
			 "(0: every ray hit or free, the paper's; omnirange-train --learn chooses it)",
			 [](P& p) -> auto& { return p.sure_run; })
		.within(Range::closed(0, 10000));
}
}  // namespace

const OptionsTable<PolarScannerParams>& PolarScannerParams::table()
{
	using P = PolarScannerParams;
	static const auto t = [] {
		OptionsTable<P> t;
		t.add("scanlines", "-", "S, the number of scanlines and of rays in the scan", [](P& p) -> auto& { return p.scanlines; })
		.within(Range::closed(2, 36000))
		.add("base_radius", "px", "radius of the robot's own base at the image centre; scanlines start there",
			 [](P& p) -> auto& { return p.base_radius; })
		.within(Range::atLeast(0))
		.add("min_range", "m", "hits closer than this (or on a scanline's first pixel) report min_range",
			 [](P& p) -> auto& { return p.min_range; })
		.within(Range::atLeast(0))
		.add("max_range", "m", "no hit up to this range reports max_range, flagged invalid",
			 [](P& p) -> auto& { return p.max_range; })
		.within(Range::openLow(0, 1000))
		.add("boundary_offset", "px",
			 "where the floor's end is put, outwards from the midpoint between the last free and the first "
			 "non-free pixel; 0 is exact for hard edges, blurred edges want about +0.5 (omnirange-calibrate "
			 "suggests a value)",
			 [](P& p) -> auto& { return p.boundary_offset; })
		.within(Range::closed(-1, 1))
		.addEnum("boundary_model",
				 "midpoint: halfway between the last free and the first non-free pixel (the paper's); subpixel: "
				 "the floor fractions of the mixed pixels around it, summed (docs/method.md)",
				 [](P& p) -> auto& { return p.boundary_model; }, boundaryModelFromString,
				 {BoundaryModel::Midpoint, BoundaryModel::Subpixel})
		.add("boundary_reach", "px",
			 "with boundary_model = subpixel, how far past the centre of the first non-free pixel the edge may "
			 "be placed; a floor darkened at its edge leaves its last pixels non-free (1: the limit "
			 "before commit e13c8b5)",
			 [](P& p) -> auto& { return p.boundary_reach; })
		.within(Range::closed(0, kMaxBoundaryReach))
		.add("N", "px", "false-positive filter: pixels behind a candidate that must be non-free",
			 [](P& p) -> auto& { return p.filter.N; })
		.within(Range::closed(1, 10000))
		.add("K", "px", "false-negative filter: longest free run negated inside that window",
			 [](P& p) -> auto& { return p.filter.K; })
		.within(Range::closed(0, 10000));
		addStepKeys(t);
		return t;
	}();
	return t;
}

void PolarScannerParams::validate(const OmniCameraModel& cam) const
{
	table().requireRanges(*this);
	require(base_shadow <= max_range, "base_shadow must be within [0, max_range] m");
	require(edge_bias.size() <= static_cast<std::size_t>(kEdgeContrastBins), "edge_bias has at most 20 values");
	require(max_range > min_range, "max_range must be > min_range");
	require(base_radius < cam.rhoFromDistance(max_range),
			"base_radius must be smaller than the max-range radius (" +
				std::to_string(cam.rhoFromDistance(max_range)) + " px)");
	// A viewpoint's height far off (h = 0.001 m) puts every range in a thin ring at the horizon: all "too close".
	const double inner = std::max(base_radius, cam.rhoFromDistance(min_range)), ring = cam.rhoFromDistance(max_range) - inner;
	require(ring >= kMinScanRing, "from min_range (or base_radius) to max_range the scanlines are " + std::to_string(ring) +
									  " px long, under " + std::to_string(static_cast<int>(kMinScanRing)) +
									  ": are h (the viewpoint's height above the floor, m) and the mirror's keys right?");
}

double scanAperture(int S) { return 2.0 * kPi * (S - 1) / S; }

double scanlineBearing(int i, int S)
{
	return -0.5 * scanAperture(S) + 2.0 * kPi * i / S;
}

PolarScanner::PolarScanner(const OmniCameraModel& cam, const PolarScannerParams& p)
	: p_(p), width_(cam.params().image_width), height_(cam.params().image_height), camera_(cam)
{
	p_.validate(cam);
	max_rho_ = cam.rhoFromDistance(p_.max_range);
	const int window = p_.filter.N + p_.filter.K + 1;

	lines_.reserve(p_.scanlines);
	for (int s = 0; s < p_.scanlines; ++s)
	{
		Scanline line{scanlineBearing(s, p_.scanlines), pixel_.size(), 0, -1, -1};
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
					"scanner: the scan circle (max_range " + formatDouble(p_.max_range) + " m = " +
					formatDouble(std::round(max_rho_ * 10) / 10) + " px, plus the N+K+1 = " + std::to_string(window) +
					" px filter window) does not fit in the " + std::to_string(width_) + "x" + std::to_string(height_) +
					" image around (" + formatDouble(cam.params().cx) + ", " + formatDouble(cam.params().cy) + ")");
			const long idx = v * width_ + u;
			if (idx == prev) continue;
			prev = idx;
			const double rho = cam.rhoOfPixel({static_cast<double>(u), static_cast<double>(v)});
			const double mid = line.count == 0 ? rho : 0.5 * (prev_rho + rho) + p_.boundary_offset;
			prev_rho = rho;
			const double range = cam.distanceFromRho(mid);
			pixel_.push_back(static_cast<std::int32_t>(idx));
			mid_rho_.push_back(static_cast<float>(mid));
			rho_.push_back(static_cast<float>(rho));
			mid_range_.push_back(static_cast<float>(range));
			if (past_max < 0 && range > p_.max_range) past_max = line.count;
			if (line.first_in_range < 0 && range >= p_.min_range) line.first_in_range = line.count;
			++line.count;
		}
		line.last_candidate = past_max - 1;
		longest_line_ = std::max(longest_line_, line.count);
		scan_radius_ = std::max(scan_radius_, prev_rho);
		lines_.push_back(line);
	}
}

PixelBox PolarScanner::pixelsRead() const
{
	PixelBox box;
	box.add(pixel_, width_);
	return box;
}

void PolarScanner::checkImage(const cv::Mat& image) const
{
	if (image.type() != CV_8UC3) throw std::invalid_argument("scanner: the image must be 8-bit, 3-channel BGR");
	if (image.cols != width_ || image.rows != height_)
		throw std::invalid_argument("scanner: the image is " + std::to_string(image.cols) + "x" +
									std::to_string(image.rows) + " but the camera is " + std::to_string(width_) +
									"x" + std::to_string(height_));
}

std::vector<Ray> PolarScanner::scan(const cv::Mat& image, const PixelClassifier& classifier) const
{
	checkImage(image);
	const cv::Mat bgr = image.isContinuous() ? image : image.clone();
	const std::uint8_t* data = bgr.ptr<std::uint8_t>();
	std::vector<std::uint8_t> free(longest_line_);

	std::vector<Ray> rays(lines_.size());
	for (std::size_t s = 0; s < lines_.size(); ++s)
	{
		const Scanline& line = lines_[s];
		const std::int32_t* pix = pixel_.data() + line.first;
		int classified = 0;  // pixels [0, classified) of this scanline are in `free`
		const auto class_of = [&](int k) {
			while (k >= classified)
			{
				const int n = std::min(kClassifyRun, line.count - classified);
				classifier.classify(data, pix + classified, n, free.data() + classified);
				classified += n;
			}
			return free[k];
		};
		const auto is_free = [&](int k) { return class_of(k) != kNotFree; };
		Ray& ray = rays[s];
		ray.bearing = line.bearing;
		searchColour(line, is_free, ray);
		const int hit = endOfFloor(line, data, pix, ray);
		const int end = hit < 0 ? line.last_candidate + 1 : hit;  // the stretch the ray claims free
		if (end > 0) class_of(end - 1);  // classified up to there (the search has read them)
		findDoubt(line, free.data(), end, ray);
		if (hit < 0)
		{
			ray.status = RayStatus::NoHit;
			ray.range = static_cast<float>(p_.max_range);
			continue;
		}
		placeHit(line, data, pix, hit, ray);
	}
	return rays;
}

template <class IsFree>
void PolarScanner::searchColour(const Scanline& line, IsFree& is_free, Ray& ray) const
{
	ray.search = findHit(is_free, line.count, line.last_candidate, p_.filter);
	if (ray.search.status != HitSearch::Status::Hit || ray.search.index != 0 || p_.base_shadow <= 0) return;
	// An obstacle cannot stand inside the robot's base, and one just outside
	// it hides the floor up its face: floor that comes back soon after a
	// non-free run at the base is floor, darkened by the robot or its body.
	const int resume = floorPastBase(line, is_free);
	if (resume <= 0) return;
	auto from = [&](int k) { return is_free(resume + k); };
	ray.search = findHit(from, line.count - resume, line.last_candidate - resume, p_.filter);
	if (ray.search.index >= 0) ray.search.index += resume;
	if (ray.search.last_rejected >= 0) ray.search.last_rejected += resume;
	ray.past_base = resume;
}

int PolarScanner::endOfFloor(const Scanline& line, const std::uint8_t* bgr, const std::int32_t* pix, Ray& ray) const
{
	const bool colour_hit = ray.search.status == HitSearch::Status::Hit;
	const int hit = colour_hit ? ray.search.index : -1;
	if (p_.step_threshold <= 0 || line.first_in_range < 0) return hit;
	// A face the colour model sees through still shows its foot. The search
	// may climb to the colour's hit: a step that peaks there is the colour's
	// own edge, and the colour places it. A shadow passed at the base has an
	// edge too: the search starts past it.
	const int to = colour_hit ? hit : line.last_candidate;
	const int step = findBrightnessStep(bgr, pix, line.count, std::max(line.first_in_range, ray.past_base), to,
										p_.step_threshold, p_.step_window, p_.step_sign);
	if (step < 0 || (colour_hit && step >= hit)) return hit;
	ray.by_step = true;
	return step;
}

void PolarScanner::placeHit(const Scanline& line, const std::uint8_t* bgr, const std::int32_t* pix, int hit, Ray& ray) const
{
	float range = mid_range_[line.first + hit];
	ray.hit_rho = mid_rho_[line.first + hit];
	if (p_.boundary_model == BoundaryModel::Subpixel && hit > 0)
	{
		ray.hit_rho = static_cast<float>(rhoAt(line, refineBoundary(bgr, pix, line.count, hit, p_.boundary_reach)) + p_.boundary_offset);
		range = static_cast<float>(camera_.distanceFromRho(ray.hit_rho));
	}
	ray.edge_contrast = edgeContrast(bgr, pix, hit);
	if (const double bias = edgeBiasAt(p_.edge_bias, ray.edge_contrast); bias != 0 && range + bias > 0)
	{
		range = static_cast<float>(std::min(range + bias, p_.max_range));
		ray.hit_rho = static_cast<float>(camera_.rhoFromDistance(range));
	}
	// The first pixel is at the base: the obstacle may start inside it.
	const bool too_close = hit == 0 || range < p_.min_range;
	ray.status = too_close ? RayStatus::TooClose : RayStatus::Hit;
	ray.range = too_close ? static_cast<float>(p_.min_range) : range;
}

void PolarScanner::findDoubt(const Scanline& line, const std::uint8_t* classes, int end, Ray& ray) const
{
	// The paper's N/K search again, on sure floor against the rest and only
	// inside the free stretch: a few doubtful pixels at the blurred edge of
	// the floor's end never reach sure_run. It starts at the stretch's first
	// pixel that is not sure floor (the search's first candidate).
	const int from = ray.past_base;
	if (p_.sure_run <= 0 || end <= from) return;
	const std::uint8_t* c = classes + from;
	const int n = end - from;
	// A confirmed run holds at least 1 + sure_run / (K + 1) pixels not sure floor (each negated run of at
	// most K sure ones is followed by one that is not): most stretches have fewer.
	if (n - std::count(c, c + n, kFree) < 1 + p_.sure_run / (p_.filter.K + 1)) return;
	const int first = static_cast<int>(std::find_if(c, c + n, [](std::uint8_t v) { return v != kFree; }) - c);
	const auto sure = [&](int k) { return c[first + k] == kFree; };
	const HitSearch doubt = findHit(sure, n - first, n - first - 1, HitFilterParams{p_.sure_run, p_.filter.K});
	if (doubt.status != HitSearch::Status::Hit) return;
	ray.sure_end = from + first + doubt.index;
	ray.sure_range = mid_range_[line.first + ray.sure_end];
}

template <class IsFree>
int PolarScanner::floorPastBase(const Scanline& line, IsFree& is_free) const
{
	// The N/K filter with free and non-free swapped finds where the floor
	// resumes: N free pixels counting the first (the filter counts N behind
	// its candidate), starting within base_shadow of the scanline's first pixel.
	const float* range = mid_range_.data() + line.first;
	const int last = static_cast<int>(std::upper_bound(range, range + line.count, range[0] + p_.base_shadow) - range) - 1;
	HitFilterParams window = p_.filter;
	window.N -= 1;
	const auto not_free = [&](int k) { return !is_free(k); };
	const HitSearch floor = findHit(not_free, line.count, last, window);
	return floor.status == HitSearch::Status::Hit ? floor.index : 0;
}

double PolarScanner::rhoAt(const Scanline& line, double k) const
{
	// Pixel centres are not evenly spaced along a digital ray: interpolate theirs.
	const int k0 = std::clamp(static_cast<int>(std::floor(k)), 0, line.count - 2);
	const double f = k - k0;
	const float* r = rho_.data() + line.first;
	return r[k0] + f * (r[k0 + 1] - r[k0]);
}

std::vector<std::int32_t> PolarScanner::scanlinePixels(int s) const
{
	const Scanline& line = lines_.at(s);
	return {pixel_.begin() + line.first, pixel_.begin() + line.first + line.count};
}

}  // namespace omnirange
