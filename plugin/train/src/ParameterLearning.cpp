#include "omnirange/train/ParameterLearning.h"

#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/RawlogProcessor.h"
#include "omnirange/train/EdgeBiasLearning.h"
#include "omnirange/train/LaserComparison.h"

#include <omnirange/core/Threads.h>

#include <mrpt/obs/CObservationImage.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <tuple>

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

using Trainers = std::map<HistogramKey, HistogramTrainer>;

/** How many pairs the options select: a pass that decodes no image. */
int countSelected(const RawlogTrainingOptions& o)
{
	RawlogProcessor loop(o.input);
	int pairs = 0, selected = 0;
	loop.onPair<CObservationImage, CObservation2DRangeScan>(
		o.omni_label, o.laser_label, o.max_dt,
		[&](const CObservationImage::Ptr&, const CObservation2DRangeScan::Ptr&) { selected += o.selects(pairs++); });
	loop.run();
	if (pairs == 0) throw std::runtime_error(loop.describeNoPair() + "; learning needs both");
	return selected;
}

/** `rf`'s scan of each held-aside pair, in their order; the pairs are
 * scanned on the threads OpenCV may use (each alone: the sums stay the same). */
std::vector<CObservation2DRangeScan::Ptr> scansOf(const Rangefinder& rf, const std::vector<Validation>& validation)
{
	std::vector<CObservation2DRangeScan::Ptr> scans(validation.size());
	forEachOnThreads(static_cast<int>(validation.size()), [&](int i) {
		scans[i] = rf.toObservation(rf.process(validation[i].image), validation[i].laser->timestamp);
	});
	return scans;
}

/** The candidate's error on the held-aside pairs, and per pair in
 * `frame_errors` (see LearnedCandidate::score). */
double score(const Rangefinder& rf, const std::vector<Validation>& validation, std::vector<double>& frame_errors,
			 std::vector<double>& frame_shortfalls)
{
	double sum = 0;
	std::size_t n = 0;
	const double max_range = rf.params().scanner.max_range, cap = kDefaultMaxDifference;
	frame_errors.clear();
	frame_shortfalls.clear();
	const auto scans = scansOf(rf, validation);
	for (std::size_t i = 0; i < validation.size(); ++i)
	{
		double frame = 0, short_of_laser = 0;
		std::size_t rays = 0;
		const auto& v = validation[i];
		const auto& omni = scans[i];
		for (const RangePair& p : pairScans(*v.laser, *omni, cap))
		{
			const RayError e = learningError(p, omni->getScanRangeValidity(p.omni_ray), max_range);
			frame += e.error, short_of_laser += e.nearer ? e.error : 0.0, ++rays;
		}
		sum += frame, n += rays;
		frame_errors.push_back(rays ? frame / static_cast<double>(rays) : cap);
		frame_shortfalls.push_back(rays ? short_of_laser / static_cast<double>(rays) : 0.0);
	}
	return n ? sum / n : cap;
}

/** The doubt grid: shares of the floor's training pixels whose colours are
 * sure floor (1: all free colours), and runs of pixels not sure floor
 * (doubtful or not free) that end a ray's claim. */
constexpr double kSureShares[] = {1.0, 0.995, 0.99, 0.98, 0.95, 0.9, 0.8, 0.7, 0.6, 0.5};
constexpr int kSureRuns[] = {5, 10, 20, 40};
/** ...and how much likelier the floor than the obstacles' feet must show a colour (0: no matter). */
constexpr double kSureRatios[] = {0, 1, 2, 4, 8};

/** `rf`'s doubt on the validation pairs against the laser: the share of the
 * laser's returns within max range seen through (read free more than
 * kSeenThroughMargin past them), the share of rays unsure, and the cost that
 * weighs the two (kFalseFreeCost). */
