#include "omnirange_apps/TrainApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange/config/LayeredIni.h>
#include <omnirange/config/Output.h>
#include <omnirange/io/ImageFile.h>
#include <omnirange/io/RawlogWriter.h>
#include <omnirange/io/Progress.h>

#include <cmath>
#include <optional>

namespace omnirange::app
{
namespace
{
constexpr char kProgram[] = "omnirange-train";
}

std::vector<std::string> TrainApp::inputs() const { return {o_.training.input, imagesDirToRead(o_.training.input), o_.ini}; }

TrainApp::Options TrainApp::parse(int argc, const char* const* argv)
{
	Options o;
	auto& t = o.training;
	TCLAP::CmdLine cmd("omnirange-train: learn the floor's colours from a rawlog with an omnicam and a laser", ' ', "0.1");
	TCLAP::ValueArg<std::string> in("i", "input", "rawlog with omnicam images and laser scans", true, "", "RAWLOG", cmd);
	TCLAP::ValueArg<std::string> out("o", "output", "histogram file to write", true, "", "FILE", cmd);
	RangefinderIniArgs ini(cmd, "the camera, and the [training] and [learning] keys (docs/parameters.md)", true);
	BoundArgs bound(cmd);
	bound.pairing(t.omni_label, t.laser_label, t.max_dt);
	bound.value("", "every", "use every N-th image/scan pair", t.every, "N");
	bound.value("", "first", "skip the pairs before this one (0-based)", t.first, "N");
	const auto& max_frames = bound.value("n", "max-frames", "use at most this many pairs (0: all)", t.max_frames, "N");
	bound.value("", "until", "use only the pairs before this one (0: to the end)", t.until, "N");
	bound.flag("near-disc-only",
			   "count only the floor nearer than every laser hit, all round: a first histogram for omnirange-calibrate that "
			   "does not depend on the ini's orientation",
			   t.training.near_disc_only);
	const auto& figures_frame =
		bound.value("", "figures-frame", "which used pair the figures show (0-based)", t.figures_frame, "N");
	TCLAP::ValueArg<std::string> learn("", "learn", "also learn colour space, bins, threshold, obstacle_ratio, N, K and the boundary model against the laser on held-aside pairs, and write them to this ini", false, "", "INI", cmd);
	TCLAP::ValueArg<std::string> candidates("", "learn-candidates", "with --learn: also write every candidate tried and its score to this CSV", false, "", "CSV", cmd);
	TCLAP::ValueArg<std::string> figures("", "figures", "write PREFIX_birdseye.png, PREFIX_laser.png, PREFIX_fused.png (paper Fig. 1)", false, "", "PREFIX", cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	o.output = requiredPath(out), o.ini = ini.ini.getValue(), o.section = ini.section.getValue();
	o.learn_ini = optionalPath(learn), o.learn_candidates = optionalPath(candidates);
	if (!o.learn_candidates.empty() && o.learn_ini.empty())
		throw std::invalid_argument("--learn-candidates needs --learn");
	t.input = in.getValue();
	t.figures_prefix = prefixPath(figures, "fig");
	// Options that only mean something beside another: given without it, say so rather than ignore them.
	if (figures_frame.isSet() && t.figures_prefix.empty()) throw std::invalid_argument("--figures-frame needs --figures");
	if (max_frames.isSet() && !o.learn_ini.empty())
		throw std::invalid_argument("-n is not read by --learn, which splits every pair of the range it is given: "
									"choose the range with --first and --until");
	if (!t.figures_prefix.empty() && !o.learn_ini.empty())
		throw std::invalid_argument("--figures is drawn by a plain training run, not with --learn: run them apart");
	o.verbosity = verbosity.level();
	return o;
}

TrainApp::TrainApp(Options o) : mrpt::system::COutputLogger("omnirange-train"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
}

RawlogTrainingResult TrainApp::run()
{
	const auto& t = o_.training;
	const std::string fig = t.figures_prefix;
	const auto figure = [&](const std::string& name) { return Output{fig.empty() ? "" : fig + name, OutputKind::Image}; };
	requireOutputsAllowed({{o_.output, OutputKind::Histogram}, {o_.learn_ini, OutputKind::Ini, kLearnedIniBegins},
						   {o_.learn_candidates, OutputKind::Text, candidateColumns()}, figure("_birdseye.png"), figure("_laser.png"),
						   figure("_fused.png")},
						  kProgram, inputs());
	const RangefinderParams params = loadRangefinderIni(o_.ini, o_.section, *this);
	loadIniSection(o_.ini, kTrainingSection, TrainingParams::table(), o_.training.training);
	loadIniSection(o_.ini, kLearningSection, LearningOptions::table(), o_.learning);
	Progress progress("objects read");
	if (!o_.learn_ini.empty()) return learn(params);
	const RawlogTrainingResult r =
		trainFromRawlog(params, o_.training, progressAt(o_.verbosity, progress));
	// The histogram and its figures all or none.
	OutputSet set(kProgram, inputs());
	set.write({o_.output, OutputKind::Histogram}, r.model.serialize());
	if (!fig.empty())
		for (const auto& [path, image] : figureFiles(r, fig)) stageImage(set, path, image);
	set.commit();
	MRPT_LOG_INFO_FMT("trained on %d image/scan pairs (of %d), %zu floor and %zu obstacle pixels -> %s", r.used,
					  r.pairs, r.pixels, r.obstacle_pixels, o_.output.c_str());
	logSeparation(colourSeparation(r.model, Rangefinder(params, r.model).classifier(), params.histogram_smoothing));
	return r;
}

void TrainApp::logSeparation(const ColourSeparation& s)
{
	// A room colour cannot see in is the user's first thing to know: a warning, not an aside.
	if (s.known && s.auc < kPoorlySeparated) MRPT_LOG_WARN(separationLine(s));
	else MRPT_LOG_INFO(separationLine(s));
}

RawlogTrainingResult TrainApp::learn(const RangefinderParams& params)
{
	Progress progress("objects read (learning)");
	const LearningResult l = learnParameters(params, o_.training, o_.learning, progressAt(o_.verbosity, progress));
	// The histogram and the ini that goes with it (and the candidates) all or none.
	OutputSet set(kProgram, inputs());
	set.write({o_.output, OutputKind::Histogram}, l.model.serialize());
	set.write({o_.learn_ini, OutputKind::Ini, kLearnedIniBegins}, learnedIni(l, o_.section));
	if (!o_.learn_candidates.empty()) set.write({o_.learn_candidates, OutputKind::Text, candidateColumns()}, candidatesCsv(l));
	set.commit();
	MRPT_LOG_INFO_FMT("learned from %d pairs, validated on %d: %s (mean error %.4f m) -> %s, %s", l.training_pairs,
					  l.validation_pairs, describe(l.best).c_str(), l.best.score, o_.learn_ini.c_str(), o_.output.c_str());
	if (const auto other = bestInOtherSpace(l))
		MRPT_LOG_INFO_FMT("the best in another colour space: %s (mean error %.4f m, %.1f mm %s)",
						  describe(*other).c_str(), other->score, 1000 * std::abs(other->score - l.best.score),
						  other->score >= l.best.score ? "more" : "less");
	if (l.overruled)
		MRPT_LOG_INFO("CHROMA was kept on a tie: the lower score is within the held-aside frames' noise");
	if (!l.edge_bias.empty())
		MRPT_LOG_INFO_FMT("edge bias (by the hit's contrast): mean error %.4f m with it, %s", l.edge_bias_score,
						  l.params.scanner.edge_bias.empty() ? "not kept" : "kept");
	if (const std::string warning = poorLearningWarning(l); !warning.empty()) MRPT_LOG_WARN(warning);
	MRPT_LOG_INFO_FMT("doubt: sure_floor_share %g, sure_obstacle_ratio %g, sure_run %d: read free more than 25 cm past %.1f "
					  "%% of the laser's returns within max range on the held-aside pairs (%.1f %% without doubt), %.1f %% of rays "
					  "unsure",
					  l.doubt.sure_floor_share, l.doubt.sure_obstacle_ratio, l.doubt.sure_run, 100 * l.doubt.false_free,
					  100 * l.doubt.false_free_without, 100 * l.doubt.unsure);
	logSeparation(l.separation);
	RawlogTrainingResult r;
	r.model = l.model;
	r.used = l.refit_pairs > 0 ? l.refit_pairs : l.training_pairs;
	return r;
}

}  // namespace omnirange::app
