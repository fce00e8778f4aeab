// omnirange-accuracy: a rawlog with LASER and OMNISCAN scans -> the paper's
// accuracy test: every pair in a CSV, a histogram like Fig. 9, a table like
// Table II (Markdown), with the exclusions counted.
#include "AppMain.h"

#include <omnirange/Accuracy.h>
#include <omnirange/AtomicWrite.h>

#include <cstdio>

using namespace omnirange;

int main(int argc, char** argv)
{
	return app::runApp("omnirange-accuracy", [&] {
		TCLAP::CmdLine cmd("omnirange-accuracy: compare omnicam scans against the laser (paper Table II, Fig. 9)", ' ', "0.1");
		TCLAP::ValueArg<std::string> in("i", "input", "rawlog with both scans (omnirange-scan's output)", true, "", "RAWLOG", cmd);
		TCLAP::ValueArg<std::string> out("o", "output", "prefix of the outputs: PREFIX_pairs.csv, PREFIX_histogram.png, PREFIX_table.md", true, "", "PREFIX", cmd);
		TCLAP::ValueArg<std::string> laser("", "laser-label", "label of the laser scans", false, "LASER", "LABEL", cmd);
		TCLAP::ValueArg<std::string> omni("", "omni-label", "label of the omnicam scans", false, "OMNISCAN", "LABEL", cmd);
		TCLAP::ValueArg<double> max_diff("", "max-difference", "pairs differing by more are excluded [m]", false, 1.25, "M", cmd);
		TCLAP::ValueArg<double> sync("", "max-dt", "largest time between paired scans [s]", false, 0.1, "S", cmd);
		TCLAP::ValueArg<std::string> title("", "title", "title of the histogram", false, "", "TEXT", cmd);
		TCLAP::SwitchArg quiet("q", "quiet", "no table on stdout", cmd);
		app::parseArgs(cmd, argc, argv);

		AccuracyOptions o;
		o.laser_label = laser.getValue();
		o.omni_label = omni.getValue();
		o.max_difference = max_diff.getValue();
		o.max_dt = sync.getValue();
		const AccuracyResult r = evaluateAccuracy(in.getValue(), o);
		const std::string table = r.table(o.max_difference);
		writeFileAtomically(out.getValue() + "_pairs.csv", r.csv);
		writeImageAtomically(out.getValue() + "_histogram.png",
							 differenceHistogram(r.stats.differences, title.getValue().empty() ? in.getValue() : title.getValue(),
												 o.max_difference));
		writeFileAtomically(out.getValue() + "_table.md", table);
		if (!quiet.getValue()) std::printf("%s", table.c_str());
		return 0;
	});
}