DoubtChoice scoreDoubt(const Rangefinder& rf, const std::vector<Validation>& validation, double& cost)
{
	std::size_t rays = 0, in_range = 0, false_free = 0, unsure = 0;
	const auto scans = scansOf(rf, validation);
	for (std::size_t i = 0; i < validation.size(); ++i)
	{
		const auto& omni = scans[i];
		for (const RangePair& p : pairScans(*validation[i].laser, *omni))
		{
			++rays;
			unsure += rayIsUnsure(*omni, p.omni_ray);
			if (p.status == PairStatus::LaserBeyondMaxRange) continue;
			++in_range;
			false_free += p.status == PairStatus::OmniRejected || p.omni > p.laser + kSeenThroughMargin;
		}
	}
	DoubtChoice d;
	d.false_free = in_range ? double(false_free) / in_range : 0;
	d.unsure = rays ? double(unsure) / rays : 0;
	cost = rays ? (kFalseFreeCost * false_free + unsure) / rays : 0;
	return d;
}

/** The hits of `rf` on every pair `o` selects that a laser ray sees too,
 * with their contrast (EdgeBiasLearning.h). */
std::vector<EdgeSample> edgeSamples(const Rangefinder& rf, const RawlogTrainingOptions& o)
{
	std::vector<EdgeSample> samples;
	RawlogProcessor loop(o.input);
	int pairs = 0;
	loop.onPair<CObservationImage, CObservation2DRangeScan>(
		o.omni_label, o.laser_label, o.max_dt,
		[&](const CObservationImage::Ptr& image, const CObservation2DRangeScan::Ptr& laser) {
			if (!o.selects(pairs++)) return;
			const RangeScan scan = rf.process(decodeImage(*image, rf.params().camera));
			const auto omni = rf.toObservation(scan, laser->timestamp);
			for (const RangePair& p : pairScans(*laser, *omni))
				if (p.status == PairStatus::Compared && omni->getScanRangeValidity(p.omni_ray))
					samples.push_back({scan.rays[p.omni_ray].edge_contrast, p.difference()});
		});
	loop.run();
	return samples;
}
}  // namespace

namespace
{
/** `v` sorted, each value once: each is scored once. */
template <class T>
std::vector<T> sortedOnce(std::vector<T> v)
{
	std::sort(v.begin(), v.end());
	v.erase(std::unique(v.begin(), v.end()), v.end());
	return v;
}

/** What learning's stages share: the inputs, the histograms' counts on the
 * training pairs and on the held-aside ones, the held-aside images, and the
 * result so far. */
struct Learning
{
	const RangefinderParams& start;
	const RawlogTrainingOptions& o;
	const LearningOptions& lo;
	OmniCameraModel camera;
	int selected;
	Trainers trainers, aside;  // one per histogram key; `aside`: the held-aside pairs' counts (refit)
	std::vector<Validation> validation;
	std::map<HistogramKey, ColourModel> models;  // trained on the training pairs
	int set_aside{0};
	LearningResult r;

	Learning(const RangefinderParams& s, const RawlogTrainingOptions& opts, const LearningOptions& l)
		: start(s), o(opts), lo(l), camera(s.camera), selected(countSelected(opts))
	{
	}

	/** A trainer per colour space and bin count, for the training pairs and for the held-aside ones. */
	void makeTrainers()
	{
		std::vector<int> bins = lo.bins.empty() ? std::vector<int>{o.training.bins, std::min(64, 2 * o.training.bins)} : lo.bins;
		const double base_range = floorBeyondBase(camera, start.scanner);
		for (const ColourSpace space : lo.spaces)
			for (const int b : sortedOnce(bins))
			{
				TrainingParams tp = o.training;
				tp.space = space, tp.bins = b, tp.light_change = 0;
				const HistogramTrainer t(camera, start.sensor_pose, base_range, start.scanner.max_range, tp);
				trainers.emplace(HistogramKey{space, b}, t);
				aside.emplace(HistogramKey{space, b}, t);
			}
	}

