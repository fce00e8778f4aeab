// The experiment's report (Markdown) and metrics, from what a run measured.
#include "omnirange_eval/Experiment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace omnirange::eval
{
namespace
{
std::string fmt(const char* f, double v)
{
	char b[64];
	std::snprintf(b, sizeof b, f, v);
	return b;
}

void writeMapsTable(std::ostream& o, const ExperimentResults& r)
{
	o << "| localisation | sensor | occupied cells | precision | recall | wall thickness | ATE RMSE | final pose error |\n"
	  << "|---|---|---|---|---|---|---|---|\n";
	for (const auto& s : r.sensors)
		o << "| ground truth | " << s.label << " | " << s.gt.occupied << " | " << fmt("%.3f", s.gt.precision) << " | "
		  << fmt("%.3f", s.gt.recall) << " | " << fmt("%.3f m", s.gt.thickness) << " | - | - |\n";
	const auto slamRow = [&](const std::string& engine, const SensorMaps& s, const MapMetrics& g, const PathError& p) {
		o << "| " << engine << " + odometry | " << s.label << " | " << g.occupied << " | " << fmt("%.3f", g.precision)
		  << " | " << fmt("%.3f", g.recall) << " | " << fmt("%.3f m", g.thickness) << " | " << fmt("%.3f m", p.ate_rmse)
		  << (worseThanOdometry(p.ate_rmse, r.odometry_path.ate_rmse) ? kWorseThanOdometry : "") << " | " << fmt("%.3f m", p.final_xy) << ", " << fmt("%.1f deg", p.final_yaw * 180 / M_PI) << " |\n";
	};
	const auto& odo = r.odometry_path;
	o << "| odometry alone | - | - | - | - | - | " << fmt("%.3f m", odo.ate_rmse) << " | " << fmt("%.3f m", odo.final_xy)
	  << ", " << fmt("%.1f deg", odo.final_yaw * 180 / M_PI) << " |\n";
	for (const auto& s : r.sensors) slamRow("icp-slam", s, s.icp, s.icp_path);
	for (const auto& s : r.sensors) slamRow("guarded ICP", s, s.guarded, s.guarded_path);
	for (const auto& s : r.sensors)
		if (!s.rbpf_ini.empty()) slamRow("rbpf-slam", s, s.rbpf, s.rbpf_path);
}

void writeCheckRegion(std::ostream& o, const ExperimentConfig& c, const ExperimentResults& r)
{
	const auto& b = c.check_box;
	o << "## Check region (" << b[0] << ", " << b[1] << "), " << b[2] << " x " << b[3]
	  << " m\n\nOccupied cells within 0.15 m of the box, as a length (cells x resolution): a wall along its " << b[2]
	  << " m side gives about that.\n\n| map |";
	for (const auto& s : r.sensors) o << " " << s.label << " |";
	o << "\n|---|---|---|\n| ground-truth poses |";
	for (const auto& s : r.sensors) o << " " << fmt("%.2f m", s.gt_check_marked) << " |";
	o << "\n| icp-slam |";
	for (const auto& s : r.sensors) o << " " << fmt("%.2f m", s.icp_check_marked) << " |";
	o << "\n\n";
}
}  // namespace

Metrics metricsOf(const ExperimentResults& r)
{
	Metrics m;
	const auto& a = r.accuracy.stats;
	m["frames"] = r.simulated.frames;
	m["training_pairs"] = r.training_pairs;
	m["training_until"] = r.training_until;
	m["omni_hit_fraction"] = r.omni_hit_fraction;
	if (r.separation.known)  // training saw no obstacle's feet: nothing measured
	{
		m["colour_separation_auc"] = r.separation.auc;
		m["colour_feet_read_free"] = r.separation.feet_read_free;
	}
	if (a.compared > 0)  // every ray the laser sees unsure: no mean to give
	{
		m["accuracy_mean_abs"] = a.meanAbs();
		m["accuracy_mean_percent"] = a.meanPercent();
		m["accuracy_signed_mean"] = a.meanSigned();
	}
	m["accuracy_compared"] = double(a.compared);
	m["accuracy_excluded_fraction"] = a.excludedFraction();
	m["laser_false_free"] = a.falseFree();
	m["laser_unsure"] = a.unsure();
	if (r.accuracy.truth.frames > 0)
	{
		const TruthBand t = r.accuracy.truth.all();
		const double n = static_cast<double>(std::max<std::size_t>(1, t.rays));
		m["truth_within_2cm"] = t.within_2cm / n;
		m["truth_within_5cm"] = t.within_5cm / n;
		m["truth_mean_abs"] = t.meanAbs();
		m["truth_median_abs"] = t.medianAbs();
		m["truth_missed"] = t.missed() / n;
		m["truth_false_free"] = t.false_free / n;
		m["truth_unsure"] = double(r.accuracy.truth.allUnsure()) / std::max<std::size_t>(1, r.accuracy.truth.allRays());
		m["truth_within_5cm_confident"] = t.within_5cm / std::max(1.0, n - t.unsure);
		m["truth_false_obstacles"] =
			double(r.accuracy.truth.false_obstacles) / std::max<std::size_t>(1, r.accuracy.truth.open_rays);
	}
	// The same rays for every sensor (writeInViewTable()): MODE_LABEL_WHAT, as the maps' keys.
	for (const auto& [mode, view] : {std::pair{"truth_", &r.accuracy.truth_in_view}, std::pair{"body_", &r.accuracy.body_in_view}})
		for (const auto& [label, t] : *view)
		{
			const TruthBand all = t.all();
			const double n = static_cast<double>(std::max<std::size_t>(1, all.rays));
			m[mode + label + "_missed"] = all.false_free / n;
			m[mode + label + "_within_5cm"] = all.within_5cm / n;
			m[mode + label + "_unsure"] = double(t.allUnsure()) / std::max<std::size_t>(1, t.allRays());
			m[mode + label + "_false_obstacles"] = double(t.false_obstacles) / std::max<std::size_t>(1, t.open_rays);
		}
	m["odometry_ate_rmse"] = r.odometry_path.ate_rmse;
	m["odometry_final_xy"] = r.odometry_path.final_xy;
	m["odometry_final_yaw"] = r.odometry_path.final_yaw;
	for (const auto& s : r.sensors)
	{
		const auto maps = [&](const std::string& mode, const MapMetrics& g) {
			m[mode + s.label + "_precision"] = g.precision;
			m[mode + s.label + "_recall"] = g.recall;
			m[mode + s.label + "_thickness"] = g.thickness;
		};
		const auto path = [&](const std::string& mode, const PathError& p) {
			m[mode + s.label + "_ate_rmse"] = p.ate_rmse;
			m[mode + s.label + "_final_xy"] = p.final_xy;
			m[mode + s.label + "_final_yaw"] = p.final_yaw;
			m[mode + s.label + "_keyframes"] = p.poses;
		};
		maps("gt_", s.gt);
		maps("icp_", s.icp), path("icp_", s.icp_path);
		maps("guarded_", s.guarded), path("guarded_", s.guarded_path);
		m["guarded_" + s.label + "_loops"] = s.guarded_loops;
		if (!s.rbpf_ini.empty()) maps("rbpf_", s.rbpf), path("rbpf_", s.rbpf_path);
		if (r.has_check_region)
		{
			m["gt_" + s.label + "_check_region_marked"] = s.gt_check_marked;
			m["icp_" + s.label + "_check_region_marked"] = s.icp_check_marked;
		}
	}
	m["seconds"] = r.seconds;
	return m;
}

bool isMetricKey(const std::string& key)
{
	// Every key a run can write: a run with truth, a check region and one
	// sensor labelled "L" that runs every engine.
	static const Metrics every = [] {
		ExperimentResults r;
		r.accuracy.truth.frames = 1, r.accuracy.stats.compared = 1, r.separation.known = true;
		r.has_check_region = true;
		r.sensors.resize(1), r.sensors[0].label = "L", r.sensors[0].rbpf_ini = "x";
		r.accuracy.truth_in_view["L"], r.accuracy.body_in_view["L"];
		return metricsOf(r);
	}();
	if (every.count(key)) return true;
	// MODE_LABEL_WHAT: the label any run of letters, digits and '_'.
	const auto first = key.find('_');
	for (const auto& [k, v] : every)
	{
		const auto l = k.find("_L_");
		if (l == std::string::npos || first != l || key.compare(0, l + 1, k, 0, l + 1) != 0) continue;
		const std::string suffix = k.substr(l + 2);  // "_precision"
		if (key.size() <= l + 1 + suffix.size() || key.compare(key.size() - suffix.size(), suffix.size(), suffix) != 0)
			continue;
		const std::string label = key.substr(l + 1, key.size() - suffix.size() - l - 1);
		if (!label.empty() && label.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_") ==
								  std::string::npos)
			return true;
	}
	return false;
}

std::string reportMarkdown(const ExperimentConfig& c, const ExperimentResults& r)
{
	const double max_difference = AccuracyOptions{}.max_difference;
	std::ostringstream o;
	o << "# omnirange experiment: " << c.name << "\n\n"
	  << (r.camera_mismatch.empty()
			  ? std::string()
			  : "**Warning:** the robot's camera, which made the images, is not `[rangefinder]`'s, which read them: they "
				"differ in " + joined(r.camera_mismatch) + ". Every range below is read through the wrong camera.\n\n")
	  << "From `" << c.ini_file << "`: " << r.simulated.frames << " simulated frames ("
	  << fmt("%.0f", r.simulated.route_seconds) << " s of route), histogram trained on " << r.training_pairs
	  << " image/laser pairs from the route's first " << r.training_until << " frames; everything below is scored on the "
	  << (r.simulated.frames - r.training_until) << " frames after them."
	  << (r.learned.empty() ? "" : " Parameters learned against the laser: " + r.learned + ".")
	  << " The whole run took " << fmt("%.0f", r.seconds) << " s. The robot: `" << c.robot << "`.\n\n"
	  << "Training's own word on this room: " << separationLine(r.separation) << ".\n\n"
	  << "## Accuracy: laser against omnicam (paper Table II, Fig. 9)\n\n"
	  << r.accuracy.table(max_difference) << "\n![differences](accuracy_histogram.png)\n\n"
	  << (r.accuracy.truth.frames > 0 ? "## Accuracy: omnicam against the true floor boundary\n\nEvery omnicam ray against "
										 "where the simulator knows the floor really ends along its bearing (the TRUTH "
										 "scans). Missed: the floor ends within the max range but the ray has no hit. Unsure: the ray claims free "
										 "floor only to its range (docs/method.md, \"Doubt\"). False free: a ray not "
										 "unsure that claims free floor more than 5 cm past the truth (no hit, or a hit "
										 "beyond it), or an unsure one whose extent is.\n\n" +
											r.accuracy.truth.table() + "\n"
									  : std::string())
	  << r.accuracy.inViewTable() << "All pairs: `accuracy_pairs.csv`. What the histogram learned from (paper Fig. 1): "
	  << "![bird's-eye view](fig1_birdseye.png) ![laser free region](fig1_laser.png) ![fused](fig1_fused.png)\n\n"
	  << "## Maps against the world's true map\n\n"
	  << "Occupied cells count as correct within " << c.match_tolerance << " m of a true wall (precision); "
	  << "true wall surface within " << c.rangefinder.scanner.max_range
	  << " m of the path counts as found within the same tolerance (recall). "
	  << "Wall thickness: occupied area over the length of its centre line.\n\n";
	writeMapsTable(o, r);
	o << "\n![maps with ground-truth poses](maps_gt.png)\n\n![maps from icp-slam](maps_icp.png)\n\n"
	  << "Guarded ICP: icp-slam's matching with the same ini, where the odometry refuses a match that jumps "
		 "farther than the wheels can err and keeps its own estimate along directions the scan cannot fix, "
		 "and whose keyframes form a pose graph that closes loops (the ini's [loop_closure]; docs/method.md)."
		 "\n\n![maps from the guarded matcher](maps_guarded.png)\n\n";
	const bool rbpf = std::any_of(r.sensors.begin(), r.sensors.end(), [](const auto& s) { return !s.rbpf_ini.empty(); });
	if (rbpf)
		o << "rbpf-slam is a particle filter: its figures change with its ini's RANDOM_SEED.\n\n"
		  << "![maps from rbpf-slam](maps_rbpf.png)\n\n";
	if (c.hasCheckRegion()) writeCheckRegion(o, c, r);
	return o.str();
}

}  // namespace omnirange::eval
