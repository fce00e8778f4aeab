#include "omnirange_tuner/Overlays.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace omnirange::tuner
{
namespace
{
cv::Point at(const Pixel& p) { return {static_cast<int>(std::lround(p.u)), static_cast<int>(std::lround(p.v))}; }

cv::Scalar statusColour(RayStatus s)
{
	switch (s)
	{
		case RayStatus::Hit: return colour::kHit;
		case RayStatus::NoHit: return colour::kNoHit;
		case RayStatus::TooClose: return colour::kTooClose;
		case RayStatus::Outlier: return colour::kOutlier;
		case RayStatus::Unsure: return colour::kUnsure;
	}
	return colour::kHit;
}

/** Where each ray ends in the image [px from the centre]. */
double endRho(const Ray& r, const Rangefinder& rf)
{
	switch (r.status)
	{
		case RayStatus::Hit:
		case RayStatus::Outlier: return r.hit_rho;
		case RayStatus::NoHit: return rf.scanner().maxRangeRho();
		case RayStatus::TooClose: return rf.params().scanner.base_radius;
		case RayStatus::Unsure: return rf.camera().rhoFromDistance(r.range);
	}
	return r.hit_rho;
}

void tintFreePixels(cv::Mat& img, const Rangefinder& rf)
{
	const OmniCameraModel& cam = rf.camera();
	const double inner = rf.params().scanner.base_radius, outer = rf.scanner().maxRangeRho();
	const double cx = cam.params().cx, cy = cam.params().cy;
	const int v0 = std::max(0, static_cast<int>(cy - outer)), v1 = std::min(img.rows - 1, static_cast<int>(cy + outer));
	const int u0 = std::max(0, static_cast<int>(cx - outer)), u1 = std::min(img.cols - 1, static_cast<int>(cx + outer));
	const cv::Scalar& tint = colour::kFree;
	// Through the classifier the scan used (exposure compensation included),
	// a row at a time; a row is tinted only after it was classified.
	rf.withClassifierFor(img, nullptr, [&](const PixelClassifier& classifier) {
		std::vector<std::int32_t> pixels;
		std::vector<std::uint8_t> free;
		for (int v = v0; v <= v1; ++v)
		{
			pixels.clear();
			for (int u = u0; u <= u1; ++u)
			{
				const double du = u - cx, dv = v - cy, r2 = du * du + dv * dv;
				if (r2 >= inner * inner && r2 <= outer * outer) pixels.push_back(v * img.cols + u);
			}
			free.resize(pixels.size());
			classifier.classify(img.data, pixels.data(), static_cast<int>(pixels.size()), free.data());
			for (std::size_t k = 0; k < pixels.size(); ++k)
			{
				const int u = pixels[k] % img.cols;
				if (!free[k] || (u + v) / 3 % 2 != 0) continue;  // stripes 3 px wide
				std::uint8_t* px = img.data + 3 * static_cast<std::size_t>(pixels[k]);
				for (int c = 0; c < 3; ++c) px[c] = static_cast<std::uint8_t>((3 * px[c] + 2 * static_cast<int>(tint[c])) / 5);
			}
		}
	});
}
/** A key to the colours the overlays `o` show, top left, where an omnicam
 * image has only the corner outside its mirror. */
void drawLegend(cv::Mat& img, const OverlayOptions& o)
{
	std::vector<std::pair<std::string, cv::Scalar>> items;
	if (o.rays)
		items.insert(items.end(), {{"hit", colour::kHit}, {"no hit (max range)", colour::kNoHit},
								   {"too close (base)", colour::kTooClose}, {"outlier", colour::kOutlier},
								   {"unsure (free to here)", colour::kUnsure}});
	if (o.candidates) items.push_back({"K-rejected", colour::kRejectedCandidate});
	if (o.laser) items.push_back({"laser", colour::kLaser});
	if (o.truth) items.push_back({"truth", colour::kTruth});
	if (o.classification) items.push_back({"free (striped)", colour::kFree});
	if (o.camera) items.push_back({"max range circle", colour::kMaxRange});
	const double scale = std::max(0.4, img.cols / 2048.0);
	const int line = static_cast<int>(std::lround(44 * scale)), box = line * 2 / 3;
	if (items.empty()) return;
	cv::rectangle(img, cv::Rect(0, 0, static_cast<int>(380 * scale), line * static_cast<int>(items.size()) + line / 2),
				  colour::kLegend, cv::FILLED);
	for (std::size_t i = 0; i < items.size(); ++i)
	{
		const int y = line / 4 + line * static_cast<int>(i);
		cv::rectangle(img, cv::Rect(line / 4, y, box, box), items[i].second, cv::FILLED);
		cv::putText(img, items[i].first, {line / 4 + box + line / 3, y + box}, cv::FONT_HERSHEY_SIMPLEX, 1.2 * scale,
					cv::Scalar(235, 235, 235), std::max(1, static_cast<int>(std::lround(2 * scale))), cv::LINE_AA);
	}
}
}  // namespace

cv::Mat drawOmniOverlay(const FrameScan& s, const Rangefinder& rf, const OverlayOptions& o)
{
	cv::Mat img = s.bgr.clone();
	const OmniCameraModel& cam = rf.camera();
	const double base = rf.params().scanner.base_radius, outer = rf.scanner().maxRangeRho();
	if (o.classification) tintFreePixels(img, rf);
	const int S = static_cast<int>(s.scan.rays.size());
	if (o.scanlines)
		for (int i = 0; i < S; i += std::max(1, o.scanline_step))
			cv::line(img, at(cam.pixelFromPolar(s.scan.rays[i].bearing, base)),
					 at(cam.pixelFromPolar(s.scan.rays[i].bearing, outer)), cv::Scalar(128, 128, 128), 1, cv::LINE_AA);
	if (o.camera)
	{
		const cv::Point c(static_cast<int>(std::lround(cam.params().cx)), static_cast<int>(std::lround(cam.params().cy)));
		cv::circle(img, c, static_cast<int>(std::lround(base)), colour::kCircle, 1, cv::LINE_AA);
		cv::circle(img, c, static_cast<int>(std::lround(outer)), colour::kMaxRange, 2, cv::LINE_AA);
		cv::circle(img, c, static_cast<int>(std::lround(cam.horizonRho())), colour::kCircle, 1, cv::LINE_AA);
		// White edged in black: seen on a light floor and a dark one alike.
		cv::arrowedLine(img, c, at(cam.pixelFromPolar(0.0, outer)), cv::Scalar(0, 0, 0), 5, cv::LINE_AA, 0, 0.05);
		cv::arrowedLine(img, c, at(cam.pixelFromPolar(0.0, outer)), colour::kForward, 2, cv::LINE_AA, 0, 0.05);
	}
	if (o.laser)
		for (const auto& p : s.laser_pairs)
			if (p.status != PairStatus::LaserBeyondMaxRange)
				cv::circle(img, at(cam.pixelFromPolar(p.bearing, cam.rhoFromDistance(p.laser))), 1, colour::kLaser, -1);
	if (o.truth)
		for (const auto& p : s.truth_pairs)
			if (p.status != PairStatus::LaserBeyondMaxRange)
				cv::circle(img, at(cam.pixelFromPolar(p.bearing, cam.rhoFromDistance(p.laser))), 1, colour::kTruth, -1);
	for (const Ray& r : s.scan.rays)
	{
		if (o.candidates && r.search.last_rejected >= 0)
			cv::circle(img, at(cam.pixelFromPolar(r.bearing, base + r.search.last_rejected)), 1,
					   colour::kRejectedCandidate, -1);
		if (!o.rays) continue;
		const cv::Point end = at(cam.pixelFromPolar(r.bearing, endRho(r, rf)));
		cv::circle(img, end, 2, statusColour(r.status), -1);
		if (r.by_step) cv::circle(img, end, 4, colour::kByStep, 1);  // the brightness step ended it, not colour
	}
	if (o.legend) drawLegend(img, o);
	return img;
}

cv::Mat drawScanPlot(const FrameScan& s, const RangefinderParams& p, int size)
{
	cv::Mat img(size, size, CV_8UC3, cv::Scalar(30, 30, 30));
	const double c = size / 2.0, scale = (size / 2.0 - 4) / (p.scanner.max_range + 0.3);
	const auto to = [&](double bearing, double r) {
		return cv::Point(static_cast<int>(std::lround(c - r * std::sin(bearing) * scale)),
						 static_cast<int>(std::lround(c - r * std::cos(bearing) * scale)));
	};
	for (int m = 1; m <= static_cast<int>(p.scanner.max_range); ++m)
		cv::circle(img, {int(c), int(c)}, static_cast<int>(std::lround(m * scale)), cv::Scalar(70, 70, 70), 1, cv::LINE_AA);
	cv::circle(img, {int(c), int(c)}, static_cast<int>(std::lround(p.scanner.max_range * scale)), colour::kMaxRange, 1,
			   cv::LINE_AA);
	cv::arrowedLine(img, {int(c), int(c)}, to(0.0, 0.5), colour::kForward, 2, cv::LINE_AA, 0, 0.3);
	for (const auto& q : s.truth_pairs)
		if (q.status != PairStatus::LaserBeyondMaxRange) cv::circle(img, to(q.bearing, q.laser), 1, colour::kTruth, -1);
	for (const auto& q : s.laser_pairs)
		if (q.status != PairStatus::LaserBeyondMaxRange) cv::circle(img, to(q.bearing, q.laser), 1, colour::kLaser, -1);
	for (const Ray& r : s.scan.rays) cv::circle(img, to(r.bearing, r.range), 2, statusColour(r.status), -1);
	return img;
}

int frameAtColumn(int x, int width, int frames)
{
	if (frames <= 1 || width <= 1) return 0;
	return std::clamp(static_cast<int>(std::lround(static_cast<double>(x) * (frames - 1) / (width - 1))), 0, frames - 1);
}

cv::Mat drawErrorPlot(const LogScore& score, int current, cv::Size size)
{
	cv::Mat img(size, CV_8UC3, cv::Scalar(30, 30, 30));
	const int n = static_cast<int>(score.laser_by_frame.size());
	if (n == 0)
	{
		cv::putText(img, "not scored yet: Score all frames", {8, size.height / 2 + 4},
					cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(200, 200, 200), 1, cv::LINE_AA);
		return img;
	}
	std::vector<double> all;
	for (const auto* v : {&score.laser_by_frame, &score.truth_by_frame})
		for (const double e : *v)
			if (std::isfinite(e)) all.push_back(e);
	std::sort(all.begin(), all.end());
	const double top = std::max(0.1, all.empty() ? 0.0 : all[std::min(all.size() - 1, all.size() * 95 / 100)]);
	const auto x = [&](int k) { return n == 1 ? size.width / 2 : k * (size.width - 1) / (n - 1); };
	const auto y = [&](double e) { return size.height - 1 - static_cast<int>(std::lround(std::min(e, top) / top * (size.height - 14))); };
	cv::line(img, {x(current), 0}, {x(current), size.height - 1}, cv::Scalar(110, 110, 110), 1);
	// Each frame's unsure share as a bar up from the bottom, full height at every ray unsure.
	for (int k = 0; k < static_cast<int>(score.unsure_by_frame.size()) && k < n; ++k)
		if (const double u = score.unsure_by_frame[static_cast<std::size_t>(k)]; std::isfinite(u) && u > 0)
			cv::line(img, {x(k), size.height - 1}, {x(k), size.height - 1 - static_cast<int>(std::lround(u * (size.height - 14)))},
					 colour::kUnsure, 1);
	for (const auto& [v, c] : {std::pair{&score.truth_by_frame, colour::kTruth}, std::pair{&score.laser_by_frame, colour::kLaser}})
		for (int k = 0; k < n; ++k)
			if (std::isfinite((*v)[static_cast<std::size_t>(k)]))
				cv::circle(img, {x(k), y((*v)[static_cast<std::size_t>(k)])}, 1, c, -1);
	char label[32];
	std::snprintf(label, sizeof label, "%.2f m", top);
	cv::putText(img, label, {4, 11}, cv::FONT_HERSHEY_SIMPLEX, 0.35, cv::Scalar(200, 200, 200), 1, cv::LINE_AA);
	return img;
}

cv::Mat drawFloorColours(const ColourModel& colours, const FreeSpaceClassifier& classifier, cv::Size size)
{
	// One representative colour per bin: the mean of a 32-level RGB grid's
	// colours that fall in it (works for any colour space).
	const ColourBinner& binner = classifier.binner();
	std::map<std::uint32_t, std::array<double, 4>> sums;  // bin -> B, G, R, count
	for (int b = 4; b < 256; b += 8)
		for (int g = 4; g < 256; g += 8)
			for (int r = 4; r < 256; r += 8)
			{
				const std::uint8_t bgr[3] = {std::uint8_t(b), std::uint8_t(g), std::uint8_t(r)};
				auto& s = sums[binner.binOf(bgr)];
				s[0] += b, s[1] += g, s[2] += r, s[3] += 1;
			}
	std::vector<std::pair<double, cv::Scalar>> free;  // floor probability, colour
	for (const auto& [bin, s] : sums)
	{
		const std::uint8_t mean[3] = {std::uint8_t(s[0] / s[3]), std::uint8_t(s[1] / s[3]), std::uint8_t(s[2] / s[3])};
		if (classifier.isFree(mean)) free.push_back({colours.floor.probability(bin), cv::Scalar(mean[0], mean[1], mean[2])});
	}
	std::sort(free.begin(), free.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
	cv::Mat img(size, CV_8UC3, cv::Scalar(30, 30, 30));
	const int cell = 16, cols = std::max(1, size.width / cell);
	for (std::size_t i = 0; i < free.size(); ++i)
	{
		const int x = static_cast<int>(i % cols) * cell, y = static_cast<int>(i / cols) * cell;
		if (y + cell > size.height) break;
		cv::rectangle(img, cv::Rect(x + 1, y + 1, cell - 2, cell - 2), free[i].second, cv::FILLED);
	}
	return img;
}

cv::Mat drawPlaceholder(cv::Size size, const std::string& reason)
{
	cv::Mat out(size, CV_8UC3, colour::kPlaceholder);
	const double scale = std::max(0.5, size.width / 1024.0);
	const int line_height = static_cast<int>(32 * scale), margin = size.width / 20;
	const std::size_t per_line = 60;  // characters: the reason wraps at spaces near this
	int y = size.height / 3;
	for (std::size_t from = 0; from < reason.size(); y += line_height)
	{
		std::size_t to = std::min(reason.size(), from + per_line);
		if (to < reason.size())
			if (const auto space = reason.rfind(' ', to); space != std::string::npos && space > from) to = space;
		cv::putText(out, reason.substr(from, to - from), {margin, y}, cv::FONT_HERSHEY_SIMPLEX, 0.8 * scale,
					cv::Scalar(255, 255, 255), std::max(1, static_cast<int>(2 * scale)), cv::LINE_8);
		from = to + (to < reason.size() && reason[to] == ' ');
	}
	return out;
}

}  // namespace omnirange::tuner