	/** Pair k of those selected: counted into the trainers of its role, and kept to score on when it validates. */
	void add(PairRole role, const CObservationImage& image, const CObservation2DRangeScan::Ptr& laser)
	{
		const cv::Mat bgr = decodeImage(image, start.camera);
		if (role == PairRole::Validate) validation.push_back({bgr, laser});
		Trainers& into = role == PairRole::Train ? trainers : aside;
		for (auto& [key, trainer] : into) trainer.add(bgr, *laser);
		++(role == PairRole::Train ? r.training_pairs : set_aside);
	}

	/** Every selected pair into the training or the held-aside counts (add()). */
	void collect(Progress* progress)
	{
		const std::vector<PairRole> roles = splitPairs(lo, selected);
		RawlogProcessor loop(o.input);
		int pairs = 0, s = 0;
		loop.onPair<CObservationImage, CObservation2DRangeScan>(
			o.omni_label, o.laser_label, o.max_dt,
			[&](const CObservationImage::Ptr& image, const CObservation2DRangeScan::Ptr& laser) {
				if (!o.selects(pairs++)) return;
				const int k = s++;
				if (k < static_cast<int>(roles.size())) add(roles[k], *image, laser);
			});
		loop.run(progress);
		if (pairs == 0) throw std::runtime_error(loop.describeNoPair() + "; learning needs both");
		if (r.training_pairs == 0 || validation.empty())
			throw std::runtime_error("'" + o.input + "' has too few image/laser pairs to learn from (" +
									 std::to_string(s) + " selected; some are needed to train and some to validate)");
	}

	/** A rangefinder with the training pairs' histogram of `key`, scored on the
	 * classifier's own ranges: the wall fit smooths over the very errors learning must see. */
	Rangefinder rangefinder(const RangefinderParams& p, const HistogramKey& key, bool doubt = false) const
	{
		RangefinderParams scored = p;
		scored.walls.wall_fit = false;
		if (!doubt) scored.scanner.sure_run = 0;  // the doubt is learned for the winner (learnDoubt)
		return Rangefinder(scored, models.at(key));
	}

	void consider(LearnedCandidate c)
	{
		const RangefinderParams p = withCandidate(start, c);
		c.score = score(rangefinder(p, histogramKeyOf(c)), validation, c.frame_errors, c.frame_shortfalls);
		r.tried.push_back(c);
		if (c.score < r.best.score) r.best = c, r.params = p;
	}

	/** The filter windows the image can hold past the scan circle: a user's
	 * camera may leave little room round it. */
	std::vector<std::pair<int, int>> windows() const
	{
		std::vector<std::pair<int, int>> fit;
		for (const int N : lo.Ns)
			for (const int K : lo.Ks)
			{
				PolarScannerParams scanner = start.scanner;
				scanner.filter.N = N, scanner.filter.K = K;
				try
				{
					PolarScanner(camera, scanner);
					fit.emplace_back(N, K);
				}
				catch (const std::invalid_argument&)
				{
				}
			}
		if (fit.empty())
			throw std::invalid_argument("no N and K of the learning grid fit the image past max_range (" +
										std::to_string(start.scanner.max_range) + " m)");
		return fit;
	}

	/** Every candidate of the grid, for each histogram key whose training pairs have floor counts. */
	void scoreGrid()
	{
		const auto fit = windows();
		r.best.score = 1e9;
		for (const auto& [key, trainer] : trainers)
		{
			ColourModel model = trainer.model();
			if (model.floor.empty()) continue;
			models.emplace(key, std::move(model));
			const auto& [space, b] = key;
			for (const double theta : lo.thresholds)
				for (const double ratio : lo.obstacle_ratios)
					for (const double smoothing : lo.smoothings)
						for (const auto& [N, K] : fit)
							for (const BoundaryModel boundary : lo.boundary_models)
								consider({space, b, theta, ratio, smoothing, N, K, boundary, 0.0, StepSign::Either, 0.0, {}, {}});
		}
	}

