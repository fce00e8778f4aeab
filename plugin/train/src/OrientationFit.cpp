#include "omnirange/train/OrientationFit.h"

#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/RawlogProcessor.h"
#include "omnirange/train/LaserComparison.h"

#include <mrpt/obs/CObservationImage.h>

#include <array>
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
	double sq = 0;
	for (const auto& [r, k] : frame_best)
	{
		const double diff = r != best_r ? kPi : std::abs(std::remainder(2 * kPi * (k - best_k) / S, 2 * kPi));
		sq += diff * diff;
	}
	f.spread = std::sqrt(sq / static_cast<double>(frame_best.size()));
	return f;
}

}  // namespace omnirange
