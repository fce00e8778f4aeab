#include "omnirange_eval/Experiment.h"

#include "omnirange_eval/GridMaps.h"

#include <omnirange/Accuracy.h>
#include <omnirange/AtomicWrite.h>
#include <omnirange/RawlogScan.h>
#include <omnirange/RawlogTraining.h>
#include <omnirange_sim/Simulator.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace omnirange::eval
{
namespace
{
/** Runs a shell command in `dir` with no standard input; its output goes to `log`. */
void runProgram(const std::string& dir, const std::string& cmd, const std::string& log)
{
	const std::string full = "cd '" + dir + "' && (" + cmd + ") </dev/null >'" + log + "' 2>&1";
	if (std::system(full.c_str()) != 0)
	{
		std::ifstream f(dir + "/" + log);
		std::string line, last;
		while (std::getline(f, line))
			if (!line.empty()) last = line;
		throw std::runtime_error("'" + cmd + "' failed (" + dir + "/" + log + "): " + last);
	}
}

/** Maps side by side, each with its title above, all the same size. */
cv::Mat sideBySide(const std::vector<std::pair<std::string, cv::Mat>>& maps)
{
	std::vector<cv::Mat> cols;
	for (const auto& [title, m] : maps)
	{
		cv::Mat col(m.rows + 36, m.cols, CV_8UC3, cv::Scalar(255, 255, 255));
		m.copyTo(col(cv::Rect(0, 36, m.cols, m.rows)));
		cv::putText(col, title, {8, 25}, cv::FONT_HERSHEY_SIMPLEX, 0.7, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
		cv::rectangle(col, cv::Rect(0, 0, col.cols, col.rows), cv::Scalar(120, 120, 120));
		cols.push_back(col);
	}
	cv::Mat out;
	cv::hconcat(cols, out);
	return out;
}

mrpt::maps::COccupancyGridMap2D loadGrid(const std::string& file)
{
	mrpt::maps::COccupancyGridMap2D g;
	mrpt::io::CFileGZInputStream f;
	if (!f.open(file)) throw std::runtime_error("cannot open grid map '" + file + "'");
	mrpt::serialization::archiveFrom(f) >> g;
	return g;
}

std::string fmt(const char* f, double v)
{
	char b[64];
	std::snprintf(b, sizeof b, f, v);
	return b;
}
}  // namespace

Experiment::Experiment() : mrpt::system::COutputLogger("omnirange-experiment") {}

Metrics Experiment::run(const ExperimentConfig& c)
{
	const auto t0 = std::chrono::steady_clock::now();
	fs::create_directories(c.output);
	const std::string out = fs::absolute(c.output).string();
	Metrics m;
	std::ostringstream report;
	const int kStages = 7;
	int stage = 0;
	const auto step = [&](const std::string& name, const std::function<void()>& body) {
		MRPT_LOG_INFO_STREAM("[" << ++stage << "/" << kStages << "] " << name);
		try
		{
			body();
		}
		catch (const std::exception& e)
		{
			throw std::runtime_error("stage '" + name + "' failed: " + std::string(e.what()));
		}
	};

	// 1. The dataset, from the simulator.
	const std::string dataset = out + "/dataset/" + c.name + ".rawlog";
	sim::SimSummary simulated;
	step("simulate", [&] {
		fs::create_directories(out + "/dataset");
		sim::SimOptions o;
		o.world_file = c.world;
		o.route_file = c.route;
		o.robot_ini = c.robot;
		o.output = dataset;
		o.max_frames = c.max_frames;
		sim::Simulator s;
		s.setMinLoggingLevel(mrpt::system::LVL_ERROR);
		simulated = s.run(o);
		m["frames"] = simulated.frames;
	});

	// 2. The histogram, trained against the laser (paper §III-A1).
	const std::string hist = out + "/floor.hist";
	RawlogTrainingResult trained;
	step("train", [&] {
		RawlogTrainingOptions o;
		o.input = dataset;
		o.every = c.train_every;
		o.figures_prefix = out + "/fig1";
		o.figures_frame = 0;
		trained = trainFromRawlog(c.rangefinder, o);
		trained.histogram.save(hist);
		m["training_pairs"] = trained.used;
	});

	// 3. The omnicam scans.
	const std::string scanned = out + "/scanned.rawlog";
	step("scan", [&] {
		const Rangefinder rf(c.rangefinder, trained.histogram);
		RawlogScanOptions o;
		o.input = dataset;
		o.output = scanned;
		const auto s = scanRawlog(rf, o);
		m["omni_hit_fraction"] = double(s.hits) / std::max<std::size_t>(1, s.rays);
	});

	// 4. The accuracy test (Table II, Fig. 9).
	AccuracyResult acc;
	step("accuracy", [&] {
		acc = evaluateAccuracy(scanned, AccuracyOptions{});
		writeFileAtomically(out + "/accuracy_pairs.csv", acc.csv);
		writeImageAtomically(out + "/accuracy_histogram.png", differenceHistogram(acc.stats.differences, c.name));
		writeFileAtomically(out + "/accuracy_table.md", acc.table(1.25));
		m["accuracy_mean_abs"] = acc.stats.meanAbs();
		m["accuracy_mean_percent"] = acc.stats.meanPercent();
		m["accuracy_signed_mean"] = acc.stats.meanSigned();
		m["accuracy_compared"] = double(acc.stats.compared);
		m["accuracy_excluded_fraction"] = acc.stats.excludedFraction();
	});

	// 5. Maps with ground-truth poses, against the true map.
	const auto truth = loadGrid(out + "/dataset/" + c.name + "_truemap.gridmap.gz");
	const auto gt = groundTruthPath(dataset);
	const double reach = c.rangefinder.scanner.max_range;
	std::map<std::string, MapMetrics> gt_maps;
	using Figures = std::vector<std::pair<std::string, cv::Mat>>;
	// A built map against the truth: its figure, its check region, its metrics.
	const auto assess = [&](const std::string& mode, const std::string& label, const mrpt::maps::COccupancyGridMap2D& g,
							Figures& figs) {
		figs.push_back({label + (mode == "gt" ? ", ground-truth poses" : ", icp-slam"), paperStyle(g)});
		if (c.has_check_region)
		{
			const auto& r = c.check_region;
			m[mode + "_" + label + "_check_region_marked"] = occupiedLengthAt(g, r[0], r[1], r[2], r[3], 0.15);
		}
		return compareWithTruth(g, truth, c.match_tolerance, gt, reach);
	};
	step("maps with ground-truth poses", [&] {
		Figures figs{{"true map", paperStyle(truth)}};
		for (const auto& [label, ini] :
			 {std::pair<std::string, std::string>{"LASER", c.map_laser_ini}, {"OMNISCAN", c.map_omni_ini}})
		{
			// observations2map, the real program, on a simplemap at the GT poses.
			const std::string lc = label == "LASER" ? "laser" : "omniscan";
			saveSimplemap(simplemapWithGroundTruth(scanned, label, gt), out + "/gt_" + lc + ".simplemap");
			runProgram(out, "observations2map '" + ini + "' gt_" + lc + ".simplemap gt_" + lc, "observations2map_" + lc + ".log");
			gt_maps[label] = assess("gt", label, resampledLike(loadGrid(out + "/gt_" + lc + "_gridmap_no00.gridmap"), truth), figs);
		}
		writeImageAtomically(out + "/maps_gt.png", sideBySide(figs));
	});

	// 6. icp-slam, the real program, once per sensor, odometry as the guess.
	std::map<std::string, PathError> icp_err;
	std::map<std::string, MapMetrics> icp_maps;
	step("icp-slam", [&] {
		Figures figs{{"true map", paperStyle(truth)}};
		for (const auto& [label, ini] : {std::pair<std::string, std::string>{"LASER", c.icp_laser_ini}, {"OMNISCAN", c.icp_omni_ini}})
		{
			const std::string lc = label == "LASER" ? "laser" : "omniscan";
			runProgram(out, "rawlog-edit --keep-label " + label + ",ODOMETRY -i scanned.rawlog -o only_" + lc + ".rawlog -w",
					   "rawlog-edit_" + lc + ".log");
			runProgram(out, "icp-slam '" + ini + "' only_" + lc + ".rawlog", "icp-slam_" + lc + ".log");
			const auto sm = loadSimplemap(out + "/icp_slam_" + lc + "/_finalmap_.simplemap");
			icp_err[label] = comparePaths(simplemapKeyframes(sm), gt);
			icp_maps[label] = assess("icp", label, mapFromSimplemap(sm, icp_err[label].alignment, truth, invalidIsFreeFor(label)), figs);
		}
		writeImageAtomically(out + "/maps_icp.png", sideBySide(figs));
	});
	for (const std::string label : {"LASER", "OMNISCAN"})
	{
		const auto& g = gt_maps[label];
		const auto& i = icp_maps[label];
		const auto& e = icp_err[label];
		m["gt_" + label + "_precision"] = g.precision;
		m["gt_" + label + "_recall"] = g.recall;
		m["gt_" + label + "_thickness"] = g.thickness;
		m["icp_" + label + "_precision"] = i.precision;
		m["icp_" + label + "_recall"] = i.recall;
		m["icp_" + label + "_thickness"] = i.thickness;
		m["icp_" + label + "_ate_rmse"] = e.ate_rmse;
		m["icp_" + label + "_final_xy"] = e.final_xy;
		m["icp_" + label + "_final_yaw"] = e.final_yaw;
		m["icp_" + label + "_keyframes"] = e.poses;
	}

	// 7. The report.
	step("report", [&] {
		const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		report << "# omnirange experiment: " << c.name << "\n\n"
			   << "From `" << c.ini_file << "`: " << simulated.frames << " simulated frames (" << fmt("%.0f", simulated.route_seconds)
			   << " s of route), histogram trained on " << trained.used << " image/laser pairs. The whole run took "
			   << fmt("%.0f", secs) << " s.\n\n"
			   << "## Accuracy: laser against omnicam (paper Table II, Fig. 9)\n\n"
			   << acc.table(1.25) << "\n![differences](accuracy_histogram.png)\n\n"
			   << "All pairs: `accuracy_pairs.csv`. What the histogram learned from (paper Fig. 1): "
			   << "![bird's-eye view](fig1_birdseye.png) ![laser free region](fig1_laser.png) ![fused](fig1_fused.png)\n\n"
			   << "## Maps against the world's true map\n\n"
			   << "Occupied cells count as correct within " << c.match_tolerance << " m of a true wall (precision); "
			   << "true wall surface within " << reach << " m of the path counts as found within the same tolerance (recall). "
			   << "Wall thickness: occupied area over the length of its centre line.\n\n"
			   << "| localisation | sensor | occupied cells | precision | recall | wall thickness | ATE RMSE | final pose error |\n"
			   << "|---|---|---|---|---|---|---|---|\n";
		for (const std::string label : {"LASER", "OMNISCAN"})
		{
			const auto& g = gt_maps[label];
			report << "| ground truth | " << label << " | " << g.occupied << " | " << fmt("%.3f", g.precision) << " | "
				   << fmt("%.3f", g.recall) << " | " << fmt("%.3f m", g.thickness) << " | - | - |\n";
		}
		for (const std::string label : {"LASER", "OMNISCAN"})
		{
			const auto& g = icp_maps[label];
			const auto& e = icp_err[label];
			report << "| icp-slam + odometry | " << label << " | " << g.occupied << " | " << fmt("%.3f", g.precision)
				   << " | " << fmt("%.3f", g.recall) << " | " << fmt("%.3f m", g.thickness) << " | "
				   << fmt("%.3f m", e.ate_rmse) << " | " << fmt("%.3f m", e.final_xy) << ", "
				   << fmt("%.1f deg", e.final_yaw * 180 / M_PI) << " |\n";
		}
		report << "\n![maps with ground-truth poses](maps_gt.png)\n\n![maps from icp-slam](maps_icp.png)\n\n";
		if (c.has_check_region)
		{
			report << "## Check region (" << c.check_region[0] << ", " << c.check_region[1] << "), " << c.check_region[2]
				   << " x " << c.check_region[3] << " m\n\nOccupied cells within 0.15 m of the box, as a length "
				   << "(cells x resolution): a wall along its " << c.check_region[2] << " m side gives about that.\n\n"
				   << "| map | LASER | OMNISCAN |\n|---|---|---|\n"
				   << "| ground-truth poses | " << fmt("%.2f m", m["gt_LASER_check_region_marked"]) << " | "
				   << fmt("%.2f m", m["gt_OMNISCAN_check_region_marked"]) << " |\n"
				   << "| icp-slam | " << fmt("%.2f m", m["icp_LASER_check_region_marked"]) << " | "
				   << fmt("%.2f m", m["icp_OMNISCAN_check_region_marked"]) << " |\n\n";
		}
		m["seconds"] = secs;
		std::ostringstream ini;
		ini << "[metrics]\n";
		for (const auto& [k, v] : m) ini << k << " = " << fmt("%.6g", v) << "\n";
		writeFileAtomically(out + "/metrics.ini", ini.str());
		writeFileAtomically(out + "/report.md", report.str());
	});
	return m;
}

}  // namespace omnirange::eval