	/** The brightness step on the grid's best: it is for what colour cannot
	 * see, and scoring it on every candidate would multiply the cost. */
	void scoreSteps()
	{
		const std::vector<StepSign> signs = sortedOnce(lo.step_signs);
		const std::vector<double> steps = signs.empty() ? std::vector<double>{} : sortedOnce(lo.step_thresholds);
		std::vector<LearnedCandidate> best = r.tried;
		const std::size_t top = std::min<std::size_t>(best.size(), std::max(0, lo.step_candidates));
		std::partial_sort(best.begin(), best.begin() + top, best.end(),
						  [](const LearnedCandidate& a, const LearnedCandidate& b) { return a.score < b.score; });
		for (std::size_t i = 0; i < top; ++i)
			for (const double step : steps)
				for (const StepSign sign : signs)
				{
					LearnedCandidate c = best[i];
					c.step_threshold = step, c.step_sign = sign;
					consider(c);
				}
	}

	/** The histograms the result runs with: the training pairs' counts with the held-aside pairs' added. */
	void refit()
	{
		r.training = o.training;
		r.training.space = r.best.space, r.training.bins = r.best.bins, r.training.light_change = 0;
		for (const auto& [key, unused] : models)
		{
			HistogramTrainer all = trainers.at(key);
			all.merge(aside.at(key));
			r.models.emplace(key, all.model());
		}
		r.model = r.models.at(histogramKeyOf(r.best));
		r.refit_pairs = r.training_pairs + set_aside;
	}

	/** The winner's hits on every training pair, with the histogram it will
	 * run with, against the laser by their contrast; kept if the validation
	 * pairs, scored as every candidate was, agree. */
	void fitEdgeBias()
	{
		RangefinderParams unfitted = r.params;
		unfitted.walls.wall_fit = false;
		unfitted.scanner.sure_run = 0;
		r.edge_bias = learnEdgeBias(edgeSamples(Rangefinder(unfitted, r.model), o), lo.edge_bias_min_samples);
		if (r.edge_bias.empty()) return;
		RangefinderParams with = r.params;
		with.scanner.edge_bias = r.edge_bias;
		std::vector<double> frame_errors, frame_shortfalls;
		r.edge_bias_score = score(rangefinder(with, histogramKeyOf(r.best)), validation, frame_errors, frame_shortfalls);
		if (r.edge_bias_score < r.best.score) r.params = with;
	}

	/** The winner's doubt: the ratio, share and run of kSureRatios x
	 * kSureShares x kSureRuns whose seen-through and unsure rays on the
	 * held-aside pairs cost least; no doubt unless one costs less than none,
	 * and of equal costs the first in the grid's order. */
	void learnDoubt()
	{
		double best = 0;
		RangefinderParams p = r.params;
		p.sure_floor_share = 1.0, p.sure_obstacle_ratio = 0, p.scanner.sure_run = 0;
		r.doubt = scoreDoubt(rangefinder(p, histogramKeyOf(r.best), true), validation, best);
		r.doubt.false_free_without = r.doubt.false_free;
		const bool feet = r.model.hasObstacles();
		for (const double ratio : kSureRatios)
			for (const double share : kSureShares)
				for (const int run : kSureRuns)
				{
					if (ratio > 0 && !feet) continue;  // no feet seen: the ratio doubts nothing
					// share 1 still doubts a run of non-free pixels shorter than N: a thin or far obstacle.
					p.sure_floor_share = share, p.sure_obstacle_ratio = ratio, p.scanner.sure_run = run;
					double cost = 0;
					DoubtChoice d = scoreDoubt(rangefinder(p, histogramKeyOf(r.best), true), validation, cost);
					if (cost >= best) continue;
					best = cost;
					d.sure_floor_share = share, d.sure_obstacle_ratio = ratio, d.sure_run = run;
					d.false_free_without = r.doubt.false_free_without;
					r.doubt = d;
				}
		r.params.sure_floor_share = r.doubt.sure_floor_share, r.params.sure_obstacle_ratio = r.doubt.sure_obstacle_ratio;
		r.params.scanner.sure_run = r.doubt.sure_run;
	}
};
}  // namespace

