#include "omnirange_apps/CalibrateApp.h"

#include "omnirange_apps/CommandLine.h"

#include <omnirange/config/Output.h>
#include <omnirange/io/RawlogWriter.h>
#include <omnirange/config/IniSectionWriter.h>
#include <omnirange/config/LayeredIni.h>
#include <omnirange/io/ObservationImage.h>
#include <omnirange/config/OptionsTable.h>
#include <omnirange/io/Progress.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <optional>

namespace omnirange::app
{
namespace
{
constexpr char kProgram[] = "omnirange-calibrate";
// Past these, a calibration is doubted: a warning, and nothing saved without --accept.
constexpr double kMaxRms = 1.0;  // [px] reprojection error over the boards
constexpr double kMaxCentreSpread = 3.0;  // [px] the principal point's move without a group of boards
constexpr double kMaxEllipticity = 0.1;  // of --rim's disc
constexpr char kOpenCvYamlBegins[] = "%YAML:1.0";  // how cv::FileStorage begins -o's intrinsics
// [px] --rim's centre from a calibrated one (mei, ocamcalib) in the ini, and one image's own disc
// from all images': the real paraboloid's disc and its checkerboard centre agree within 3 px, its
// ten images' own discs within 2.5 px of theirs together; the rest is room for a rim partly hidden.
constexpr double kMaxRimOffset = 10.0;

/** A calibrated camera's keys, each printed by the ini's own table. */
std::vector<std::pair<std::string, std::string>> cameraKeys(const CameraParams& cam,
															const std::vector<std::string>& model_keys)
{
	std::vector<std::string> names{"image_width", "image_height", "cx", "cy", "mirror_model"};
	names.insert(names.end(), model_keys.begin(), model_keys.end());
	std::vector<std::pair<std::string, std::string>> keys;
	for (const std::string& name : names)
		for (const auto& f : CameraParams::table().fields())
			if (f.info.key == name) keys.push_back({name, f.print(cam)});
	return keys;
}
/** Every image file in `dir`, sorted by name, appended to `files`. */
void addImagesOf(const std::string& dir, std::vector<std::string>& files)
{
	namespace fs = std::filesystem;
	if (!fs::is_directory(dir)) throw std::runtime_error("--checkerboard-dir: no folder '" + dir + "'");
	std::vector<std::string> found;
	for (const auto& e : fs::directory_iterator(dir))
		if (isImageFileName(e.path().string()))
		{
			requireRegularFile(e.path().string(), "checkerboard image");  // a FIFO would block; said, not skipped
			found.push_back(e.path().string());
		}
	if (found.empty()) throw std::runtime_error("--checkerboard-dir: no image in '" + dir + "'");
	std::sort(found.begin(), found.end());
	files.insert(files.end(), found.begin(), found.end());
}
}  // namespace

void CalibrateApp::say(const char* format, ...) const
{
	if (getMinLoggingLevel() > mrpt::system::LVL_INFO) return;
	va_list args;
	va_start(args, format);
	std::vprintf(format, args);
	va_end(args);
}

CalibrateApp::Options CalibrateApp::parse(int argc, const char* const* argv)
{
	Options o;
	auto& c = o.calibration;
	TCLAP::CmdLine cmd("omnirange-calibrate: fit the mirror's R or alpha against a laser (paper §IV-D); or, with "
					   "--checkerboard, the camera's intrinsics (Mei's unified model) from checkerboard images",
					   ' ', "0.1");
	TCLAP::ValueArg<std::string> in("i", "input", "rawlog with omnicam images and laser scans", false, "", "RAWLOG", cmd);
	RangefinderIniArgs ini(cmd, "the rangefinder's parameters (a first guess of R or alpha)", false);
	TCLAP::ValueArg<std::string> hist("H", "histogram", "histogram file from omnirange-train", false, "", "FILE", cmd);
	TCLAP::MultiArg<std::string> boards("", "checkerboard", "an image of a checkerboard (repeat for each; >= 3 found needed)", false, "IMAGE", cmd);
	TCLAP::ValueArg<std::string> save("", "save-to", "write what was found (orientation, then R or alpha and boundary_offset; cx, cy with --rim; the camera model with --checkerboard or --ocamcalib) into this ini's section, keeping the rest of the file", false, "", "INI", cmd);
	TCLAP::ValueArg<std::string> board_dir("", "checkerboard-dir",
										   "every image (jpg, png, pgm, ppm, bmp) in this folder, as --checkerboard each",
										   false, "", "DIR", cmd);
	TCLAP::MultiArg<std::string> rims("", "rim", "an ordinary image: find the mirror's centre and rim radius (repeat; a few images)", false, "IMAGE", cmd);
	TCLAP::ValueArg<std::string> ocam("", "ocamcalib", "OCamCalib's calib_results.txt: the camera's polynomial model (with --save-to: into the ini)", false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> board("", "board", "inner corners, COLUMNSxROWS", false, "8x6", "CxR", cmd);
	BoundArgs bound(cmd);
	bound.value("", "square", "side of a board square [m]", o.board.square, "M");
	TCLAP::ValueArg<std::string> out("o", "output", "with --checkerboard: write the intrinsics here (OpenCV YAML)", false, "", "FILE", cmd);
	bound.pairing(c.omni_label, c.laser_label, c.max_dt);
	bound.value("", "every", "use every N-th image/scan pair", c.every, "N");
	TCLAP::SwitchArg accept("", "accept",
							"save and exit 0 even when the result looks unsure (RMS over 1 px, an implausible mirror disc)",
							cmd);
	VerbosityArgs verbosity(cmd);
	parseArgs(cmd, argc, argv);
	bound.fill();
	o.accept = accept.getValue();
	o.ini = ini.ini.getValue(), o.section = ini.section.getValue(), o.histogram = hist.getValue();
	c.input = in.getValue();
	o.verbosity = verbosity.level();
	o.checkerboards = boards.getValue(), o.intrinsics_output = optionalPath(out);
	if (!board_dir.getValue().empty()) addImagesOf(board_dir.getValue(), o.checkerboards);
	o.checkerboard_dir = board_dir.getValue();
	o.rim_images = rims.getValue(), o.save_to = optionalPath(save), o.ocamcalib = ocam.getValue();
	if (!o.intrinsics_output.empty() && o.checkerboards.empty())
		throw std::invalid_argument("-o is written by a checkerboard calibration only (--checkerboard or --checkerboard-dir)");
	int used = 0;
	if (std::sscanf(board.getValue().c_str(), "%dx%d%n", &o.board.columns, &o.board.rows, &used) != 2 ||
		used != static_cast<int>(board.getValue().size()))
		throw std::invalid_argument("--board must be COLUMNSxROWS, e.g. 8x6, not '" + board.getValue() + "'");
	const bool without_laser = !o.checkerboards.empty() || !o.rim_images.empty() || !o.ocamcalib.empty();
	if (without_laser && (!c.input.empty() || !o.histogram.empty()))
		throw std::invalid_argument("-i and -H are read by the calibration against a laser only, which --rim, "
									"--checkerboard and --ocamcalib do not run: run it on its own");
	if (!without_laser && (o.ini.empty() || o.histogram.empty() || c.input.empty()))
		throw std::invalid_argument("against a laser, -i RAWLOG, -c INI and -H HISTOGRAM are all needed (or --checkerboard IMAGE..., --rim IMAGE... or --ocamcalib FILE)");
	return o;
}

CalibrateApp::CalibrateApp(Options o) : mrpt::system::COutputLogger("omnirange-calibrate"), o_(std::move(o))
{
	setMinLoggingLevel(o_.verbosity);
	// --save-to writes keys into an ini (the -c one is the usual choice), never into what was read.
	inputs_ = {o_.calibration.input, o_.histogram, o_.ocamcalib};
	inputs_.insert(inputs_.end(), o_.checkerboards.begin(), o_.checkerboards.end());
	inputs_.insert(inputs_.end(), o_.rim_images.begin(), o_.rim_images.end());
	if (!o_.checkerboard_dir.empty()) inputs_.push_back(o_.checkerboard_dir);
	if (!o_.calibration.input.empty()) inputs_.push_back(imagesDirToRead(o_.calibration.input));
	// Its -c ini is the usual --save-to, but not the bases under it: they are other inis' too.
	if (!o_.ini.empty())
		for (const auto& base : iniBasesOf(o_.ini)) inputs_.push_back(base);
	requireOutputsAllowed({{o_.save_to, OutputKind::Ini}, {o_.intrinsics_output, OutputKind::Text, kOpenCvYamlBegins}},
						  kProgram, inputs_);
	if (!o_.save_to.empty()) RangefinderParams::requireWritable(o_.save_to, o_.section);
	save_to_file_ = fileLedTo(o_.save_to);
}

void CalibrateApp::saveCameraKeys(const CameraParams& cam, const std::vector<std::string>& model_keys,
								  const std::function<void(OutputSet&)>& with) const
{
	saveKeys(cameraKeys(cam, model_keys), with);
	say("wrote the %s model's keys into [%s] of %s\n", toString(cam.mirror_model).c_str(), o_.section.c_str(),
		o_.save_to.c_str());
}

void CalibrateApp::saveKeys(const std::vector<std::pair<std::string, std::string>>& keys,
							const std::function<void(OutputSet&)>& with) const
{
	// An ini replaced meanwhile by a link (to its base, to another camera's ini) is not written through.
	requireStillLeadsTo(o_.save_to, save_to_file_, "the run began");
	writeIniSection(o_.save_to, o_.section, keys, RangefinderParams::table().comments(), {kProgram, inputs_, with});
}

void CalibrateApp::runModes()
{
	if (!o_.rim_images.empty()) runRim();
	if (!o_.checkerboards.empty()) runIntrinsics();
	if (!o_.ocamcalib.empty()) runOCamCalib();
	if (o_.rim_images.empty() && o_.checkerboards.empty() && o_.ocamcalib.empty()) run();
}

MirrorCalibration CalibrateApp::run()
{
	const RangefinderParams params = loadRangefinderIni(o_.ini, o_.section, *this);
	const ColourModel colours = ColourModel::load(o_.histogram);
	const Rangefinder rf(params, colours);
	const MirrorModel m = params.camera.mirror_model;
	const bool shape_calibrated = m == MirrorModel::Mei || m == MirrorModel::OCamCalib;
	Progress progress("objects read");
	const MirrorCalibration c =
		calibrateMirror(rf, o_.calibration, progressAt(o_.verbosity, progress));
	// The result is the program's output: on stdout, unless -q.
	say("pairs: %zu (%zu kept after dropping residuals over 3x the median)\n", c.pairs, c.kept);
	say("paraboloid:   R = %.2f px      RMS range error %.3f m (ini's R = %.2f: %.3f m)\n", c.R, c.rms_R,
		params.camera.R, c.rms_given);
	say("first order:  alpha = %.2f px/rad   RMS range error %.3f m\n", c.alpha, c.rms_alpha);
	say("height:       h = %.4f m +- %.4f (standard error over %d images), from %zu pairs with the ini's %s "
		"model; RMS range error %.3f m (the ini's h = %.3f m)\n",
		c.height.h, c.height.std_error, c.height.frames, c.height.used,
		toString(params.camera.mirror_model).c_str(), c.rms_height, params.camera.h);
	say("boundary: the laser's edge lies a median %+.2f px beyond the omnicam's "
		"(suggested boundary_offset = %.2f with the ini's mirror%s)\n",
		c.boundary_px, c.suggested_boundary_offset, c.clamped ? ", clamped to [-1, 1]" : "");
	constexpr double kDeg = 57.29577951308232;
	const ScaledOrientationFit scaled = fitOrientationAndScale(params, colours, c, o_.calibration);
	const OrientationFit& f = scaled.fit;
	orientation_ = f;
	say("orientation: forward_azimuth_deg = %.0f, mirrored = %s (at %s = %.4g; %d of %d frames agree within "
		"%.0f deg); mean error %.3f m (the ini's %.0f deg, %s: %.3f m)\n",
		f.forward_azimuth * kDeg, f.mirrored ? "true" : "false", scaled.scale_key.c_str(), scaled.scale,
		f.agreeing, f.frames, kAgreeingTurn * kDeg, f.error, params.camera.forward_azimuth * kDeg,
		params.camera.mirrored ? "true" : "false", f.error_as_given);
	if (!pinnedDown(f))
		requireSure({"only " + std::to_string(f.agreeing) + " of " + std::to_string(f.frames) +
					 " frames have their own best orientation within " + formatDouble(std::round(kAgreeingTurn * kDeg)) +
					 " deg of the fitted one: the orientation is not pinned down (are cx, cy and the mirror's scale near right? "
					 "is the histogram this camera's?)"});
	// R, alpha and the boundary were fitted with the ini's orientation: worth
	// anything only when that orientation was right.
	const double turn = std::abs(std::remainder(f.forward_azimuth - params.camera.forward_azimuth, 2 * M_PI));
	const bool orientation_ok = f.mirrored == params.camera.mirrored && turn <= 1.5 / kDeg;
	if (!orientation_ok)
		say("the ini's orientation is off: set forward_azimuth_deg and mirrored as above and run again "
			"(R, alpha and the boundary above were fitted with the ini's orientation)\n");
	if (!o_.save_to.empty())
	{
		std::vector<std::pair<std::string, std::string>> keys{
			{"forward_azimuth_deg", formatDouble(std::round(f.forward_azimuth * kDeg))},
			{"mirrored", f.mirrored ? "true" : "false"}};
		if (orientation_ok)
		{
			// A mei camera's radial model comes from --checkerboard; the laser fits R or alpha only.
			if (params.camera.mirror_model == MirrorModel::Paraboloid) keys.push_back({"R", formatDouble(c.R)});
			if (params.camera.mirror_model == MirrorModel::FirstOrder) keys.push_back({"alpha", formatDouble(c.alpha)});
			// With a calibrated shape (mei, ocamcalib) only the height is left to the laser;
			// for the paraboloid and first order, R or alpha absorb it.
			if (shape_calibrated) keys.push_back({"h", formatDouble(std::round(c.height.h * 1e4) / 1e4)});
			keys.push_back({"boundary_offset", formatDouble(c.suggested_boundary_offset)});
		}
		saveKeys(keys);
		say("wrote %zu keys into [%s] of %s\n", keys.size(), o_.section.c_str(), o_.save_to.c_str());
	}
	return c;
}

CheckerboardCalibration CalibrateApp::runIntrinsics()
{
	const CheckerboardCalibration c = calibrateFromCheckerboards(o_.checkerboards, o_.board);
	for (const auto& i : c.images)
		say("%s: %s%s\n", i.file.c_str(),
			i.found ? ("board found (" + i.detector + ")").c_str()
					: ("no board of " + std::to_string(o_.board.columns) + "x" + std::to_string(o_.board.rows) +
					   " inner corners found")
						  .c_str(),
			i.used ? (", reprojection " + std::to_string(i.rms).substr(0, 5) + " px").c_str()
			: !i.same_view_as.empty() ? (", not used: the board lies as in " + i.same_view_as).c_str()
			: (i.found ? ", not used: cv::omnidir could not start its fit from it" : ""));
	say("boards found in %d of %zu images, %d used; RMS reprojection error %.3f px\n", c.found(),
		c.images.size(), c.used(), c.rms);
	say("fx %.2f  fy %.2f  skew %.3f  cx %.2f  cy %.2f px;  xi %.4f;  k1 %.4f  k2 %.4f  p1 %.5f  p2 %.5f\n",
		c.K(0, 0), c.K(1, 1), c.K(0, 1), c.K(0, 2), c.K(1, 2), c.xi, c.D[0], c.D[1], c.D[2], c.D[3]);
	if (c.centre_subsets > 0)
		say("the centre moves up to %.2f px when a group of boards is left out (%d calibrations)\n",
			c.centre_spread, c.centre_subsets);

	std::vector<std::string> doubts;
	for (const auto& i : c.images)
		if (i.part_of_larger)
			doubts.push_back(i.file + ": a board one corner wider or taller is found there too: is --board " +
							 std::to_string(o_.board.columns) + "x" + std::to_string(o_.board.rows) +
							 " the count of inner corners? (OCamCalib and MATLAB count squares, one more each way)");
	if (c.rms > kMaxRms)
		doubts.push_back("the RMS reprojection error, " + formatDouble(std::round(c.rms * 100) / 100) +
						 " px, is over " + formatDouble(kMaxRms) + " px: is --board right? It counts inner corners (" +
						 std::to_string(o_.board.columns) + "x" + std::to_string(o_.board.rows) +
						 " here); OCamCalib and MATLAB count squares, one more each way");
	if (c.centre_subsets == 0)
		doubts.push_back("only " + std::to_string(c.used()) +
						 " boards were used: too few to tell whether they pin the centre down; add boards");
	if (c.centre_spread > kMaxCentreSpread)
		doubts.push_back("the centre moves " + formatDouble(std::round(c.centre_spread * 10) / 10) +
						 " px when a group of boards is left out (over " + formatDouble(kMaxCentreSpread) +
						 " px): the boards do not pin it down; add boards spread around the mirror");
	requireSure(doubts);
	// Both outputs or neither: the model is checked first, then the YAML and
	// the ini with its keys go in as one set.
	const CameraParams cam = meiCamera(c);
	if (!o_.save_to.empty())
		try
		{
			OmniCameraModel{cam};  // refuses a model whose radius does not grow up to the horizon
		}
		catch (const std::invalid_argument& e)
		{
			throw std::runtime_error("the checkerboards' calibration is no camera the rangefinder takes (" +
									 std::string(e.what()) + "); nothing saved");
		}
	const Output yaml{o_.intrinsics_output, OutputKind::Text, kOpenCvYamlBegins};
	const auto stageYaml = [&](OutputSet& set) {
		if (!yaml.path.empty()) set.write(yaml, c.yaml());
	};
	if (!o_.save_to.empty()) saveCameraKeys(cam, {"xi", "gamma", "aspect", "skew", "k1", "k2", "p1", "p2"}, stageYaml);
	else if (!yaml.path.empty())
	{
		OutputSet set(kProgram, inputs_);
		stageYaml(set);
		set.commit();
	}
	return c;
}

void CalibrateApp::requireSure(const std::vector<std::string>& doubts) const
{
	if (doubts.empty()) return;
	if (o_.accept)
	{
		for (const auto& d : doubts) std::fprintf(stderr, "omnirange-calibrate: warning: %s\n", d.c_str());
		return;
	}
	std::string all;
	for (const auto& d : doubts) all += (all.empty() ? "" : "; ") + d;
	throw std::runtime_error("the calibration may be wrong: " + all + ". Nothing saved; --accept saves it all the same");
}

std::optional<CameraParams> CalibrateApp::calibratedCamera()
{
	if (!o_.ini.empty()) return loadRangefinderIni(o_.ini, o_.section, *this).camera;
	try  // the --save-to ini may be a bare section waiting for keys: then there is nothing to compare
	{
		if (std::filesystem::exists(o_.save_to)) return RangefinderParams::loadFromFile(o_.save_to, o_.section).camera;
	}
	catch (const std::exception&)
	{
	}
	return std::nullopt;
}

MirrorRim CalibrateApp::runRim()
{
	const MirrorRim rim = detectMirrorRim(o_.rim_images);
	say("mirror disc: centre cx = %.1f px, cy = %.1f px; rim radius %.1f px; ellipticity %.3f (from %zu images; "
		"one image's own centre at most %.1f px from it)\n",
		rim.cx, rim.cy, rim.radius, rim.ellipticity, o_.rim_images.size(), rim.centre_spread);
	// A disc the whole image could not hold, or far from round, is not a mirror's rim.
	std::vector<std::string> doubts;
	if (rim.cx - rim.radius < 0 || rim.cy - rim.radius < 0 || rim.cx + rim.radius > rim.image_width ||
		rim.cy + rim.radius > rim.image_height)
		doubts.push_back("the disc found (radius " + formatDouble(std::round(rim.radius)) +
						 " px) reaches past the image: the rim is not all in view, or what was found is not the mirror");
	if (rim.centre_spread > kMaxRimOffset)
		doubts.push_back("one image's disc is " + formatDouble(std::round(rim.centre_spread * 10) / 10) +
						 " px from the centre of all (over " + formatDouble(kMaxRimOffset) +
						 " px): the camera or the mirror moved between the images, so the centre is of none of them");
	if (rim.ellipticity > kMaxEllipticity)
		doubts.push_back("the disc found is not round (ellipticity " + formatDouble(std::round(rim.ellipticity * 100) / 100) +
						 " > " + formatDouble(kMaxEllipticity) + "): its centre is not the mirror's");
	// A centre the checkerboards (or OCamCalib) calibrated is the better one: say if the disc disagrees.
	if (const auto cam = calibratedCamera(); cam)
		if (cam->mirror_model == MirrorModel::Mei || cam->mirror_model == MirrorModel::OCamCalib)
			if (const double off = std::hypot(rim.cx - cam->cx, rim.cy - cam->cy); off > kMaxRimOffset)
				doubts.push_back("the disc's centre is " + formatDouble(std::round(off)) + " px from the calibrated centre (" +
								 formatDouble(cam->cx) + ", " + formatDouble(cam->cy) + ") of the ini" +
								 ": the rim is not the mirror's, or the camera moved since it was calibrated");
	// The centre is a pixel of images this size: another camera's size (the -c ini's, or the one
	// --save-to writes into) would place it elsewhere.
	std::vector<std::pair<std::string, CameraParams>> cameras;
	if (const auto cam = calibratedCamera(); cam) cameras.emplace_back(o_.ini.empty() ? o_.save_to : o_.ini, *cam);
	if (!o_.ini.empty() && !o_.save_to.empty() && std::filesystem::exists(o_.save_to))
		try
		{
			cameras.emplace_back(o_.save_to, RangefinderParams::loadFromFile(o_.save_to, o_.section).camera);
		}
		catch (const std::exception&)
		{
		}
	for (const auto& [file, cam] : cameras)
		if (cam.image_width != rim.image_width || cam.image_height != rim.image_height)
		{
			doubts.push_back("the images are " + std::to_string(rim.image_width) + "x" + std::to_string(rim.image_height) +
							 " but the camera of " + file + " is " + std::to_string(cam.image_width) + "x" +
							 std::to_string(cam.image_height) + " (image_width, image_height): the centre would be written "
							 "for another camera");
			break;
		}
	requireSure(doubts);
	if (!o_.save_to.empty())
	{
		saveKeys({{"image_width", std::to_string(rim.image_width)},
				  {"image_height", std::to_string(rim.image_height)},
				  {"cx", formatDouble(std::round(rim.cx * 10) / 10)},
				  {"cy", formatDouble(std::round(rim.cy * 10) / 10)}});
		say("wrote image_width, image_height, cx, cy into [%s] of %s\n", o_.section.c_str(), o_.save_to.c_str());
	}
	return rim;
}

CameraParams CalibrateApp::runOCamCalib()
{
	const OCamCalibFile f = readOCamCalib(o_.ocamcalib);
	CameraParams cam;
	std::optional<OmniCameraModel> checked;
	try
	{
		cam = ocamCamera(f);
		checked.emplace(cam);  // refuses a polynomial whose angle does not grow
	}
	catch (const std::invalid_argument& e)  // the camera it describes is impossible: say which file
	{
		throw std::runtime_error(o_.ocamcalib + ": " + e.what());
	}
	const OmniCameraModel& model = *checked;
	say("OCamCalib model: %zu coefficients, centre cx = %.2f px, cy = %.2f px, image %d x %d; "
		"the horizon at %.1f px\n",
		f.poly.size(), cam.cx, cam.cy, cam.image_width, cam.image_height, model.horizonRho());
	say("affine terms c %.5f, d %.5f, e %.5f%s\n", f.c, f.d, f.e,
		model.radial() ? " (none: the image is radial)" : " (the scanlines follow them)");
	if (!o_.save_to.empty())
	{
		saveCameraKeys(cam, {"ocam_poly", "ocam_affine"});
	}
	return cam;
}

}  // namespace omnirange::app
