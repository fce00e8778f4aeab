#include "omnirange/train/MirrorCalibration.h"

#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/RawlogProcessor.h"
#include "omnirange/train/LaserComparison.h"

#include <mrpt/obs/CObservationImage.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace omnirange
{
namespace
{
double median(std::vector<double> v)
{
	std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
	return v[v.size() / 2];
}

/** Which residuals are within 3x their median (at least 3x `floor`): the
 * pairs a fit explains, the others being misclassified rays. */
std::vector<bool> explained(const std::vector<double>& residual, double floor)
{
	const double cut = 3.0 * std::max(floor, median(residual));
	std::vector<bool> keep;
	for (const double r : residual) keep.push_back(r <= cut);
	return keep;
}
}  // namespace

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

HeightFit fitHeight(const OmniCameraModel& camera, const std::vector<RhoRangePair>& pairs)
{
	struct Sample
	{
		double t, d;  // tan(theta), range
		int frame;
	};
	std::vector<Sample> all;
	for (const auto& p : pairs)
	{
		const double theta = camera.thetaFromRho(p.rho);
		if (p.rho > 0 && p.range > 0 && std::isfinite(p.range) && theta > 0 && theta < 85 * M_PI / 180)
			all.push_back({std::tan(theta), p.range, p.frame});
	}
	const auto fit = [](const std::vector<Sample>& v) {
		double s_td = 0, s_tt = 0;
		for (const auto& x : v) s_td += x.t * x.d, s_tt += x.t * x.t;
		return s_td / s_tt;
	};
	if (all.size() < 2) throw std::invalid_argument("fitHeight: fewer than 2 pairs below 85 degrees");
	// Fit, drop the pairs over 3x the median residual (misclassified rays), fit again.
	const double first = fit(all);
	std::vector<double> residual;
	for (const auto& x : all) residual.push_back(std::abs(x.d - first * x.t));
	const std::vector<bool> keep = explained(residual, 1e-9);
	std::vector<Sample> kept;
	for (std::size_t i = 0; i < all.size(); ++i)
		if (keep[i]) kept.push_back(all[i]);
	if (kept.size() < 2) kept = all;
	HeightFit r{fit(kept), 0, kept.size(), 0};
	// Its standard error from the images' own fits.
	std::map<int, std::vector<Sample>> by_frame;
	for (const auto& x : kept) by_frame[x.frame].push_back(x);
	std::vector<double> hs;
	for (const auto& [frame, v] : by_frame)
		if (v.size() >= 10) hs.push_back(fit(v));
	r.frames = static_cast<int>(hs.size());
	if (hs.size() >= 2)
	{
		double mean = 0, var = 0;
		for (const double h : hs) mean += h / hs.size();
		for (const double h : hs) var += (h - mean) * (h - mean) / (hs.size() - 1);
		r.std_error = std::sqrt(var / hs.size());
	}
	return r;
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

namespace
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationImage;

/** The (boundary rho, laser range) pairs of the chosen image/scan pairs. */
std::vector<RhoRangePair> collectPairs(const Rangefinder& rf, const MirrorCalibrationOptions& o, Progress* progress)
{
	RawlogProcessor loop(o.input);
	std::vector<RhoRangePair> pairs;
	int k = 0;
	loop.onPair<CObservationImage, CObservation2DRangeScan>(
		o.omni_label, o.laser_label, o.max_dt,
		[&](const CObservationImage::Ptr& image, const CObservation2DRangeScan::Ptr& laser) {
			if (k++ % o.every != 0) return;
			const RangeScan scan = rf.process(decodeImage(*image, rf.params().camera));
			const auto omni = rf.toObservation(scan, image->timestamp);
			// Hits only; a laser range beyond the max range cannot have one. The
			// boundary as found, without the ini's boundary_offset: R fitted to
			// shifted hits would absorb the offset, and saving both (as
			// --save-to does) would make each run move the other.
			const double offset = rf.params().scanner.boundary_offset;
			for (const RangePair& p : pairScans(*laser, *omni, 1e9))
				if (p.status != PairStatus::LaserBeyondMaxRange && scan.rays[p.omni_ray].status == RayStatus::Hit)
					pairs.push_back({scan.rays[p.omni_ray].hit_rho - offset, p.laser, k});
		});
	loop.run(progress);
	if (k == 0) throw std::runtime_error(loop.describeNoPair());
	return pairs;
}

/** The pairs a first paraboloid fit explains within 3x its median residual
 * (the others are misclassified rays). */
std::vector<RhoRangePair> dropWorstPairs(const std::vector<RhoRangePair>& pairs, const CameraParams& given)
{
	CameraParams para = given;
	para.mirror_model = MirrorModel::Paraboloid;
	para.R = fitR(pairs, given.h);
	const OmniCameraModel model(para);
	std::vector<double> residual;
	for (const auto& p : pairs) residual.push_back(std::abs(model.thetaFromRho(p.rho) - std::atan2(p.range, given.h)));
	const std::vector<bool> keep = explained(residual, 1e-6);
	std::vector<RhoRangePair> kept;
	for (std::size_t i = 0; i < pairs.size(); ++i)
		if (keep[i]) kept.push_back(pairs[i]);
	return kept;
}
}  // namespace

MirrorCalibration calibrateMirror(const Rangefinder& rf, const MirrorCalibrationOptions& o, Progress* progress)
{
	if (o.every < 1) throw std::invalid_argument("every must be >= 1");
	const std::vector<RhoRangePair> pairs = collectPairs(rf, o, progress);
	if (pairs.size() < 10)
		throw std::runtime_error("only " + std::to_string(pairs.size()) + " image/laser ray pairs with a hit in '" +
								 o.input + "': too few to calibrate");
	const CameraParams& given = rf.params().camera;
	const std::vector<RhoRangePair> kept = dropWorstPairs(pairs, given);
	MirrorCalibration c;
	c.pairs = pairs.size(), c.kept = kept.size();
	CameraParams para = given, first = given;
	para.mirror_model = MirrorModel::Paraboloid;
	first.mirror_model = MirrorModel::FirstOrder;
	c.R = para.R = fitR(kept, given.h);
	c.alpha = first.alpha = fitAlpha(kept, given.h);
	c.rms_R = rmsRangeError(OmniCameraModel(para), kept);
	c.rms_alpha = rmsRangeError(OmniCameraModel(first), kept);
	c.rms_given = rmsRangeError(rf.camera(), kept);
	c.height = fitHeight(rf.camera(), pairs);  // its own outlier cut: dropWorstPairs assumes a paraboloid
	CameraParams with_h = given;
	with_h.h = c.height.h;
	c.rms_height = rmsRangeError(OmniCameraModel(with_h), kept);
	std::vector<double> px;
	for (const auto& p : kept) px.push_back(rf.camera().rhoFromDistance(p.range) - p.rho);
	const double want = median(px);  // from the boundary as found
	c.boundary_px = want - rf.params().scanner.boundary_offset;  // beyond the omnicam's, offset included
	c.suggested_boundary_offset = std::clamp(want, -1.0, 1.0);
	c.clamped = c.suggested_boundary_offset != want;
	return c;
}

}  // namespace omnirange
