// omnirange-train: rawlog with OMNICAM + LASER -> colour histogram of the
// free floor (paper §III-A1), and the three images of paper Fig. 1.
#include "AppMain.h"
#include "Progress.h"
#include "RangefinderIni.h"

#include <omnirange/AtomicWrite.h>
#include <omnirange/HistogramTrainer.h>
#include <omnirange/ObservationImage.h>
#include <omnirange/RawlogReader.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>

#include <cmath>
#include <set>

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
		if (every.getValue() < 1 || first.getValue() < 0 || max_frames.getValue() < 0 || !(sync.getValue() >= 0))
			throw std::invalid_argument("--every must be >= 1; --first, --max-frames and --max-dt >= 0");

		const RangefinderParams rp = app::loadRangefinderIni(ini.getValue(), section.getValue());
		const OmniCameraModel camera(rp.camera);
		TrainingParams tp;
		tp.view_range = rp.scanner.max_range;
		tp.base_range = camera.distanceFromRho(rp.scanner.base_radius) + 0.05;
		tp.bins = bins.getValue();
		tp.space = colourSpaceFromString(space.getValue());
		tp.laser_margin = margin.getValue();
		HistogramTrainer trainer(camera, rp.sensor_pose, tp);

		RawlogReader reader(in.getValue());
		mrpt::obs::CObservationImage::Ptr last_img;
		mrpt::obs::CObservation2DRangeScan::Ptr last_scan;
		std::set<std::string> labels;
		int pairs = 0, used = 0;
		std::size_t pixels = 0;
		while (auto obj = reader.next())
		{
			auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
			if (!obs) continue;
			labels.insert(obs->sensorLabel);
			if (auto im = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs); im && im->sensorLabel == omni.getValue())
				last_img = im;
			else if (auto sc = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs); sc && sc->sensorLabel == laser.getValue())
				last_scan = sc;
			else
				continue;
			if (!last_img || !last_scan ||
				std::abs(mrpt::system::timeDifference(last_img->timestamp, last_scan->timestamp)) > sync.getValue())
				continue;
			// A synchronised pair: is it one we use?
			const int k = pairs++;
			const auto img = last_img;
			const auto scan = last_scan;
			last_img.reset();
			last_scan.reset();
			if (k < first.getValue() || (k - first.getValue()) % every.getValue() != 0) continue;
			if (max_frames.getValue() > 0 && used >= max_frames.getValue()) break;

			const cv::Mat bgr = decodeImage(*img);
			if (bgr.cols != rp.camera.image_width || bgr.rows != rp.camera.image_height)
				throw std::runtime_error(
					"image '" + img->image.getExternalStorageFile() + "' is " + std::to_string(bgr.cols) + "x" +
					std::to_string(bgr.rows) + " but " + ini.getValue() + " says " +
					std::to_string(rp.camera.image_width) + "x" + std::to_string(rp.camera.image_height));
			const TrainingFrame f = trainer.add(bgr, *scan);
			pixels += f.pixels;
			if (!figures.getValue().empty() && used == figure_frame.getValue())
			{
				const std::string pre = figures.getValue();
				for (const auto& [name, mat] : {std::pair<std::string, cv::Mat>{"_birdseye.png", f.birds_eye},
												{"_laser.png", f.laser_free}, {"_fused.png", f.fused}})
					writeImageAtomically(pre + name, mat);
			}
			++used;
			if (!quiet.getValue()) app::showProgress("pairs used", used, max_frames.getValue() > 0 ? max_frames.getValue() : used);
		}
		if (used == 0)
		{
			std::string all;
			for (const auto& l : labels) all += (all.empty() ? "" : ", ") + l;
			throw std::runtime_error(
				"no " + omni.getValue() + " image had a " + laser.getValue() + " scan within " +
				std::to_string(sync.getValue()) + " s in '" + in.getValue() + "' (labels found: " +
				(all.empty() ? "none" : all) + "); training needs both");
		}
		if (trainer.histogram().empty()) throw std::runtime_error("no free-floor pixel was found to train on");
		trainer.histogram().save(out.getValue());
		if (!quiet.getValue())
			std::printf("trained on %d image/scan pairs (of %d), %zu floor pixels -> %s\n", used, pairs, pixels,
						out.getValue().c_str());
		return 0;
	});
}
