#include "omnirange_apps/CalibrateApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange/io/Progress.h>

#include <cstdio>

namespace omnirange::app
{
CalibrateApp::Options CalibrateApp::parse(int argc, const char* const* argv)
{
	Options o;
	auto& c = o.calibration;
	TCLAP::CmdLine cmd("omnirange-calibrate: fit the mirror's R or alpha against a laser (paper §IV-D)", ' ', "0.1");
	TCLAP::ValueArg<std::string> in("i", "input", "rawlog with omnicam images and laser scans", true, "", "RAWLOG", cmd);
	TCLAP::ValueArg<std::string> ini("c", "config", "ini with the rangefinder's parameters (a first guess of R or alpha)", true, "", "INI", cmd);
	TCLAP::ValueArg<std::string> section("s", "section", "ini section", false, o.section, "NAME", cmd);
	TCLAP::ValueArg<std::string> hist("H", "histogram", "histogram file from omnirange-train", true, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> omni("", "omni-label", "label of the images", false, c.omni_label, "LABEL", cmd);
	TCLAP::ValueArg<std::string> laser("", "laser-label", "label of the laser scans", false, c.laser_label, "LABEL", cmd);
	TCLAP::ValueArg<double> max_dt("", "max-dt", "largest time between an image and its scan [s]", false, c.max_dt, "S", cmd);
	TCLAP::ValueArg<int> every("", "every", "use every N-th image/scan pair", false, c.every, "N", cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	o.ini = ini.getValue(), o.section = section.getValue(), o.histogram = hist.getValue();
	c.input = in.getValue(), c.omni_label = omni.getValue(), c.laser_label = laser.getValue();
	c.max_dt = max_dt.getValue(), c.every = every.getValue();
	o.verbosity = verbosity.level();
	return o;
}

CalibrateApp::CalibrateApp(Options o) : mrpt::system::COutputLogger("omnirange-calibrate"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
}

MirrorCalibration CalibrateApp::run()
{
	const RangefinderParams params = loadRangefinderIni(o_.ini, o_.section, *this);
	const Rangefinder rf(params, ColourModel::load(o_.histogram));
	Progress progress("objects read");
	const MirrorCalibration c =
		calibrateMirror(rf, o_.calibration, progressAt(o_.verbosity, progress));
	// The result is the program's output: on stdout, whatever the verbosity.
	std::printf("pairs: %zu (%zu kept after dropping residuals over 3x the median)\n", c.pairs, c.kept);
	std::printf("paraboloid:   R = %.2f px      RMS range error %.3f m (ini's R = %.2f: %.3f m)\n", c.R, c.rms_R,
				params.camera.R, c.rms_given);
	std::printf("first order:  alpha = %.2f px/rad   RMS range error %.3f m\n", c.alpha, c.rms_alpha);
	std::printf("boundary: the laser's edge lies a median %+.2f px beyond the omnicam's "
				"(suggested boundary_offset = %.2f with the ini's mirror%s)\n",
				c.boundary_px, c.suggested_boundary_offset, c.clamped ? ", clamped to [-1, 1]" : "");
	return c;
}

}  // namespace omnirange::app
