#include "omnirange/Accuracy.h"

#include "omnirange/RawlogReader.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace omnirange
{
std::string toString(PairStatus s)
{
	switch (s)
	{
		case PairStatus::Compared: return "compared";
		case PairStatus::LaserBeyondMaxRange: return "laser_beyond_max_range";
		case PairStatus::TooDifferent: return "too_different";
		default: return "omni_rejected";
	}
}

std::vector<RangePair> pairScans(const mrpt::obs::CObservation2DRangeScan& laser,
								 const mrpt::obs::CObservation2DRangeScan& omni, double max_diff)
{
	std::vector<RangePair> out;
	const int S = static_cast<int>(omni.getScanSize());
	if (S < 2) return out;
	const double step = omni.aperture / (S - 1);
	// The laser's pose seen from the omnicam (both on the robot).
	const mrpt::poses::CPose3D rel = laser.sensorPose - omni.sensorPose;
	for (std::size_t i = 0; i < laser.getScanSize(); ++i)
	{
		if (!laser.getScanRangeValidity(i)) continue;  // no return: nothing to compare
		const double r = laser.getScanRange(i), a = laser.getScanAngle(i);
		mrpt::math::TPoint3D p;
		rel.composePoint({r * std::cos(a), r * std::sin(a), 0}, p);
		const double bearing = std::atan2(p.y, p.x);
		int k = static_cast<int>(std::lround((bearing + 0.5 * omni.aperture) / step));
		k = ((k % S) + S) % S;  // the scan closes the circle
		RangePair rp{static_cast<int>(i), k, bearing, std::hypot(p.x, p.y), omni.getScanRange(k), PairStatus::Compared};
		const bool no_hit = !omni.getScanRangeValidity(k) && rp.omni >= omni.maxRange - 1e-4;
		if (rp.laser > omni.maxRange)
			rp.status = PairStatus::LaserBeyondMaxRange;
		else if (!omni.getScanRangeValidity(k) && !no_hit)
			rp.status = PairStatus::OmniRejected;
		else if (std::abs(rp.difference()) > max_diff)
			rp.status = PairStatus::TooDifferent;
		out.push_back(rp);
	}
	return out;
}

void AccuracyStats::add(const RangePair& p)
{
	switch (p.status)
	{
		case PairStatus::LaserBeyondMaxRange: ++laser_beyond; return;
		case PairStatus::TooDifferent: ++too_different; return;
		case PairStatus::OmniRejected: ++omni_rejected; return;
		case PairStatus::Compared: break;
	}
	++compared;
	const double d = p.difference();
	sum_abs += std::abs(d);
	sum_signed += d;
	sum_pct += 100.0 * std::abs(d) / p.laser;
	differences.push_back(d);
}

double AccuracyStats::excludedFraction() const
{
	const auto n = total();
	return n ? static_cast<double>(laser_beyond + too_different) / n : 0.0;
}

AccuracyResult evaluateAccuracy(const std::string& rawlog, const AccuracyOptions& o)
{
	if (!(o.max_difference > 0) || !(o.max_dt >= 0))
		throw std::invalid_argument("accuracy: max_difference must be > 0 and max_dt >= 0");
	RawlogReader reader(rawlog);
	mrpt::obs::CObservation2DRangeScan::Ptr laser, omni;
	AccuracyResult r;
	r.csv = "frame,laser_ray,omni_ray,bearing_rad,laser_m,omni_m,difference_m,status\n";
	while (auto obj = reader.next())
	{
		auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obj);
		if (!scan) continue;
		if (scan->sensorLabel == o.laser_label) laser = scan;
		else if (scan->sensorLabel == o.omni_label) omni = scan;
		else continue;
		if (!laser || !omni || std::abs(mrpt::system::timeDifference(laser->timestamp, omni->timestamp)) > o.max_dt)
			continue;
		for (const RangePair& p : pairScans(*laser, *omni, o.max_difference))
		{
			r.stats.add(p);
			char line[200];
			std::snprintf(line, sizeof line, "%d,%d,%d,%.5f,%.4f,%.4f,%.4f,%s\n", r.frames, p.laser_ray, p.omni_ray,
						  p.bearing, p.laser, p.omni, p.difference(), toString(p.status).c_str());
			r.csv += line;
		}
		laser.reset();
		omni.reset();
		++r.frames;
	}
	if (r.frames == 0)
		throw std::runtime_error("no " + o.laser_label + " scan had an " + o.omni_label + " scan within " +
								 std::to_string(o.max_dt) + " s in '" + rawlog + "'");
	return r;
}

std::string AccuracyResult::table(double max_difference) const
{
	const auto& s = stats;
	const double n = static_cast<double>(std::max<std::size_t>(1, s.total()));
	char row[512];
	std::snprintf(row, sizeof row,
				  "| frames | pairs | compared | excluded: laser beyond omni max range | excluded: difference > %.2f m "
				  "| omni ray rejected | mean absolute difference | mean percentage difference | signed mean |\n"
				  "|---|---|---|---|---|---|---|---|---|\n"
				  "| %d | %zu | %zu | %zu (%.1f %%) | %zu (%.1f %%) | %zu | %.4f m | %.3f %% | %+.4f m |\n",
				  max_difference, frames, s.total(), s.compared, s.laser_beyond, 100.0 * s.laser_beyond / n,
				  s.too_different, 100.0 * s.too_different / n, s.omni_rejected, s.meanAbs(), s.meanPercent(),
				  s.meanSigned());
	return row;
}

cv::Mat differenceHistogram(const std::vector<double>& d, const std::string& title, double range, double bin)
{
	const int nb = static_cast<int>(std::lround(2 * range / bin));
	std::vector<int> counts(nb, 0);
	for (double x : d)
	{
		const int b = static_cast<int>(std::floor((x + range) / bin));
		if (b >= 0 && b < nb) ++counts[b];
	}
	const int W = 800, H = 500, L = 70, R = 20, T = 40, B = 60;
	cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
	const int top = std::max(1, *std::max_element(counts.begin(), counts.end()));
	const double bw = double(W - L - R) / nb;
	for (int b = 0; b < nb; ++b)
	{
		const int h = static_cast<int>(double(H - T - B) * counts[b] / top);
		cv::rectangle(img, cv::Point(int(L + b * bw), H - B - h), cv::Point(int(L + (b + 1) * bw) - 1, H - B),
					  cv::Scalar(180, 110, 40), cv::FILLED);
	}
	const auto text = [&](const std::string& s, int x, int y, double scale = 0.45) {
		cv::putText(img, s, {x, y}, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
	};
	cv::line(img, {L, H - B}, {W - R, H - B}, cv::Scalar(0, 0, 0));
	cv::line(img, {L, T}, {L, H - B}, cv::Scalar(0, 0, 0));
	for (double x = -range; x <= range + 1e-9; x += 0.25)
	{
		const int px = static_cast<int>(L + (x + range) / (2 * range) * (W - L - R));
		cv::line(img, {px, H - B}, {px, H - B + 5}, cv::Scalar(0, 0, 0));
		char s[16];
		std::snprintf(s, sizeof s, "%.2f", x);
		text(s, px - 18, H - B + 22);
	}
	for (int k = 0; k <= 4; ++k)
	{
		const int py = H - B - (H - T - B) * k / 4;
		text(std::to_string(top * k / 4), 5, py + 5);
	}
	text("laser - omnicam [m]", W / 2 - 80, H - 12, 0.55);
	text(title, L, 25, 0.6);
	return img;
}

}  // namespace omnirange
