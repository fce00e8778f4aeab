#include "omnirange/train/ParameterLearning.h"

#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/RawlogProcessor.h"
#include "omnirange/train/LaserComparison.h"

#include <mrpt/obs/CObservationImage.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace omnirange
{
namespace
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationImage;

struct Validation
{
	cv::Mat image;
	CObservation2DRangeScan::Ptr laser;
};

using TrainerKey = std::pair<ColourSpace, int>;  // colour space, bins

/** Trains one histogram per colour space and bin count on the training pairs and keeps the held-aside ones. */
void collect(const RangefinderParams& rp, const RawlogTrainingOptions& o, const LearningOptions& lo,
			 std::map<TrainerKey, HistogramTrainer>& trainers, std::vector<Validation>& validation, int& trained,
			 Progress* progress)
{
	RawlogProcessor loop(o.input);
	int pairs = 0, selected = 0;
	loop.onPair<CObservationImage, CObservation2DRangeScan>(
		o.omni_label, o.laser_label, o.max_dt,
		[&](const CObservationImage::Ptr& image, const CObservation2DRangeScan::Ptr& laser) {
			const int k = pairs++;
			if ((o.until > 0 && k >= o.until) || k < o.first || (k - o.first) % o.every != 0) return;
			const cv::Mat bgr = decodeImage(*image, rp.camera);
			if (++selected % lo.hold_out_every == 0)
			{
				if (static_cast<int>(validation.size()) < lo.max_validation_pairs) validation.push_back({bgr, laser});
				return;
			}
			for (auto& [key, trainer] : trainers) trainer.add(bgr, *laser);
			++trained;
		});
	loop.run(progress);
	if (pairs == 0) throw std::runtime_error(loop.describeNoPair() + "; learning needs both");
	if (trained == 0 || validation.empty())
		throw std::runtime_error("'" + o.input + "' has too few image/laser pairs to learn from (" +
								 std::to_string(selected) + " selected; some are needed to train and some to validate)");
}

/** The candidate's error on the held-aside pairs (see LearnedCandidate::score). */
double score(const Rangefinder& rf, const std::vector<Validation>& validation)
{
	double sum = 0;
	std::size_t n = 0;
	const double max_range = rf.params().scanner.max_range, cap = kDefaultMaxDifference;
	for (const auto& v : validation)
	{
		const auto omni = rf.toObservation(rf.process(v.image), v.laser->timestamp);
		for (const RangePair& p : pairScans(*v.laser, *omni, cap))
		{
			const bool hit = omni->getScanRangeValidity(p.omni_ray);
			switch (p.status)
			{
				case PairStatus::Compared: sum += std::min(cap, std::abs(p.difference())); break;
				case PairStatus::TooDifferent: sum += cap; break;
				case PairStatus::OmniRejected: sum += cap; break;  // no answer is as bad as a wrong one
				case PairStatus::LaserBeyondMaxRange: sum += hit ? std::min(cap, max_range - p.omni) : 0.0; break;
			}
			++n;
		}
	}
	return n ? sum / n : cap;
}
}  // namespace

LearningResult learnParameters(const RangefinderParams& start, const RawlogTrainingOptions& o, const LearningOptions& lo,
							   Progress* progress)
{
	o.validate();
	start.validate();
	if (lo.hold_out_every < 2) throw std::invalid_argument("hold_out_every must be >= 2");
	const OmniCameraModel camera(start.camera);
	const double base_range = camera.distanceFromRho(start.scanner.base_radius) + 0.05;
	std::vector<int> bins = lo.bins;
	if (bins.empty()) bins = {o.training.bins, std::min(64, 2 * o.training.bins)};
	std::sort(bins.begin(), bins.end());
	bins.erase(std::unique(bins.begin(), bins.end()), bins.end());
	std::map<TrainerKey, HistogramTrainer> trainers;
	for (const ColourSpace space : lo.spaces)
		for (const int b : bins)
		{
			TrainingParams tp = o.training;
			tp.space = space, tp.bins = b;
			trainers.emplace(TrainerKey{space, b},
							 HistogramTrainer(camera, start.sensor_pose, base_range, start.scanner.max_range, tp));
		}
	std::vector<Validation> validation;
	LearningResult r;
	collect(start, o, lo, trainers, validation, r.training_pairs, progress);
	r.validation_pairs = static_cast<int>(validation.size());

	r.best.score = 1e9;
	for (const auto& [key, trainer] : trainers)
	{
		const ColourModel model = trainer.model();
		if (model.floor.empty()) continue;
		for (const double theta : lo.thresholds)
			for (const double ratio : lo.obstacle_ratios)
				for (const int N : lo.Ns)
					for (const int K : lo.Ks)
						for (const BoundaryModel boundary : lo.boundary_models)
						{
							RangefinderParams p = start;
							p.threshold = theta, p.obstacle_ratio = ratio, p.scanner.filter.N = N;
							p.scanner.filter.K = K, p.scanner.boundary_model = boundary;
							const LearnedCandidate c{key.first, key.second, theta, ratio, N, K, boundary,
													 score(Rangefinder(p, model), validation)};
							r.tried.push_back(c);
							if (c.score < r.best.score) r.best = c, r.params = p, r.model = model;
						}
	}
	if (r.tried.empty()) throw std::runtime_error("no free-floor pixel was found to train on");
	return r;
}

std::string describe(const LearnedCandidate& c)
{
	char s[300];
	std::snprintf(s, sizeof s, "colour space %s, %d bins, threshold %g, obstacle_ratio %g, N %d, K %d, %s boundary",
				  toString(c.space).c_str(), c.bins, c.threshold, c.obstacle_ratio, c.N, c.K, toString(c.boundary).c_str());
	return s;
}

std::string learnedIni(const LearningResult& r, const std::string& section)
{
	char head[700];
	std::snprintf(head, sizeof head,
				  "; Learned by omnirange-train --learn: %zu candidates scored against the laser on %d held-aside\n"
				  "; image/laser pairs (histograms trained on %d others). The winner: %s;\n"
				  "; mean error %.4f m. Train the histogram in that colour space and with those bins\n"
				  "; (the histogram file written with this ini is).\n[%s]\n",
				  r.tried.size(), r.validation_pairs, r.training_pairs, describe(r.best).c_str(), r.best.score,
				  section.c_str());
	return head + r.params.asIni();
}

}  // namespace omnirange
