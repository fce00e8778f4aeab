#include "omnirange_eval/Accuracy.h"

#include <omnirange/core/ScanFusion.h>
#include <omnirange/io/RawlogProcessor.h>

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <cstdio>

namespace omnirange::eval
{
void AccuracyStats::add(const RangePair& p)
{
	if (p.status != PairStatus::LaserBeyondMaxRange)
	{
		// The laser sees the floor end within range: is it claimed free past there?
		++laser_in_range;
		laser_false_free += p.status == PairStatus::OmniRejected || p.omni > p.laser + kFalseFreeMargin;
	}
	switch (p.status)
	{
		case PairStatus::LaserBeyondMaxRange: ++laser_beyond; return;
		case PairStatus::TooDifferent: ++too_different; return;
		case PairStatus::OmniRejected: ++omni_rejected; return;
		case PairStatus::OmniUnsure: ++omni_unsure; return;
		case PairStatus::Compared: break;
	}
	++compared;
	const double d = p.difference();
	sum_abs += std::abs(d);
	sum_signed += d;
	sum_pct += 100.0 * std::abs(d) / p.laser;
	differences.push_back(d);
}

namespace
{
using mrpt::obs::CObservation2DRangeScan;

/** One moment: an omnicam scan and, of each other label, the scan taken nearest to it
 * within max_dt, whatever their order in the rawlog. */
struct Moment
{
	CObservation2DRangeScan::Ptr omni, laser, fused, truth, body;
};

/** The last two scans of each label read: an omnicam scan's moment is made when the
 * next one comes (or the rawlog ends), of the nearer of the two of each label. */
class Moments
{
   public:
	explicit Moments(const AccuracyOptions& o) : o_(o) {}
	/** Feeds a scan; returns the moment the previous omnicam scan made, when this is the next one. */
	std::optional<Moment> add(const CObservation2DRangeScan::Ptr& scan)
	{
		std::optional<Moment> done;
		if (scan->sensorLabel == o_.omni_label) done = finish(), pending_ = scan;
		else
		{
			auto& last = last_[scan->sensorLabel];
			last[0] = last[1], last[1] = scan;
		}
		return done;
	}
	/** The last omnicam scan's moment (at the rawlog's end). */
	std::optional<Moment> finish() const
	{
		if (!pending_) return std::nullopt;
		Moment m;
		m.omni = pending_;
		m.laser = nearest(o_.laser_label), m.fused = nearest(o_.fused_label);
		m.truth = nearest(o_.truth_label), m.body = nearest(o_.body_label);
		return m;
	}

   private:
	CObservation2DRangeScan::Ptr nearest(const std::string& label) const
	{
		const auto it = last_.find(label);
		if (it == last_.end()) return nullptr;
		CObservation2DRangeScan::Ptr best;
		double best_dt = o_.max_dt;
		for (const auto& s : it->second)
			if (s)
				if (const double dt = std::abs(mrpt::system::timeDifference(pending_->timestamp, s->timestamp)); dt <= best_dt)
					best = s, best_dt = dt;
		return best;
	}

