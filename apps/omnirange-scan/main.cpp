// omnirange-scan: rawlog + histogram + ini -> the same rawlog with an
// OMNISCAN CObservation2DRangeScan right after every OMNICAM image.
#include "AppMain.h"
#include "Progress.h"
#include "RangefinderIni.h"

#include <omnirange/RawlogScan.h>

using namespace omnirange;

int main(int argc, char** argv)
{
	return app::runApp("omnirange-scan", [&] {
		TCLAP::CmdLine cmd("omnirange-scan: add an omnicam range scan after every omnicam image of a rawlog", ' ', "0.1");
		TCLAP::ValueArg<std::string> in("i", "input", "rawlog with OMNICAM images", true, "", "RAWLOG", cmd);
		TCLAP::ValueArg<std::string> out("o", "output", "rawlog to write (all input observations plus the scans)", true, "", "RAWLOG", cmd);
		TCLAP::ValueArg<std::string> ini("c", "config", "ini with the rangefinder's parameters (docs/parameters.md)", true, "", "INI", cmd);
		TCLAP::ValueArg<std::string> section("s", "section", "ini section", false, "rangefinder", "NAME", cmd);
		TCLAP::ValueArg<std::string> hist("H", "histogram", "histogram file from omnirange-train", true, "", "FILE", cmd);
		TCLAP::ValueArg<std::string> omni("", "omni-label", "label of the images to scan", false, "OMNICAM", "LABEL", cmd);
		TCLAP::ValueArg<int> threads("j", "threads", "threads decoding and scanning images", false, 2, "N", cmd);
		TCLAP::SwitchArg decode_only("", "decode-only", "only read and decode the images, write nothing (to time decoding alone)", cmd);
		TCLAP::SwitchArg quiet("q", "quiet", "no progress or summary", cmd);
		app::parseArgs(cmd, argc, argv);

		const RangefinderParams params = app::loadRangefinderIni(ini.getValue(), section.getValue());
		const Rangefinder rf(params, ColourHistogram::load(hist.getValue()));
		RawlogScanOptions o;
		o.input = in.getValue();
		o.output = out.getValue();
		o.omni_label = omni.getValue();
		o.threads = threads.getValue();
		o.decode_only = decode_only.getValue();
		const auto s = scanRawlog(rf, o, [&](std::size_t n) {
			if (!quiet.getValue()) app::showProgress("images scanned", static_cast<int>(n), static_cast<int>(n));
		});
		if (!quiet.getValue())
			std::printf("%zu images scanned, %.1f %% of rays hit, %zu objects -> %s\n", s.images,
						100.0 * s.hits / std::max<std::size_t>(1, s.rays), s.objects, o.output.c_str());
		return 0;
	});
}