LearningResult learnParameters(const RangefinderParams& start, const RawlogTrainingOptions& o, const LearningOptions& lo,
							   Progress* progress)
{
	o.validate();
	start.validate();
	LearningOptions::table().requireRanges(lo);
	require(!lo.thresholds.empty() && !lo.smoothings.empty() && !lo.obstacle_ratios.empty(),
			"[learning] thresholds, smoothings and obstacle_ratios need one value at least");
	Learning l(start, o, lo);
	l.makeTrainers();
	l.collect(progress);
	l.r.validation_pairs = static_cast<int>(l.validation.size());
	l.scoreGrid();
	l.scoreSteps();
	if (l.r.tried.empty()) throw std::runtime_error("no free-floor pixel was found to train on");
	if (const auto chroma = lo.chroma_on_tie ? chromaOnTie(l.r.tried, l.r.best) : std::nullopt)
	{
		l.r.overruled = l.r.best;
		l.r.best = *chroma, l.r.params = withCandidate(start, *chroma);
	}
	l.refit();
	if (lo.fit_edge_bias) l.fitEdgeBias();
	l.learnDoubt();
	l.r.separation = colourSeparation(l.r.model, Rangefinder(l.r.params, l.r.model).classifier(), l.r.params.histogram_smoothing);
	return l.r;
}

RayError learningError(const RangePair& p, bool hit, double max_range)
{
	const double cap = kDefaultMaxDifference;
	switch (p.status)
	{
		case PairStatus::Compared: return {std::min(cap, std::abs(p.difference())), p.difference() > 0};
		case PairStatus::TooDifferent: return {cap, p.difference() > 0};
		case PairStatus::OmniRejected:
		case PairStatus::OmniUnsure: return {cap, false};  // no answer is as bad as a wrong one
		case PairStatus::LaserBeyondMaxRange: return {hit ? std::min(cap, max_range - p.omni) : 0.0, true};
	}
	return {};
}

RangefinderParams withCandidate(const RangefinderParams& start, const LearnedCandidate& c)
{
	RangefinderParams p = start;
	p.threshold = c.threshold, p.obstacle_ratio = c.obstacle_ratio, p.histogram_smoothing = c.smoothing;
	p.scanner.filter.N = c.N, p.scanner.filter.K = c.K, p.scanner.boundary_model = c.boundary;
	p.scanner.step_threshold = c.step_threshold;
	p.scanner.step_sign = c.step_sign;
	p.scanner.edge_bias.clear();  // learned for the winner only, after it is chosen
	return p;
}

std::vector<PairRole> splitPairs(const LearningOptions& lo, int selected)
{
	std::vector<PairRole> roles(std::max(0, selected), PairRole::Train);
	std::vector<int> held;
	for (int s = lo.hold_out_every - 1; s < selected; s += lo.hold_out_every) held.push_back(s);
	// Keep at most max_validation_pairs, evenly spread over the held-aside ones.
	const std::size_t keep = std::min<std::size_t>(held.size(), std::max(1, lo.max_validation_pairs));
	for (std::size_t i = 0; i < held.size(); ++i) roles[held[i]] = PairRole::Unused;
	for (std::size_t j = 0; j < keep; ++j) roles[held[j * held.size() / keep]] = PairRole::Validate;
	return roles;
}

bool enoughToLearn(const LearningOptions& lo, int selected)
{
	const std::vector<PairRole> roles = splitPairs(lo, selected);
	return std::count(roles.begin(), roles.end(), PairRole::Validate) > 0 &&
		   std::count(roles.begin(), roles.end(), PairRole::Train) > 0;
}

