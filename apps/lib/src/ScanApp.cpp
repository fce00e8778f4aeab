#include "omnirange_apps/ScanApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange/io/RawlogWriter.h>

#include <omnirange/config/Output.h>
#include <omnirange/io/Progress.h>

#include <algorithm>
#include <cstdio>

namespace omnirange::app
{
namespace
{
/** [%] share of the scan's rays. */
double shareOf(std::size_t n, const RawlogScanSummary& s) { return 100.0 * n / std::max<std::size_t>(1, s.rays); }
}  // namespace

ScanApp::Options ScanApp::parse(int argc, const char* const* argv)
{
	Options o;
	auto& s = o.scan;
	TCLAP::CmdLine cmd("omnirange-scan: add an omnicam range scan after every omnicam image of a rawlog", ' ', "0.1");
	TCLAP::ValueArg<std::string> in("i", "input", "rawlog with omnicam images", true, "", "RAWLOG", cmd);
	TCLAP::ValueArg<std::string> out("o", "output", "rawlog to write (all input observations plus the scans)", true, "", "RAWLOG", cmd);
	RangefinderIniArgs ini(cmd, "the rangefinder's parameters (docs/parameters.md)", true);
	TCLAP::ValueArg<std::string> hist("H", "histogram", "histogram file from omnirange-train", true, "", "FILE", cmd);
	BoundArgs bound(cmd);
	bound.value("", "omni-label", "label of the images to scan", s.omni_label, "LABEL");
	bound.value("j", "threads", "threads decoding and scanning images", s.threads, "N");
	bound.flag("decode-only", "only read and decode the images, write nothing (to time decoding alone)", s.decode_only);
	bound.flag("whole-images", "decode each image whole, not only the part the scan reads (the same scans, slower)",
			   s.whole_images);
	bound.flag("skip-bad-images",
			   "skip a missing, cut or undecodable image (no scan for it; each named, and counted) instead of stopping",
			   s.skip_bad_images);
	const auto& fuse = bound.value("", "fuse-with",
				"label of a laser on the same robot: also write a FUSED scan, the nearer of the laser and a sure omnicam "
				"hit per ray (docs/users.md)",
				s.fuse_with, "LABEL");
	const auto& max_dt =
		bound.value("", "max-dt", "with --fuse-with: largest time between an image and the laser scan fused with it [s]",
					s.max_dt, "S");
	ForceArg force(cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	s.force = force.value();
	o.ini = ini.ini.getValue(), o.section = ini.section.getValue(), o.histogram = hist.getValue();
	s.input = in.getValue(), s.output = requiredPath(out);
	if (fuse.isSet() && s.fuse_with.empty()) throw std::invalid_argument("--fuse-with names no label");
	if (max_dt.isSet() && s.fuse_with.empty()) throw std::invalid_argument("--max-dt needs --fuse-with");
	o.verbosity = verbosity.level();
	return o;
}

ScanApp::ScanApp(Options o) : mrpt::system::COutputLogger("omnirange-scan"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
}

RawlogScanSummary ScanApp::run()
{
	// The rawlog too (scanRawlog checks it again): an output that is the input is called that,
	// before its images folder is judged as an output's.
	requireRawlogOutputAllowed(o_.scan.output, kScanProgram,
							   {o_.ini, o_.histogram, o_.scan.input, imagesDirToRead(o_.scan.input)}, o_.scan.force);
	const RangefinderParams params = loadRangefinderIni(o_.ini, o_.section, *this);
	const ColourModel colours = ColourModel::load(o_.histogram);
	const Rangefinder rf(params, colours);
	if (rf.compensationMissing())
		MRPT_LOG_WARN_FMT("'%s' records no floor colour from training: exposure compensation is off; train it again with "
						  "this omnirange-train to have it", o_.histogram.c_str());
	if (const PixelBox box = rf.pixelsRead(); !o_.scan.whole_images)
	{
		const int w = box.right - box.left + 1, h = box.bottom - box.top + 1;
		MRPT_LOG_INFO_FMT("the scan reads a %dx%d box of the %dx%d image (%.1f %%): a JPEG is decoded only around it",
						  w, h, params.camera.image_width, params.camera.image_height,
						  100.0 * w * h / (double(params.camera.image_width) * params.camera.image_height));
	}
	Progress progress("objects read");
	const auto s = scanRawlog(rf, o_.scan, progressAt(o_.verbosity, progress));
	for (const auto& why : s.skipped_reasons) MRPT_LOG_WARN_FMT("skipped: %s", why.c_str());
	if (s.skipped > 0)
		MRPT_LOG_WARN_FMT("%zu of %zu images skipped as bad", s.skipped, s.skipped + s.images);
	if (s.images_copied > 0)
		MRPT_LOG_INFO_FMT("%zu of the input's image files copied beside the output (no hard link could be made: another "
						  "file system, or links not allowed there)",
						  s.images_copied);
	const auto share = [&](std::size_t n) { return shareOf(n, s); };
	MRPT_LOG_INFO_FMT("%zu images scanned: %.1f %% of rays hit, %.1f %% free to max range, %.1f %% unsure (free "
					  "only to where the floor's colour stops being sure), %.1f %% too close, %.1f %% rejected as "
					  "outliers; %zu objects -> %s",
					  s.images, share(s.hits), share(s.no_hit), share(s.unsure), share(s.too_close), share(s.outliers),
					  s.objects, o_.scan.output.c_str());
	if (!o_.scan.fuse_with.empty())
		MRPT_LOG_INFO_FMT("%zu %s scans (%s with %s); %zu images were paired with no %s scan (an image pairs with "
						  "the next scan within %g s, or the one before it, as training pairs them)",
						  s.fused, kFusedLabel, rf.params().sensor_label.c_str(), o_.scan.fuse_with.c_str(),
						  s.images - s.fused, o_.scan.fuse_with.c_str(), o_.scan.max_dt);
	for (const auto& w : scanWarnings(s, o_.histogram, colours.trainedOnColour())) MRPT_LOG_WARN(w);
	return s;
}

std::vector<std::string> scanWarnings(const RawlogScanSummary& s, const std::string& histogram, bool trained_on_colour)
{
	if (s.rays == 0) return {};
	std::vector<std::string> warnings;
	// The colours a histogram learned are not in a grey image: its rays end where the grey happens to fall.
	if (trained_on_colour && s.grey_images > 0)
		warnings.push_back(std::to_string(s.grey_images) + " of " + std::to_string(s.images) +
						   " images are grey (three equal channels), but '" + histogram +
						   "' was trained on a floor of colour: train it on this camera's images");
	const double hit = shareOf(s.hits, s), too_close = shareOf(s.too_close, s);
	const auto percent = [](double x) {
		char b[32];
		std::snprintf(b, sizeof b, "%.1f %%", x);
		return std::string(b);
	};
	// Almost no hit at all is what a histogram trained on another floor, in
	// other light or with another camera gives: worth saying, not an error.
	if (hit < 2.0)
	{
		warnings.push_back("only " + percent(hit) + " of the rays hit anything: was '" + histogram +
						   "' trained on this floor, light and camera?");
		return warnings;
	}
	// A ray is too close when the floor just beyond the base is not free:
	// the robot's body inside the scan circle, or that floor darker or
	// otherwise unlike training (light, the robot's own shadow). Said only
	// when the histogram itself is not in doubt (above): a histogram of
	// another floor ends every ray at the base too.
	if (too_close >= 10.0)
		warnings.push_back(percent(too_close) +
						   " of the rays ended at the robot's base (too close): check base_radius against the robot's "
						   "body in the image, and whether the floor around it looks as in training (light, the "
						   "robot's shadow; exposure_compensation)");
	return warnings;
}

}  // namespace omnirange::app
