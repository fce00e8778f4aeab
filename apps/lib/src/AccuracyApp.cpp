#include "omnirange_apps/AccuracyApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange_eval/Figures.h>

#include <omnirange/config/Output.h>
#include <omnirange/io/ImageFile.h>

#include <filesystem>
#include <optional>

namespace omnirange::app
{
AccuracyApp::Options AccuracyApp::parse(int argc, const char* const* argv)
{
	Options o;
	auto& a = o.accuracy;
	TCLAP::CmdLine cmd("omnirange-accuracy: compare omnicam scans against the laser (paper Table II, Fig. 9)", ' ', "0.1");
	TCLAP::ValueArg<std::string> in("i", "input", "rawlog with both scans (omnirange-scan's output)", true, "", "RAWLOG", cmd);
	TCLAP::ValueArg<std::string> out("o", "output", "prefix of the outputs: PREFIX_pairs.csv, PREFIX_histogram.png, PREFIX_table.md", true, "", "PREFIX", cmd);
	BoundArgs bound(cmd);
	bound.value("", "laser-label", "label of the laser scans", a.laser_label, "LABEL");
	bound.value("", "omni-label", "label of the omnicam scans", a.omni_label, "LABEL");
	bound.value("", "max-difference", "pairs differing by more are excluded [m]", a.max_difference, "M");
	bound.value("", "max-dt", "largest time between paired scans [s]", a.max_dt, "S");
	bound.value("", "first", "score only from this scan pair on (0-based; e.g. after the training part)", a.first, "N");
	bound.value("", "title", "title of the histogram", o.title, "TEXT");
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	o.input = in.getValue(), o.output = prefixPath(out, "accuracy");
	if (o.output.empty()) throw std::invalid_argument("-o names no file or folder");
	o.verbosity = verbosity.level();
	return o;
}

AccuracyApp::AccuracyApp(Options o) : mrpt::system::COutputLogger("omnirange-accuracy"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
}

eval::AccuracyResult AccuracyApp::run()
{
	const auto& a = o_.accuracy;
	const std::vector<Output> outputs{{o_.output + "_pairs.csv", OutputKind::Text, eval::kPairsCsvBegins},
									  {o_.output + "_histogram.png", OutputKind::Image},
									  {o_.output + "_table.md", OutputKind::Text, eval::kAccuracyTableBegins},
									  {o_.output + "_truth.md", OutputKind::Text, eval::kTruthTableBegins}};
	requireOutputsAllowed(outputs, "omnirange-accuracy", {o_.input});
	const eval::AccuracyResult r = eval::evaluateAccuracy(o_.input, a);
	const std::string table = r.table(a.max_difference);
	// The files of one run, all or none.
	OutputSet set("omnirange-accuracy", {o_.input});
	set.write(outputs[0], r.csv);
	stageImage(set, outputs[1].path,
			   eval::differenceHistogram(r.stats.differences, o_.title.empty() ? o_.input : o_.title, a.max_difference));
	set.write(outputs[2], table);
	// With the truth: the omnicam's table, then the laser, the omnicam and a fused scan on the laser's rays.
	const bool truth = r.truth.frames > 0;
	const std::string truth_table = truth ? r.truth.table() + "\n" + r.inViewTable() : "";
	if (truth) set.write(outputs[3], truth_table);
	set.commit();
	// No truth in this rawlog: an earlier run's table beside these files would read as theirs (checked ours above).
	if (!truth) std::filesystem::remove(o_.output + "_truth.md");
	MRPT_LOG_INFO_STREAM("\n" << table);
	if (truth) MRPT_LOG_INFO_STREAM("against the truth:\n" << truth_table);
	return r;
}

}  // namespace omnirange::app
