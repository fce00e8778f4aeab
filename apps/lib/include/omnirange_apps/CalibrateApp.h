#pragma once
// omnirange-calibrate: fit the mirror's R (paraboloid) or alpha (first-order
// model) against a laser (paper §IV-D), and say where the boundary sits; or
// the camera's intrinsics from checkerboard images (--checkerboard); or the
// mirror disc's centre and radius from ordinary images (--rim).

#include <omnirange/train/CheckerboardCalibration.h>
#include <omnirange/train/OCamCalibFile.h>
#include <omnirange/train/MirrorCalibration.h>
#include <omnirange/train/MirrorRim.h>
#include <omnirange/train/OrientationFit.h>

#include <mrpt/system/COutputLogger.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace omnirange
{
class OutputSet;
}

namespace omnirange::app
{
class CalibrateApp : public mrpt::system::COutputLogger
{
   public:
	struct Options
	{
		std::string ini, section{kRangefinderSection}, histogram;
		MirrorCalibrationOptions calibration;
		std::vector<std::string> checkerboards;  ///< images: calibrate the intrinsics instead
		std::string checkerboard_dir;  ///< --checkerboard-dir: an input folder, never an output's place
		CheckerboardOptions board;
		std::string intrinsics_output;  ///< OpenCV YAML; empty: print only
		std::vector<std::string> rim_images;  ///< images: find the mirror's disc instead
		std::string ocamcalib;  ///< OCamCalib's calib_results.txt: take the camera from it instead
		std::string save_to;  ///< ini to write what was found into (its [section]); empty: print only
		/** Save and exit 0 even when the result looks unsure (requireSure()). */
		bool accept{false};
		mrpt::system::VerbosityLevel verbosity{mrpt::system::LVL_INFO};
	};
	/** Throws ExitRequest on --help or a command-line mistake. */
	static Options parse(int argc, const char* const* argv);

	explicit CalibrateApp(Options o);
	const Options& options() const { return o_; }
	/** What the command line asked for: each of --rim, --checkerboard and
	 * --ocamcalib given, in that order, or else the fit against the laser. */
	void runModes();
	/** Against the laser: fits and prints the result on stdout. */
	MirrorCalibration run();
	/** With checkerboard images: calibrates the intrinsics, prints them and
	 * each image's result, and writes the YAML file if asked. */
	CheckerboardCalibration runIntrinsics();
	/** With --rim images: finds and prints the mirror disc's centre and radius. */
	MirrorRim runRim();
	/** With --ocamcalib: reads calib_results.txt, prints what the rangefinder
	 * takes from it and what it leaves out, and saves it if asked. */
	CameraParams runOCamCalib();
	/** After run(): the camera's orientation fitted against the laser. */
	const OrientationFit& orientation() const { return orientation_; }

   private:
	/** printf() on stdout unless -q: the results are the summary -q leaves out. */
	void say(const char* format, ...) const __attribute__((format(printf, 2, 3)));
	/** The camera of the -c ini, or of the --save-to ini when it loads; none otherwise. */
	std::optional<CameraParams> calibratedCamera();
	/** Unless --accept, an error naming every doubt (one line): nothing is
	 * saved from a calibration that says it may be wrong. With --accept,
	 * each doubt is a warning on stderr. */
	void requireSure(const std::vector<std::string>& doubts) const;
	/** `keys` into [section] of --save-to, with `with` as one set, checked
	 * against the inputs again (an ini replaced meanwhile by a link to its
	 * base). */
	void saveKeys(const std::vector<std::pair<std::string, std::string>>& keys,
				  const std::function<void(OutputSet&)>& with = {}) const;
	/** A calibrated camera's keys (the image, the centre, the model and its `model_keys`), saved and said. */
	void saveCameraKeys(const CameraParams& cam, const std::vector<std::string>& model_keys,
						const std::function<void(OutputSet&)>& with = {}) const;
	Options o_;
	/** What the run reads, as found at the start (the -c ini's bases included). */
	std::vector<std::string> inputs_;
	/** The file --save-to leads to at the start, through links. */
	std::string save_to_file_;
	OrientationFit orientation_;
};

}  // namespace omnirange::app
