// omnirange-train: rawlog with OMNICAM + LASER -> colour histogram of the
// free floor (paper §III-A1), and the three images of paper Fig. 1.
#include "AppMain.h"
#include "Progress.h"
#include "RangefinderIni.h"

#include <omnirange/RawlogTraining.h>

using namespace omnirange;

int main(int argc, char** argv)
{
	return app::runApp("omnirange-train", [&] {
		TCLAP::CmdLine cmd("omnirange-train: learn the floor's colours from a rawlog with an omnicam and a laser", ' ', "0.1");
		TCLAP::ValueArg<std::string> in("i", "input", "rawlog with OMNICAM images and LASER scans", true, "", "RAWLOG", cmd);
		TCLAP::ValueArg<std::string> out("o", "output", "histogram file to write", true, "", "FILE", cmd);
		TCLAP::ValueArg<std::string> ini("c", "config", "ini with the camera (docs/parameters.md)", true, "", "INI", cmd);
		TCLAP::ValueArg<std::string> section("s", "section", "ini section", false, "rangefinder", "NAME", cmd);
		TCLAP::ValueArg<std::string> omni("", "omni-label", "label of the images", false, "OMNICAM", "LABEL", cmd);
		TCLAP::ValueArg<std::string> laser("", "laser-label", "label of the laser scans", false, "LASER", "LABEL", cmd);
		TCLAP::ValueArg<double> sync("", "max-dt", "largest time between an image and its scan [s]", false, 0.1, "S", cmd);
		TCLAP::ValueArg<int> every("", "every", "use every N-th image/scan pair", false, 1, "N", cmd);
		TCLAP::ValueArg<int> first("", "first", "skip the pairs before this one (0-based)", false, 0, "N", cmd);
		TCLAP::ValueArg<int> max_frames("n", "max-frames", "use at most this many pairs (0: all)", false, 0, "N", cmd);
		TCLAP::ValueArg<int> bins("", "bins", "bins per colour channel", false, ColourHistogram::kDefaultBins, "N", cmd);
		TCLAP::ValueArg<std::string> space("", "colour-space", "RGB or HSV", false, "RGB", "SPACE", cmd);
		TCLAP::ValueArg<double> margin("", "laser-margin", "distance kept from laser hits [m]", false, 0.10, "M", cmd);
		TCLAP::ValueArg<std::string> figures("", "figures", "write PREFIX_birdseye.png, PREFIX_laser.png, PREFIX_fused.png (paper Fig. 1)", false, "", "PREFIX", cmd);
		TCLAP::ValueArg<int> figure_frame("", "figures-frame", "which used pair the figures show (0-based)", false, 0, "N", cmd);
		TCLAP::SwitchArg quiet("q", "quiet", "no progress or summary", cmd);
		app::parseArgs(cmd, argc, argv);

		RawlogTrainingOptions o;
		o.input = in.getValue();
		o.omni_label = omni.getValue();
		o.laser_label = laser.getValue();
		o.max_dt = sync.getValue();
		o.every = every.getValue();
		o.first = first.getValue();
		o.max_frames = max_frames.getValue();
		o.bins = bins.getValue();
		o.space = colourSpaceFromString(space.getValue());
		o.laser_margin = margin.getValue();
		o.figures_prefix = figures.getValue();
		o.figures_frame = figure_frame.getValue();
		const auto r = trainFromRawlog(app::loadRangefinderIni(ini.getValue(), section.getValue()), o, [&](int n) {
			if (!quiet.getValue()) app::showProgress("pairs used", n, n);
		});
		r.histogram.save(out.getValue());
		if (!quiet.getValue())
			std::printf("trained on %d image/scan pairs (of %d), %zu floor pixels -> %s\n", r.used, r.pairs, r.pixels,
						out.getValue().c_str());
		return 0;
	});
}