std::string describe(const LearnedCandidate& c)
{
	char s[300];
	std::snprintf(s, sizeof s,
				  "colour space %s, %d bins, threshold %g, obstacle_ratio %g, smoothing %g, N %d, K %d, "
				  "%s boundary, step %g%s",
				  toString(c.space).c_str(), c.bins, c.threshold, c.obstacle_ratio, c.smoothing, c.N, c.K,
				  toString(c.boundary).c_str(), c.step_threshold,
				  c.step_threshold > 0 && c.step_sign != StepSign::Either ? (" " + toString(c.step_sign)).c_str() : "");
	return s;
}

namespace
{
/** P(X >= k) for X ~ Binomial(n, 1/2). */
double upperTailOfHalf(int k, int n)
{
	double tail = 0, term = std::pow(0.5, n);  // C(n, 0) / 2^n
	for (int i = 0; i <= n; ++i)
	{
		if (i >= k) tail += term;
		term = term * (n - i) / (i + 1);
	}
	return tail;
}

/** The lowest-scoring candidate of `tried` whose colour space `wanted` accepts. */
template <typename Wanted>
std::optional<LearnedCandidate> bestWhere(const std::vector<LearnedCandidate>& tried, Wanted wanted)
{
	const LearnedCandidate* best = nullptr;
	for (const LearnedCandidate& c : tried)
		if (wanted(c.space) && (!best || c.score < best->score)) best = &c;
	return best ? std::optional<LearnedCandidate>(*best) : std::nullopt;
}
}  // namespace

bool withinNoiseOf(const LearnedCandidate& a, const LearnedCandidate& b)
{
	// With fewer than 6 frames the sign test could not reject chance at 5 %
	// even were `a` worse on every frame: too few to call anything a tie.
	const std::size_t n = std::min(a.frame_errors.size(), b.frame_errors.size());
	if (n < 6) return false;
	std::vector<double> d(n);
	for (std::size_t f = 0; f < n; ++f) d[f] = a.frame_errors[f] - b.frame_errors[f];
	const double mean = std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(n);
	double sq = 0;
	for (const double x : d) sq += (x - mean) * (x - mean);
	const int worse = static_cast<int>(std::count_if(d.begin(), d.end(), [](double x) { return x > 0; }));
	const int differ = worse + static_cast<int>(std::count_if(d.begin(), d.end(), [](double x) { return x < 0; }));
	const double standard_error = std::sqrt(sq / static_cast<double>(n - 1) / static_cast<double>(n));
	// A few frames with large errors make the standard error large; the sign
	// test does not let them hide `a` being worse on nearly every frame.
	const bool worse_on_most = 2 * worse > differ && 2 * upperTailOfHalf(worse, differ) < 0.05;
	return mean <= 2.0 * standard_error && !worse_on_most;
}

std::optional<LearnedCandidate> chromaOnTie(const std::vector<LearnedCandidate>& tried, const LearnedCandidate& lowest)
{
	if (lowest.space == ColourSpace::Chroma) return std::nullopt;
	const auto chroma = bestWhere(tried, [](ColourSpace s) { return s == ColourSpace::Chroma; });
	if (!chroma || !withinNoiseOf(*chroma, lowest)) return std::nullopt;
	return chroma;
}

std::string candidateColumns()
{
	return "colour_space,bins,threshold,obstacle_ratio,histogram_smoothing,N,K,boundary_model,step_threshold,step_sign";
}

std::string candidateColumns(const LearnedCandidate& c)
{
	char row[300];
	std::snprintf(row, sizeof row, "%s,%d,%g,%g,%g,%d,%d,%s,%g,%s", toString(c.space).c_str(), c.bins, c.threshold, c.obstacle_ratio, c.smoothing, c.N, c.K, toString(c.boundary).c_str(),
				  c.step_threshold, toString(c.step_sign).c_str());
	return row;
}