	const AccuracyOptions& o_;
	CObservation2DRangeScan::Ptr pending_;
	std::map<std::string, std::array<CObservation2DRangeScan::Ptr, 2>> last_;
};

/** `laser` seen from the omnicam along the rays of `omni` (laserAlong()): a
 * return valid at its range, no return invalid at the laser's max range; and
 * which rays the laser sees. */
CObservation2DRangeScan laserOnOmniRays(const CObservation2DRangeScan& laser, const CObservation2DRangeScan& omni,
										std::vector<char>& seen)
{
	CObservation2DRangeScan s = omni;
	s.sensorLabel = laser.sensorLabel;
	s.setScanHasIntensity(false);
	const auto along = laserAlong(laser, omni);
	seen.assign(along.size(), 0);
	for (std::size_t i = 0; i < along.size(); ++i)
	{
		const bool hit = along[i].kind == LaserReading::Kind::Return;
		seen[i] = along[i].kind != LaserReading::Kind::Unseen;
		s.setScanRange(i, static_cast<float>(hit ? along[i].range : laser.maxRange));
		s.setScanRangeValidity(i, hit);
	}
	return s;
}

/** Scores the moment's laser, omnicam and fused scans on the rays the laser sees. */
void scoreInView(const Moment& m, AccuracyResult& r)
{
	if (!m.omni || !m.laser || (!m.truth && !m.body)) return;
	std::vector<char> seen;
	const CObservation2DRangeScan laser = laserOnOmniRays(*m.laser, *m.omni, seen);
	const double reach = m.omni->maxRange;
	for (const auto& [truth, stats] : {std::pair{m.truth, &r.truth_in_view}, std::pair{m.body, &r.body_in_view}})
	{
		if (!truth) continue;
		for (const CObservation2DRangeScan* scan : std::initializer_list<const CObservation2DRangeScan*>{&laser, m.omni.get(), m.fused.get()})
			if (scan) (*stats)[scan->sensorLabel].add(*truth, *scan, seen, reach);
	}
}
}  // namespace

double AccuracyStats::excludedFraction() const
{
	const auto n = total();
	return n ? static_cast<double>(laser_beyond + too_different) / n : 0.0;
}

AccuracyResult evaluateAccuracy(const std::string& rawlog, const AccuracyOptions& o, Progress* progress)
{
	using mrpt::obs::CObservation2DRangeScan;
	// A bound past any omnicam's reach pairs nothing more, and makes the
	// histogram's bins without end.
	require(o.max_difference > 0 && o.max_difference <= kMaxRangeDifference,
			"accuracy: max_difference must be within (0, " + formatDouble(kMaxRangeDifference) + "] m");
	require(o.first >= 0, "accuracy: first must be >= 0");
	requirePairingDt(o.max_dt);
	RawlogProcessor loop(rawlog);
	AccuracyResult r;
	int seen = 0, truth_seen = 0;  // pairs so far, scored from `first` on
	r.csv = std::string(kPairsCsvBegins) + "bearing_rad,laser_m,omni_m,difference_m,status\n";
	loop.onPair<CObservation2DRangeScan, CObservation2DRangeScan>(
		o.laser_label, o.omni_label, o.max_dt,
		[&](const CObservation2DRangeScan::Ptr& laser, const CObservation2DRangeScan::Ptr& omni) {
			if (seen++ < o.first) return;
			for (const RangePair& p : pairScans(*laser, *omni, o.max_difference))
			{
				r.stats.add(p);
				char line[200];
				std::snprintf(line, sizeof line, "%d,%d,%d,%.5f,%.4f,%.4f,%.4f,%s\n", r.frames, p.laser_ray,
							  p.omni_ray, p.bearing, p.laser, p.omni, p.difference(), toString(p.status).c_str());
				r.csv += line;
			}
			++r.frames;
		});
	loop.onPair<CObservation2DRangeScan, CObservation2DRangeScan>(
		o.truth_label, o.omni_label, o.max_dt,
		[&](const CObservation2DRangeScan::Ptr& truth, const CObservation2DRangeScan::Ptr& omni) {
			if (truth_seen++ >= o.first) r.truth.add(*truth, *omni);
		});
	// The scans in view, each moment scored when the next omnicam scan begins another.
	Moments moments(o);
	int scored = 0;
	const auto score = [&](const std::optional<Moment>& m) {
		if (m && m->laser && scored++ >= o.first) scoreInView(*m, r);
	};
	loop.on<CObservation2DRangeScan>("", [&](const CObservation2DRangeScan::Ptr& scan) { score(moments.add(scan)); });
	loop.run(progress);
	score(moments.finish());
	if (seen == 0) throw std::runtime_error(loop.describeNoPair());
	if (r.frames == 0)
		throw std::runtime_error("all " + std::to_string(seen) + " scan pairs of '" + rawlog + "' come before first = " +
								 std::to_string(o.first));
	// A mean over no ray would read 0.0000 m, the best score there is. A scan
	// unsure on every ray the laser sees says so, and is a result: its means
	// are left out (AccuracyResult::table, metricsOf).
	// With the truth the run is scored all the same: the laser may see nothing within the omnicam's reach.
	if (r.stats.compared == 0 && r.stats.omni_unsure == 0 && r.truth.frames == 0 && r.truth_in_view.empty() &&
		r.body_in_view.empty())
		throw std::runtime_error("no ray of '" + rawlog + "' could be compared with the laser (" +
								 std::to_string(r.stats.total()) +
								 " pairs, none within the max difference): are the sensors' poses right?");
	return r;
}

std::string AccuracyResult::table(double max_difference) const
{
	const auto& s = stats;
	const double n = static_cast<double>(std::max<std::size_t>(1, s.total()));
	char means[3][32] = {"-", "-", "-"};  // no ray compared: no mean
	if (s.compared > 0)
	{
		std::snprintf(means[0], sizeof means[0], "%.4f m", s.meanAbs());
		std::snprintf(means[1], sizeof means[1], "%.3f %%", s.meanPercent());
		std::snprintf(means[2], sizeof means[2], "%+.4f m", s.meanSigned());
	}
	char row[512];
	std::snprintf(row, sizeof row,
				  " compared | excluded: laser beyond omni max range | excluded: difference > %.2f m "
				  "| omni ray rejected | omni ray unsure | mean absolute difference | mean percentage difference | signed mean "
				  "| false free |\n"
				  "|---|---|---|---|---|---|---|---|---|---|---|---|\n"
				  "| %d | %zu | %zu | %zu (%.1f %%) | %zu (%.1f %%) | %zu | %zu (%.1f %%) | %s | %s | %s | %.1f %% |\n",
				  max_difference, frames, s.total(), s.compared, s.laser_beyond, 100.0 * s.laser_beyond / n,
				  s.too_different, 100.0 * s.too_different / n, s.omni_rejected, s.omni_unsure,
				  100.0 * s.omni_unsure / n, means[0], means[1], means[2], 100.0 * s.falseFree());
	return kAccuracyTableBegins + std::string(row);
}

std::string AccuracyResult::inViewTable() const
{
	if (truth_in_view.empty() && body_in_view.empty()) return {};
	std::string o =
		"## The laser, the omnicam and the fused scan on the same rays\n\n"
		"Every ray the laser sees, out to the omnicam's max range, against where the floor ends (TRUTH) and against "
		"what the robot would strike (BODY: the nearest solid below its height, a floating body at its face). "
		"Missed: the sensor claims free more than 5 cm past the truth. False obstacles: a return where nothing is "
		"within the max range. FUSED: the nearer of the laser and a sure omnicam hit per ray (docs/method.md).\n\n"
		"| truth | sensor | rays | within 5 cm | missed | unsure | false obstacles |\n|---|---|---|---|---|---|---|\n";
	const auto percent = [](std::size_t part, std::size_t whole) {
		char b[32];
		std::snprintf(b, sizeof b, "%.1f %%", 100.0 * part / std::max<std::size_t>(1, whole));
		return std::string(b);
	};
	for (const auto& [name, view] : {std::pair{"TRUTH", &truth_in_view}, std::pair{"BODY", &body_in_view}})
		for (const auto& [label, t] : *view)
		{
			const TruthBand all = t.all();
			o += std::string("| ") + name + " | " + label + " | " + std::to_string(all.rays) + " | " +
				 percent(all.within_5cm, all.rays) + " | " + percent(all.false_free, all.rays) + " | " +
				 percent(t.allUnsure(), t.allRays()) + " | " + percent(t.false_obstacles, t.open_rays) + " |\n";
		}
	return o + "\n";
}

}  // namespace omnirange::eval
