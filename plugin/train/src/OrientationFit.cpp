#include "omnirange/train/OrientationFit.h"

#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/RawlogProcessor.h"
#include "omnirange/train/LaserComparison.h"

#include <mrpt/obs/CObservationImage.h>

#include <array>
#include <memory>
#include <cmath>
#include <stdexcept>

namespace omnirange
{
namespace
{
using mrpt::obs::CObservation2DRangeScan;
constexpr double kPi = 3.14159265358979323846;

/** The scan turned by k rays and, for sign -1, reversed: ray j of the result
 * is the ray that would read at bearing j with that orientation. */
CObservation2DRangeScan turned(const CObservation2DRangeScan& scan, int sign, int k)
{
	CObservation2DRangeScan out = scan;
	const int S = static_cast<int>(scan.getScanSize());
	for (int j = 0; j < S; ++j)
	{
		const int m = ((sign > 0 ? j - k : S - 1 + k - j) % S + S) % S;
		out.setScanRange(j, scan.getScanRange(m));
		out.setScanRangeValidity(j, scan.getScanRangeValidity(m));
		if (scan.hasIntensity()) out.setScanIntensity(j, scan.getScanIntensity(m));  // each ray's confidence with it
	}
	return out;
}

/** Sum of the capped errors and how many laser rays counted. */
std::pair<double, int> disagreement(const CObservation2DRangeScan& laser, const CObservation2DRangeScan& omni)
{
	double sum = 0;
	int n = 0;
	for (const RangePair& p : pairScans(laser, omni, kDefaultMaxDifference))
	{
		if (p.status == PairStatus::Compared) sum += std::min(kDefaultMaxDifference, std::abs(p.difference())), ++n;
		else if (p.status == PairStatus::TooDifferent) sum += kDefaultMaxDifference, ++n;
	}
	return {sum, n};
}
}  // namespace

OrientationFit fitOrientation(const Rangefinder& rf, const MirrorCalibrationOptions& o, Progress* progress)
{
	if (o.every < 1) throw std::invalid_argument("every must be >= 1");
	const int S = rf.params().scanner.scanlines;
	// [reversed][turn]: summed error and count over every frame; each frame's best.
	std::array<std::vector<double>, 2> sum{std::vector<double>(S, 0.0), std::vector<double>(S, 0.0)};
	std::array<std::vector<int>, 2> count{std::vector<int>(S, 0), std::vector<int>(S, 0)};
	std::vector<std::pair<int, int>> frame_best;  // (reversed, turn)
	int seen = 0;
	RawlogProcessor loop(o.input);
	loop.onPair<mrpt::obs::CObservationImage, CObservation2DRangeScan>(
		o.omni_label, o.laser_label, o.max_dt,
		[&](const mrpt::obs::CObservationImage::Ptr& image, const CObservation2DRangeScan::Ptr& laser) {
			if (seen++ % o.every != 0) return;
			const auto omni = rf.toObservation(rf.process(decodeImage(*image, rf.params().camera)), image->timestamp);
			double best = 1e9;
			std::pair<int, int> arg{0, 0};
			for (int r = 0; r < 2; ++r)
				for (int k = 0; k < S; ++k)
				{
					const auto [e, n] = disagreement(*laser, turned(*omni, r ? -1 : 1, k));
					if (n < 10) continue;
					sum[r][k] += e, count[r][k] += n;
					if (e / n < best) best = e / n, arg = {r, k};
				}
			if (best < 1e9) frame_best.push_back(arg);
			if (frame_best.size() >= 60) loop.stop();
		});
	loop.run(progress);
	if (frame_best.size() < 3)
		throw std::runtime_error("only " + std::to_string(frame_best.size()) + " image/laser pairs in '" + o.input +
								 "' with rays to compare: too few to find the camera's orientation");
	OrientationFit f;
	f.frames = static_cast<int>(frame_best.size());
	int best_r = 0, best_k = 0;
	double best = 1e9;
	for (int r = 0; r < 2; ++r)
		for (int k = 0; k < S; ++k)
			if (count[r][k] > 0 && sum[r][k] / count[r][k] < best) best = sum[r][k] / count[r][k], best_r = r, best_k = k;
	f.error = best;
	f.error_as_given = count[0][0] ? sum[0][0] / count[0][0] : 0.0;
	// Back to the camera's keys (CameraModel: screen azimuth = az + s * bearing,
	// s = -1 when mirrored): a turn d and reversal sign give s' = sign * s and
	// az' = az - s' * d.
	const CameraParams& cam = rf.params().camera;
	const int s = cam.mirrored ? -1 : 1, s_new = (best_r ? -1 : 1) * s;
	const double d = 2 * kPi * best_k / S;
	f.mirrored = s_new < 0;
	f.forward_azimuth = std::remainder(cam.forward_azimuth - s_new * d, 2 * kPi);
	for (const auto& [r, k] : frame_best)
		if (r == best_r && std::abs(std::remainder(2 * kPi * (k - best_k) / S, 2 * kPi)) <= kAgreeingTurn + 1e-9)
			++f.agreeing;
	return f;
}

ScaledOrientationFit fitOrientationAndScale(const RangefinderParams& params, const ColourModel& colours,
											const MirrorCalibration& fitted, const MirrorCalibrationOptions& o)
{
	const MirrorModel m = params.camera.mirror_model;
	const std::string key = m == MirrorModel::Paraboloid ? "R" : m == MirrorModel::FirstOrder ? "alpha" : "h";
	const auto withScale = [&](double v) {
		RangefinderParams p = params;
		(key == "R" ? p.camera.R : key == "alpha" ? p.camera.alpha : p.camera.h) = v;
		return p;
	};
	const double given = key == "R" ? params.camera.R : key == "alpha" ? params.camera.alpha : params.camera.h;
	const double fitted_scale = key == "R" ? fitted.R : key == "alpha" ? fitted.alpha : fitted.height.h;
	std::vector<double> scales{given};
	if (std::isfinite(fitted_scale) && fitted_scale > 0) scales.push_back(fitted_scale);
	for (const double f : {0.6, 0.67, 0.75, 0.83, 0.91, 1.1, 1.2, 1.33, 1.5, 1.67}) scales.push_back(given * f);
	ScaledOrientationFit best;
	double error_as_given = 0;  // the ini's own orientation and scale, as the user gave them
	for (const double v : scales)
	{
		std::unique_ptr<Rangefinder> rf;
		try
		{
			rf = std::make_unique<Rangefinder>(withScale(v), colours);
		}
		catch (const std::exception&)
		{
			if (v == given) throw;  // the ini's own: what is wrong with it is the user's to hear
			continue;  // a scale the camera refuses (its radius must grow to the horizon, its circle fit the image)
		}
		const OrientationFit f = fitOrientation(*rf, o);
		if (v == given) error_as_given = f.error_as_given;
		if (best.scale_key.empty() || f.error < best.fit.error) best = {f, v, key};
	}
	if (best.scale_key.empty()) throw std::runtime_error("no scale near the ini's " + key + " makes a camera");
	best.fit.error_as_given = error_as_given;
	return best;
}

}  // namespace omnirange
