#include "omnirange_apps/ScanApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange/io/AtomicWrite.h>
#include <omnirange/io/Progress.h>

namespace omnirange::app
{
ScanApp::Options ScanApp::parse(int argc, const char* const* argv)
{
	Options o;
	auto& s = o.scan;
	TCLAP::CmdLine cmd("omnirange-scan: add an omnicam range scan after every omnicam image of a rawlog", ' ', "0.1");
	TCLAP::ValueArg<std::string> in("i", "input", "rawlog with omnicam images", true, "", "RAWLOG", cmd);
	TCLAP::ValueArg<std::string> out("o", "output", "rawlog to write (all input observations plus the scans)", true, "", "RAWLOG", cmd);
	TCLAP::ValueArg<std::string> ini("c", "config", "ini with the rangefinder's parameters (docs/parameters.md)", true, "", "INI", cmd);
	TCLAP::ValueArg<std::string> section("s", "section", "ini section", false, o.section, "NAME", cmd);
	TCLAP::ValueArg<std::string> hist("H", "histogram", "histogram file from omnirange-train", true, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> omni("", "omni-label", "label of the images to scan", false, s.omni_label, "LABEL", cmd);
	TCLAP::ValueArg<int> threads("j", "threads", "threads decoding and scanning images", false, s.threads, "N", cmd);
	TCLAP::SwitchArg decode_only("", "decode-only", "only read and decode the images, write nothing (to time decoding alone)", cmd);
	TCLAP::SwitchArg skip_bad("", "skip-bad-images",
							  "skip a missing, cut or undecodable image (no scan for it; each named, and counted) instead of stopping",
							  cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	o.ini = ini.getValue(), o.section = section.getValue(), o.histogram = hist.getValue();
	s.input = in.getValue(), s.output = out.getValue(), s.omni_label = omni.getValue();
	s.threads = threads.getValue(), s.decode_only = decode_only.getValue();
	s.skip_bad_images = skip_bad.getValue();
	o.verbosity = verbosity.level();
	return o;
}

ScanApp::ScanApp(Options o) : mrpt::system::COutputLogger("omnirange-scan"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
}

RawlogScanSummary ScanApp::run()
{
	// The rawlog input scanRawlog checks itself; these are the app's own inputs.
	requireOutputsAreNotInputs({o_.scan.output}, {o_.ini, o_.histogram});
	const RangefinderParams params = loadRangefinderIni(o_.ini, o_.section, *this);
	const Rangefinder rf(params, ColourModel::load(o_.histogram));
	if (rf.compensationMissing())
		MRPT_LOG_WARN_FMT("'%s' records no floor colour from training: exposure compensation is off; train it again with "
						  "this omnirange-train to have it", o_.histogram.c_str());
	Progress progress("objects read");
	const auto s = scanRawlog(rf, o_.scan, progressAt(o_.verbosity, progress));
	for (const auto& why : s.skipped_reasons) MRPT_LOG_WARN_FMT("skipped: %s", why.c_str());
	if (s.skipped > 0)
		MRPT_LOG_WARN_FMT("%zu of %zu images skipped as bad", s.skipped, s.skipped + s.images);
	const double hit = 100.0 * s.hits / std::max<std::size_t>(1, s.rays);
	MRPT_LOG_INFO_FMT("%zu images scanned, %.1f %% of rays hit, %zu objects -> %s", s.images, hit, s.objects,
					  o_.scan.output.c_str());
	// Almost no hit at all is what a histogram trained on another floor, in
	// other light or with another camera gives: worth saying, not an error.
	if (hit < 2.0)
		MRPT_LOG_WARN_FMT("only %.1f %% of the rays hit anything: was '%s' trained on this floor, light and camera?",
						  hit, o_.histogram.c_str());
	return s;
}

}  // namespace omnirange::app
