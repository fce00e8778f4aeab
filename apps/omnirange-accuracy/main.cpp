// omnirange-accuracy: a rawlog with LASER and OMNISCAN scans -> the paper's
// accuracy test: every pair in a CSV, a histogram like Fig. 9, a table like
// Table II (Markdown), with the exclusions counted.
#include "AppMain.h"

#include <omnirange/Accuracy.h>
#include <omnirange/AtomicWrite.h>
#include <omnirange/RawlogReader.h>

#include <cmath>
#include <cstdio>
#include <sstream>

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
		if (!(max_diff.getValue() > 0) || !(sync.getValue() >= 0))
			throw std::invalid_argument("--max-difference must be > 0 and --max-dt >= 0");

		RawlogReader reader(in.getValue());
		mrpt::obs::CObservation2DRangeScan::Ptr last_laser, last_omni;
		AccuracyStats stats;
		std::ostringstream csv;
		csv << "frame,laser_ray,omni_ray,bearing_rad,laser_m,omni_m,difference_m,status\n";
		int frames = 0;
		while (auto obj = reader.next())
		{
			auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obj);
			if (!scan) continue;
			if (scan->sensorLabel == laser.getValue()) last_laser = scan;
			else if (scan->sensorLabel == omni.getValue()) last_omni = scan;
			else continue;
			if (!last_laser || !last_omni ||
				std::abs(mrpt::system::timeDifference(last_laser->timestamp, last_omni->timestamp)) > sync.getValue())
				continue;
			for (const RangePair& p : pairScans(*last_laser, *last_omni, max_diff.getValue()))
			{
				stats.add(p);
				char line[200];
				std::snprintf(line, sizeof line, "%d,%d,%d,%.5f,%.4f,%.4f,%.4f,%s\n", frames, p.laser_ray, p.omni_ray,
							  p.bearing, p.laser, p.omni, p.difference(), toString(p.status).c_str());
				csv << line;
			}
			last_laser.reset();
			last_omni.reset();
			++frames;
		}
		if (frames == 0)
			throw std::runtime_error("no " + laser.getValue() + " scan had an " + omni.getValue() + " scan within " +
									 std::to_string(sync.getValue()) + " s in '" + in.getValue() + "'");

		std::ostringstream md;
		char row[400];
		md << "| frames | pairs | compared | excluded: laser beyond omni max range | excluded: |difference| > "
		   << max_diff.getValue() << " m | omni ray rejected | mean absolute difference | mean percentage difference | signed mean |\n"
		   << "|---|---|---|---|---|---|---|---|---|\n";
		std::snprintf(row, sizeof row, "| %d | %zu | %zu | %zu (%.1f %%) | %zu (%.1f %%) | %zu | %.4f m | %.3f %% | %+.4f m |\n",
					  frames, stats.total(), stats.compared, stats.laser_beyond,
					  100.0 * stats.laser_beyond / std::max<std::size_t>(1, stats.total()), stats.too_different,
					  100.0 * stats.too_different / std::max<std::size_t>(1, stats.total()), stats.omni_rejected,
					  stats.meanAbs(), stats.meanPercent(), stats.meanSigned());
		md << row;
		writeFileAtomically(out.getValue() + "_pairs.csv", csv.str());
		writeImageAtomically(out.getValue() + "_histogram.png",
							 differenceHistogram(stats.differences, title.getValue().empty() ? in.getValue() : title.getValue(),
												 max_diff.getValue()));
		writeFileAtomically(out.getValue() + "_table.md", md.str());
		if (!quiet.getValue()) std::printf("%s", md.str().c_str());
		return 0;
	});
}
