#include "omnirange_eval/Experiment.h"

#include "omnirange_eval/CandidateStudy.h"
#include "omnirange_eval/ExternalProgram.h"
#include "omnirange_eval/Figures.h"
#include <omnirange_slam/GuardedIcp.h>
#include <omnirange_slam/IcpSlamIni.h>
#include "omnirange_eval/SensoryFrameFormat.h"

#include <omnirange/config/Output.h>
#include <omnirange/io/ImageFile.h>
#include <omnirange/config/ErrorText.h>
#include <omnirange/config/Activity.h>
#include <omnirange/io/Progress.h>
#include <omnirange/io/RawlogScan.h>

#include <omnirange/io/GzObject.h>
#include <mrpt/serialization/CArchive.h>

#include <sys/statvfs.h>

#include <algorithm>


#include <chrono>
#include <cmath>
#include <filesystem>

namespace fs = std::filesystem;

namespace omnirange::eval
{
namespace
{
constexpr const char* kProgram = "omnirange-experiment";
/** The report's copy of the sensor's icp-slam ini (Experiment::mrptIni()), which the guarded matcher reads too. */
std::string icpIniOf(const SensorMaps& s) { return "icp-slam_" + s.tag + ".ini"; }
constexpr unsigned long long kFullDisk = 1 << 20;  // [bytes] free: too few for any stage's output

mrpt::maps::COccupancyGridMap2D loadGrid(const std::string& file)
{
	return readGzObject<mrpt::maps::COccupancyGridMap2D>(file, "grid map");
}
}  // namespace

Experiment::Experiment(ExperimentConfig config)
	: mrpt::system::COutputLogger("omnirange-experiment"), c_(std::move(config))
{
	setFolder(fs::absolute(c_.output).string());
	r_.has_check_region = c_.hasCheckRegion();
	// The laser's missing returns are free space; the omnicam's are not (emptyLike()).
	r_.sensors.resize(c_.fuses() ? 3 : 2);
	auto& laser = r_.sensors[0];
	laser.label = kLaserLabel, laser.tag = "laser", laser.map_ini = c_.map_laser_ini, laser.icp_ini = c_.icp_laser_ini;
	laser.invalid_is_free = true, laser.rbpf_ini = c_.rbpf_laser_ini;
	auto& omni = r_.sensors[1];
	omni.label = c_.rangefinder.sensor_label, omni.tag = "omniscan", omni.map_ini = c_.map_omni_ini;
	omni.icp_ini = c_.icp_omni_ini, omni.invalid_is_free = false, omni.rbpf_ini = c_.rbpf_omni_ini;
	if (c_.fuses())
	{
		// Behind the laser a fused ray is the omnicam's: its missing returns are not free space either.
		auto& fused = r_.sensors[2];
		fused.label = kFusedLabel, fused.tag = "fused", fused.map_ini = c_.map_fused_ini;
		fused.icp_ini = c_.icp_fused_ini, fused.invalid_is_free = false;
	}
	// MRPT's programs empty their logOutput_dir first: each run's must be its own folder of the
	// report, the one its map is read from; another name could be the dataset or the other sensor's.
	for (const auto& sensor : r_.sensors)
		for (const auto& [engine, ini] : {std::pair{"icp-slam", sensor.icp_ini}, std::pair{"rbpf-slam", sensor.rbpf_ini}})
			if (!ini.empty())
				if (const std::string dir = slam::mrptLogFolder(ini), own = slamFolder(engine, sensor.tag); dir != own)
					throw std::runtime_error(ini + ": [MappingApplication] logOutput_dir = '" + dir + "': the experiment reads " +
											 engine + "'s map for the " + sensor.tag + " from '" + own +
											 "' in its report, and the program empties the folder it names first: set "
											 "logOutput_dir = " + own);
	c_.requireMrptInisAsChecked();  // after every check of them, here and in the config's loading
}

std::string Experiment::mrptIni(const std::string& ini, const std::string& name) const
{
	// The bytes checked before the run, not the file now: MRPT's program reads its ini when it starts, minutes on.
	writeFileAtomically(out_ + "/" + name, c_.mrpt_ini_text.at(ini));
	return name;
}

std::string Experiment::slamFolder(const std::string& engine, const std::string& tag)
{
	std::string dir = engine + "_" + tag;  // "icp_slam_omniscan", the shipped inis' logOutput_dir
	std::replace(dir.begin(), dir.end(), '-', '_');
	return dir;
}

void Experiment::stage(const std::string& name, const std::function<void()>& body)
{
	MRPT_LOG_INFO_STREAM("[" << ++stage_ << "/" << stages_ << "] " << name);
	try
	{
		body();
	}
	catch (const std::exception& e)
	{
		// MRPT's programs may fail to write on a full disk and say nothing; the next reader then finds a file cut short.
		struct statvfs fs_stat{};
		const bool full = ::statvfs(out_.c_str(), &fs_stat) == 0 && fs_stat.f_bavail * fs_stat.f_frsize < kFullDisk;
		// MRPT's block made one line here: what is said after it (the disk, where the partial output is) stays.
		throw std::runtime_error("stage '" + name + "' failed: " + errorInOneLine(e.what()) +
								 (full ? " (the disk holding '" + out_ + "' is full)" : ""));
	}
}

void Experiment::setFolder(const std::string& dir)
{
	out_ = dir;
	dataset_ = out_ + "/dataset/" + c_.name + ".rawlog";
	histogram_ = out_ + "/floor.hist";
	scanned_ = out_ + "/scanned.rawlog";
}

std::vector<std::string> cameraMismatch(const CameraParams& made_by, const CameraParams& read_by)
{
	std::vector<std::string> keys;
	for (const auto& f : CameraParams::table().fields())
		if (f.print(made_by) != f.print(read_by)) keys.push_back(f.info.key);
	return keys;
}

Metrics Experiment::run()
{
	// Every stage writes into a fresh staging folder; the report folder is
	// replaced only when all of them succeeded, so a failed run never leaves
	// new data beside an old report.
	std::vector<std::string> inputs{c_.ini_file,      c_.world,         c_.route,          c_.robot,
									c_.icp_laser_ini, c_.icp_omni_ini,  c_.map_laser_ini,  c_.map_omni_ini,
									c_.rbpf_laser_ini, c_.rbpf_omni_ini, c_.icp_fused_ini, c_.map_fused_ini};
	inputs.insert(inputs.end(), c_.world_maps.begin(), c_.world_maps.end());
	const Output report{fs::absolute(c_.output).string(), OutputKind::Folder};
	requireOutputsAllowed({report}, kProgram, inputs, force_);
	c_.requireEnoughFrames();  // the output first: its refusal is the one a user must see
	OutputSet set(kProgram, inputs, force_);
	const std::string staging = set.stage(report);
	fs::create_directory(staging);
	setFolder(staging);
	Metrics m;
	try
	{
		m = runStages();
	}
	catch (const std::exception& e)
	{
		set.keep();  // for a look, until the next run beside it
		throw std::runtime_error(std::string(e.what()) + " (partial output in '" + staging + "'; '" + report.path +
								 "' is as it was)");
	}
	set.commit();
	setFolder(outputPath(report.path));
	return m;
}

Metrics Experiment::runStages()
{
	const auto t0 = std::chrono::steady_clock::now();
	MRPT_LOG_INFO_STREAM("experiment " << c_.name << " from " << c_.ini_file
									   << "; rangefinder, unlike the defaults: " << c_.rangefinder.changes());
	MRPT_LOG_DEBUG_STREAM("every rangefinder option:\n" << c_.rangefinder.asIni());
	// The robot's camera makes the images, [rangefinder]'s reads them: another mirror, scale or
	// centre (a --robot of another camera) reads every ray wrong, which the report must not blame on colour.
	r_.camera_mismatch = cameraMismatch(sim::RobotParams::loadFile(c_.robot).omnicam.camera, c_.rangefinder.camera);
	if (!r_.camera_mismatch.empty())  // on stderr, -q or not: every figure of the run depends on it
		activity::warn("the robot's camera (" + c_.robot + ") is not [rangefinder]'s camera: they differ in " +
					   joined(r_.camera_mismatch) + ": the images are read as another camera's, and every range with them");
	fs::create_directories(out_ + "/dataset");
	stage_ = 0;
	const bool rbpf = std::any_of(r_.sensors.begin(), r_.sensors.end(), [](const auto& s) { return !s.rbpf_ini.empty(); });
	stages_ = rbpf ? 9 : 8;
	stage("simulate", [&] { simulate(); });
	stage("train", [&] { train(); });
	stage("scan", [&] { scan(); });
	stage("accuracy", [&] { measureAccuracy(); });
	stage("maps with ground-truth poses", [&] { mapWithGroundTruth(); });
	stage("icp-slam", [&] { runIcpSlam(); });
	stage("guarded ICP", [&] { runGuardedIcp(); });
	if (rbpf) stage("rbpf-slam", [&] { runRbpfSlam(); });
	r_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	stage("report", [&] { writeReport(); });
	return metricsOf(r_);
}

// 1. The dataset, from the simulator.
void Experiment::simulate()
{
	sim::SimOptions o;
	o.world_file = c_.world;
	o.route_file = c_.route;
	o.robot_ini = c_.robot;
	o.output = dataset_;
	o.max_frames = c_.max_frames;
	sim::Simulator s;
	s.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	Progress progress("frames simulated");
	const bool show = showsProgress();
	r_.simulated = s.run(o, [&](int done, int total) {
		if (show) progress.update(done, total);
	});
}

// 2. The histogram, trained against the laser (paper §III-A1).
void Experiment::train()
{
	RawlogTrainingOptions o;
	o.input = dataset_;
	o.every = c_.train_every;
	o.training = c_.training;
	r_.training_until = c_.trainingFrames(r_.simulated.frames);
	o.until = r_.training_until;
	o.figures_prefix = out_ + "/fig1";
	if (c_.learn) return learn(o);
	const RawlogTrainingResult trained = trainFromRawlog(c_.rangefinder, o);
	trained.model.save(histogram_);
	for (const auto& [path, image] : figureFiles(trained, o.figures_prefix)) writeImageAtomically(path, image);
	histogram_data_ = trained.model;
	r_.training_pairs = trained.used;
}

void Experiment::learn(const RawlogTrainingOptions& o)
{
	const RangefinderParams start = c_.rangefinder;
	Progress progress("training pairs read for learning");
	const LearningResult l = learnParameters(start, o, c_.learning, showsProgress() ? &progress : nullptr);
	c_.rangefinder = l.params;
	histogram_data_ = l.model;
	histogram_data_.save(histogram_);
	writeFileAtomically(out_ + "/learned.ini", learnedIni(l));
	r_.training_pairs = l.training_pairs;
	r_.learned = describe(l.best) + " (of " + std::to_string(l.tried.size()) + " candidates, validated on " +
				 std::to_string(l.validation_pairs) + " held-aside pairs: `learned.ini`)";
	if (const std::string warning = poorLearningWarning(l); !warning.empty()) r_.learned += ". Warning: " + warning;
	if (study_candidates_)
	{
		CandidateStudyOptions study;
		study.rawlog = dataset_;
		study.first = r_.training_until;  // the pairs the scan stage's accuracy scores
		writeFileAtomically(out_ + "/candidates_on_route.csv", studyCandidates(l, start, study));
	}
	// The figures of paper Fig. 1, from the first training pair.
	RawlogTrainingOptions one = o;
	one.max_frames = 1;
	for (const auto& [path, image] : figureFiles(trainFromRawlog(c_.rangefinder, one), o.figures_prefix))
		writeImageAtomically(path, image);
}

// 3. The omnicam scans.
void Experiment::scan()
{
	const Rangefinder rf(c_.rangefinder, histogram_data_);
	RawlogScanOptions o;
	o.input = dataset_;
	o.output = scanned_;
	if (c_.fuses()) o.fuse_with = kLaserLabel;
	Progress progress("objects scanned");
	const auto s = scanRawlog(rf, o, showsProgress() ? &progress : nullptr);
	r_.omni_hit_fraction = double(s.hits) / std::max<std::size_t>(1, s.rays);
	r_.separation = colourSeparation(histogram_data_, rf.classifier(), c_.rangefinder.histogram_smoothing);
}

// 4. The accuracy test (Table II, Fig. 9).
void Experiment::measureAccuracy()
{
	AccuracyOptions o;
	o.omni_label = c_.rangefinder.sensor_label;
	o.first = r_.training_until;  // score only what the histogram never saw
	r_.accuracy = evaluateAccuracy(scanned_, o);
	writeFileAtomically(out_ + "/accuracy_pairs.csv", r_.accuracy.csv);
	writeImageAtomically(out_ + "/accuracy_histogram.png",
						 differenceHistogram(r_.accuracy.stats.differences, c_.name, o.max_difference));
	writeFileAtomically(out_ + "/accuracy_table.md", r_.accuracy.table(o.max_difference));
	if (r_.accuracy.truth.frames > 0) writeFileAtomically(out_ + "/accuracy_truth.md", r_.accuracy.truth.table());
}

MapMetrics Experiment::assess(const mrpt::maps::COccupancyGridMap2D& map, const std::string& title,
							  double& check_marked, std::vector<std::pair<std::string, cv::Mat>>& figures) const
{
	figures.push_back({title, paperStyle(map)});
	if (c_.hasCheckRegion())
	{
		const auto& b = c_.check_box;
		check_marked = occupiedLengthAt(map, b[0], b[1], b[2], b[3], 0.15);
	}
	return compareWithTruth(map, truth_, c_.match_tolerance, gt_path_, c_.rangefinder.scanner.max_range);
}

// 5. Maps with ground-truth poses, built by observations2map, against the true map.
void Experiment::mapWithGroundTruth()
{
	truth_ = loadGrid(out_ + "/dataset/" + c_.name + "_truemap.gridmap.gz");
	gt_path_ = groundTruthPath(dataset_, kGroundTruthLabel);
	std::vector<std::pair<std::string, cv::Mat>> figures{{"true map", paperStyle(truth_)}};
	for (auto& s : r_.sensors)
	{
		const std::string prefix = "gt_" + s.tag;
		saveSimplemap(simplemapWithGroundTruth(scanned_, s.label, gt_path_), out_ + "/" + prefix + ".simplemap");
		runProgram({"observations2map", mrptIni(s.map_ini, "observations2map_" + s.tag + ".ini"), prefix + ".simplemap",
					prefix},
				   out_, "observations2map_" + s.tag + ".log");
		const auto built = resampledLike(loadGrid(out_ + "/" + prefix + "_gridmap_no00.gridmap"), truth_);
		s.gt = assess(built, s.label + ", ground-truth poses", s.gt_check_marked, figures);
	}
	writeImageAtomically(out_ + "/maps_gt.png", sideBySide(figures));
}

// 6. icp-slam, the real program, once per sensor, odometry as the guess;
// and the odometry alone, the path a matcher has to beat.
void Experiment::runIcpSlam()
{
	r_.odometry_path = comparePaths(odometryPath(dataset_, kOdometryLabel), gt_path_);
	std::vector<std::pair<std::string, cv::Mat>> figures{{"true map", paperStyle(truth_)}};
	for (auto& s : r_.sensors)
	{
		const std::string ini = out_ + "/" + mrptIni(s.icp_ini, icpIniOf(s));
		for (const auto& k : slam::icpKeysMrptIgnores(ini))
			MRPT_LOG_WARN_STREAM("icp-slam ini '" << s.icp_ini << "': [ICP] " << k
												  << " is not read by MRPT 2.5 and keeps its default");
		for (const auto& setting : slam::mappingSettingsGuardedIcpIgnores(ini))
			MRPT_LOG_WARN_STREAM("icp-slam ini '" << s.icp_ini << "': [MappingApplication] " << setting
												  << " is followed by icp-slam, not by the guarded matcher");
		const std::string only = "only_" + s.tag + ".rawlog";
		runProgram({"rawlog-edit", "--keep-label", s.label + "," + kOdometryLabel, "-i", "scanned.rawlog", "-o", only,
					"-w"},
				   out_, "rawlog-edit_" + s.tag + ".log");
		runProgram({"icp-slam", icpIniOf(s), only}, out_, "icp-slam_" + s.tag + ".log");
		scoreSlam("icp-slam", slamFolder("icp-slam", s.tag), s, s.icp, s.icp_path, s.icp_check_marked, figures);
	}
	writeImageAtomically(out_ + "/maps_icp.png", sideBySide(figures));
}

void Experiment::scoreSlam(const std::string& engine, const std::string& dir, const SensorMaps& s, MapMetrics& map,
						   PathError& path, double& check_marked,
						   std::vector<std::pair<std::string, cv::Mat>>& figures) const
{
	const auto sm = loadSimplemap(out_ + "/" + dir + "/_finalmap_.simplemap");
	path = comparePaths(simplemapKeyframes(sm), gt_path_);
	map = assess(mapFromSimplemap(sm, path.alignment, truth_, s.invalid_is_free), s.label + ", " + engine, check_marked,
				 figures);
}

// 7. The odometry-guarded matcher (GuardedIcp.h), with each sensor's icp-slam
// ini, on the scans icp-slam read; its keyframes are scored as icp-slam's.
void Experiment::runGuardedIcp()
{
	std::vector<std::pair<std::string, cv::Mat>> figures{{"true map", paperStyle(truth_)}};
	for (auto& s : r_.sensors)
	{
		const slam::GuardedIcpResult g = slam::runGuardedIcp(out_ + "/only_" + s.tag + ".rawlog", s.label, kOdometryLabel,
												 slam::GuardedIcpOptions::fromIniFile(out_ + "/" + icpIniOf(s)));
		MRPT_LOG_INFO_STREAM("guarded ICP, " << s.label << ": " << g.matches << " matches, " << g.refused_jumps
											 << " refused, " << g.weak_directions << " weak directions left to the odometry, "
											 << g.loops << " loops closed");
		s.guarded_loops = g.loops;
		const std::string dir = slamFolder("guarded-icp", s.tag);
		fs::create_directories(out_ + "/" + dir);
		saveSimplemap(g.keyframes, out_ + "/" + dir + "/_finalmap_.simplemap");
		double unused = 0;
		scoreSlam("guarded-icp", dir, s, s.guarded, s.guarded_path, unused, figures);
	}
	writeImageAtomically(out_ + "/maps_guarded.png", sideBySide(figures));
}

// 8. rbpf-slam (a Rao-Blackwellised particle filter), where the ini names its
// configuration: it reads only MRPT's action/sensory-frame format.
void Experiment::runRbpfSlam()
{
	std::vector<std::pair<std::string, cv::Mat>> figures{{"true map", paperStyle(truth_)}};
	for (auto& s : r_.sensors)
	{
		if (s.rbpf_ini.empty()) continue;
		const std::string frames = "frames_" + s.tag + ".rawlog";
		writeSensoryFrameFormat(out_ + "/only_" + s.tag + ".rawlog", out_ + "/" + frames);
		runProgram({"rbpf-slam", mrptIni(s.rbpf_ini, "rbpf-slam_" + s.tag + ".ini"), frames}, out_,
				   "rbpf-slam_" + s.tag + ".log");
		double unused = 0;
		scoreSlam("rbpf-slam", slamFolder("rbpf-slam", s.tag), s, s.rbpf, s.rbpf_path, unused, figures);
	}
	if (figures.size() > 1) writeImageAtomically(out_ + "/maps_rbpf.png", sideBySide(figures));
}

// 9. The report and the metrics.
void Experiment::writeReport()
{
	const Metrics m = metricsOf(r_);
	std::string ini = "[metrics]\n";
	for (const auto& [k, v] : m) ini += k + " = " + formatDouble(v) + "\n";
	// Which experiment: a report put under another one's name (-o) is not taken for it.
	ini += "\n[report]\nexperiment = " + fs::path(c_.ini_file).stem().string() + "\n";
	writeFileAtomically(out_ + "/metrics.ini", ini);
	writeFileAtomically(out_ + "/report.md", reportMarkdown(c_, r_));
}

}  // namespace omnirange::eval