std::string spaceSeparated(const std::vector<double>& values)
{
	std::string cell;
	for (std::size_t i = 0; i < values.size(); ++i)
	{
		char v[32];
		std::snprintf(v, sizeof v, i ? " %.6f" : "%.6f", values[i]);
		cell += v;
	}
	return cell;
}

std::string candidatesCsv(const LearningResult& r)
{
	std::string csv = candidateColumns() + ",score_m,frame_errors_m\n";
	for (const LearnedCandidate& c : r.tried)
	{
		char row[40];
		std::snprintf(row, sizeof row, ",%.6f,", c.score);
		csv += candidateColumns(c) + row + spaceSeparated(c.frame_errors) + "\n";
	}
	return csv;
}

std::optional<LearnedCandidate> bestInOtherSpace(const LearningResult& r)
{
	return bestWhere(r.tried, [&](ColourSpace s) { return s != r.best.space; });
}

std::vector<LearnedCandidate> nearestRivals(const LearningResult& r, std::size_t n)
{
	std::vector<LearnedCandidate> rivals;
	for (const auto& c : r.tried)
		if (describe(c) != describe(r.best)) rivals.push_back(c);
	const std::size_t k = std::min(n, rivals.size());
	std::partial_sort(rivals.begin(), rivals.begin() + k, rivals.end(),
					  [](const LearnedCandidate& a, const LearnedCandidate& b) { return a.score < b.score; });
	rivals.resize(k);
	return rivals;
}

/** The learned ini's lines on the nearest rivals. */
std::string rivalsComment(const LearningResult& r)
{
	std::string out;
	for (const auto& c : nearestRivals(r))
	{
		char line[400];
		std::snprintf(line, sizeof line, ";   %+.1f mm: %s\n", 1000 * (c.score - r.best.score), describe(c).c_str());
		out += line;
	}
	return out.empty() ? out : "; The nearest rivals, by how much more (or less) their mean error was:\n" + out;
}

std::string poorLearningWarning(const LearningResult& r)
{
	if (!(r.best.score > kPoorLearningScore)) return {};
	char s[300];
	std::snprintf(s, sizeof s,
				  "the best candidate's mean error on the held-aside frames is %.3f m (above %.2f m): colour does not "
				  "separate this floor from what stands on it; expect poor ranges (docs/users.md, What to expect)",
				  r.best.score, kPoorLearningScore);
	return s;
}

namespace
{
/** The learned ini's lines on the best candidate of the other colour space, and a tie CHROMA kept. */
std::string otherSpaceComment(const LearningResult& r)
{
	std::string out;
	if (const auto other = bestInOtherSpace(r))
	{
		char line[600];
		std::snprintf(line, sizeof line,
					  "; The best in another colour space: %s;\n"
					  "; mean error %.4f m (%.1f mm %s). When that is close, train both and score each on a\n"
					  "; later part of the log (docs/users.md): the held-aside frames cannot tell them apart.\n",
					  describe(*other).c_str(), other->score, 1000 * std::abs(other->score - r.best.score),
					  other->score >= r.best.score ? "more" : "less");
		out = line;
	}
	if (r.overruled)
		out += "; CHROMA was kept: the lower score above is within the held-aside frames' noise\n"
			   "; (docs/method.md), and CHROMA holds through changes of light they do not show.\n";
	return out;
}

/** The learned ini's lines on the edge bias (none when none was learned). */
std::string edgeBiasComment(const LearningResult& r)
{
	if (r.edge_bias.empty()) return {};
	char line[400];
	const bool kept = !r.params.scanner.edge_bias.empty();
	std::snprintf(line, sizeof line,
				  "; Edge bias (by the hit's contrast, docs/method.md), learned on every training pair: mean error\n"
				  "; %.4f m with it on the held-aside pairs; %s.\n",
				  r.edge_bias_score, kept ? "kept (edge_bias below)" : "not kept, it did not lower the winner's");
	return line;
}

/** The learned ini's lines on the doubt chosen, and on how colour separates this room. */
std::string doubtComment(const LearningResult& r)
{
	char line[700];
	std::snprintf(line, sizeof line,
				  "; Doubt (docs/method.md): sure_floor_share %g, sure_obstacle_ratio %g, sure_run %d, chosen on the\n"
				  "; held-aside pairs; there the scan read free more than 25 cm past %.1f %% of the laser's returns\n"
				  "; within max range (%.1f %% without doubt), with %.1f %% of its rays unsure.\n; %s.\n",
				  r.doubt.sure_floor_share, r.doubt.sure_obstacle_ratio, r.doubt.sure_run, 100 * r.doubt.false_free,
				  100 * r.doubt.false_free_without, 100 * r.doubt.unsure, separationLine(r.separation).c_str());
	return line;
}
}  // namespace

