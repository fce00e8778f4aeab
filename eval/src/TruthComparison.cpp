#include "omnirange_eval/TruthComparison.h"

#include <omnirange/core/Rangefinder.h>
#include <omnirange/train/LaserComparison.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace omnirange::eval
{
double TruthBand::meanAbs() const
{
	double s = 0;
	for (double e : abs_errors) s += e;
	return abs_errors.empty() ? 0 : s / abs_errors.size();
}

double TruthBand::medianAbs() const
{
	if (abs_errors.empty()) return 0;
	std::vector<double> v = abs_errors;
	std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
	return v[v.size() / 2];
}

TruthBand TruthStats::all() const
{
	TruthBand a(bands.front().lo, bands.back().hi);
	for (const auto& b : bands)
	{
		a.rays += b.rays, a.within_2cm += b.within_2cm, a.within_5cm += b.within_5cm;
		a.missed_no_hit += b.missed_no_hit, a.missed_rejected += b.missed_rejected;
		a.unsure += b.unsure, a.false_free += b.false_free;
		a.sum_signed += b.sum_signed;
		a.abs_errors.insert(a.abs_errors.end(), b.abs_errors.begin(), b.abs_errors.end());
	}
	return a;
}

void TruthStats::add(const mrpt::obs::CObservation2DRangeScan& truth, const mrpt::obs::CObservation2DRangeScan& omni,
					 const std::vector<char>& scored, double max_range)
{
	const mrpt::poses::CPose3D d = omni.sensorPose - truth.sensorPose;
	if (d.norm() > 1e-3 || std::abs(d.yaw()) > 1e-3)
		throw std::invalid_argument("the " + truth.sensorLabel + " and " + omni.sensorLabel +
									" scans were not taken from the same pose on the robot");
	const int S = static_cast<int>(truth.getScanSize());
	const int n = static_cast<int>(omni.getScanSize());
	if (S < 2 || n < 2) return;
	const double step = truth.aperture / (S - 1);
	for (int i = 0; i < n; ++i)
	{
		if (!scored.empty() && !scored[i]) continue;
		const double bearing = -0.5 * omni.aperture + i * omni.aperture / (n - 1);
		const int k = ((static_cast<int>(std::lround((bearing + 0.5 * truth.aperture) / step)) % S) + S) % S;
		const bool unsure = rayIsUnsure(omni, i);
		const bool hit = omni.getScanRangeValidity(i) && !unsure;
		const double range = omni.getScanRange(i);
		const double true_d = truth.getScanRange(k);
		if (!truth.getScanRangeValidity(k) || true_d > max_range)
		{
			++open_rays;
			open_unsure += unsure;
			false_obstacles += hit && range < max_range - 0.05 ? 1 : 0;
			continue;
		}
		TruthBand& b = *std::find_if(bands.begin(), bands.end(), [&](const TruthBand& x) { return true_d < x.hi; });
		++b.rays;
		if (unsure)
		{
			// Free only up to its extent: false free when that extent is past the truth.
			++b.unsure;
			b.false_free += range > true_d + kFalseFreeMargin;
			continue;
		}
		if (!hit)
		{
			const bool no_hit = range >= max_range - 1e-4;
			++(no_hit ? b.missed_no_hit : b.missed_rejected);
			++b.false_free;
			continue;
		}
		const double e = std::abs(range - true_d);
		b.false_free += range > true_d + kFalseFreeMargin;
		b.abs_errors.push_back(e);
		b.sum_signed += range - true_d;
		b.within_2cm += e <= 0.02;
		b.within_5cm += e <= 0.05;
	}
	++frames;
}

std::string TruthStats::table() const
{
	std::string out = std::string(kTruthTableBegins) +
		" within 2 cm | within 5 cm | mean abs error | median abs error | signed mean | "
		"missed: no hit | missed: rejected | unsure | false free |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
	const auto row = [&](const std::string& name, const TruthBand& b) {
		const double n = static_cast<double>(std::max<std::size_t>(1, b.rays));
		char line[400];
		std::snprintf(line, sizeof line,
					  "| %s | %zu | %.1f %% | %.1f %% | %.4f m | %.4f m | %+.4f m | %.1f %% | %.1f %% | %.1f %% | %.1f %% |\n",
					  name.c_str(), b.rays, 100.0 * b.within_2cm / n, 100.0 * b.within_5cm / n, b.meanAbs(),
					  b.medianAbs(), b.meanSigned(), 100.0 * b.missed_no_hit / n, 100.0 * b.missed_rejected / n,
					  100.0 * b.unsure / n, 100.0 * b.false_free / n);
		out += line;
	};
	row("all", all());
	for (const auto& b : bands)
	{
		char name[64];
		std::snprintf(name, sizeof name, b.hi > 1e8 ? "%.0f m to max range" : "%.0f to %.0f m", b.lo, b.hi);
		row(name, b);
	}
	char tail[300];
	std::snprintf(tail, sizeof tail,
				  "\nRays whose floor goes on past the max range: %zu; of them with a hit (false obstacles): %zu "
				  "(%.1f %%), unsure: %zu. %d scan pairs.\n",
				  open_rays, false_obstacles, 100.0 * false_obstacles / std::max<std::size_t>(1, open_rays), open_unsure,
				  frames);
	return out + tail;
}

}  // namespace omnirange::eval