std::string learnedIni(const LearningResult& r, const std::string& section)
{
	char head[900];
	std::snprintf(head, sizeof head,
				  "%s%zu candidates scored against the laser on %d held-aside\n"
				  "; image/laser pairs (interleaved, as seen; histograms trained on %d others). The winner:\n"
				  "; %s;\n"
				  "; mean error %.4f m. The histogram file written with this ini was made that way (trained again on all %d pairs);\n"
				  "; to train one by hand, use the same colour space and bins.\n",
				  kLearnedIniBegins, r.tried.size(), r.validation_pairs, r.training_pairs, describe(r.best).c_str(),
				  r.best.score, r.refit_pairs);
	const std::string warning = poorLearningWarning(r);
	return head + otherSpaceComment(r) + edgeBiasComment(r) + rivalsComment(r) + doubtComment(r) +
		   (warning.empty() ? "" : "; WARNING: " + warning + "\n") + "[" + section + "]\n" + r.params.asIni();
}

const OptionsTable<LearningOptions>& LearningOptions::table()
{
	using L = LearningOptions;
	static const auto t =
		OptionsTable<L>()
			.add("thresholds", "-", "the Theta values tried", [](L& l) -> auto& { return l.thresholds; })
			.within(kThresholdRange)
			.add("smoothings", "bins", "the histogram_smoothing values tried", [](L& l) -> auto& { return l.smoothings; })
			.within(kSmoothingRange)
			.add("obstacle_ratios", "-", "the obstacle_ratio values tried (0: the one-class model)",
				 [](L& l) -> auto& { return l.obstacle_ratios; })
			.within(kObstacleRatioRange)
			.add("step_thresholds", "-",
				 "the brightness step's step_threshold values tried on the best candidates (none: not tried)",
				 [](L& l) -> auto& { return l.step_thresholds; })
			.within(Range::openLow(0, 5))
			.add("step_candidates", "-", "how many of the best candidates the brightness step is tried on",
				 [](L& l) -> auto& { return l.step_candidates; })
			.within(Range::closed(1, 1000))
			.add("hold_out_every", "-", "every hold_out_every-th selected pair is held aside to score on",
				 [](L& l) -> auto& { return l.hold_out_every; })
			.within(Range::closed(2, 1000))
			.add("max_validation_pairs", "-", "at most this many held-aside pairs (their images are kept in memory)",
				 [](L& l) -> auto& { return l.max_validation_pairs; })
			.within(Range::closed(1, 10000))
			.add("chroma_on_tie", "bool",
				 "take the best CHROMA candidate when the lowest score is behind it by no more than the held-aside "
				 "frames' noise",
				 [](L& l) -> auto& { return l.chroma_on_tie; })
			.add("fit_edge_bias", "bool", "learn the winner's edge bias and keep it when the held-aside pairs agree",
				 [](L& l) -> auto& { return l.fit_edge_bias; })
			.add("edge_bias_min_samples", "-", "laser-confirmed hits a contrast bin of the edge bias needs",
				 [](L& l) -> auto& { return l.edge_bias_min_samples; })
			.within(Range::closed(1, 1e6));
	return t;
}

}  // namespace omnirange
