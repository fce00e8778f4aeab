#include "omnirange/RawlogTraining.h"

#include "omnirange/AtomicWrite.h"
#include "omnirange/ObservationImage.h"
#include "omnirange/RawlogReader.h"

#include <mrpt/obs/CObservationImage.h>

#include <cmath>
#include <set>

namespace omnirange
{
RawlogTrainingResult trainFromRawlog(const RangefinderParams& rp, const RawlogTrainingOptions& o,
									 const std::function<void(int)>& progress)
{
	if (o.every < 1 || o.first < 0 || o.max_frames < 0 || !(o.max_dt >= 0))
		throw std::invalid_argument("training: every must be >= 1; first, max_frames and max_dt >= 0");
	rp.validate();
	const OmniCameraModel camera(rp.camera);
	TrainingParams tp;
	tp.view_range = rp.scanner.max_range;
	tp.base_range = camera.distanceFromRho(rp.scanner.base_radius) + 0.05;  // the base, and a margin
	tp.bins = o.bins;
	tp.space = o.space;
	tp.laser_margin = o.laser_margin;
	HistogramTrainer trainer(camera, rp.sensor_pose, tp);

	RawlogReader reader(o.input);
	mrpt::obs::CObservationImage::Ptr last_img;
	mrpt::obs::CObservation2DRangeScan::Ptr last_scan;
	std::set<std::string> labels;
	RawlogTrainingResult r;
	while (auto obj = reader.next())
	{
		auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
		if (!obs) continue;
		labels.insert(obs->sensorLabel);
		if (auto im = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs); im && im->sensorLabel == o.omni_label)
			last_img = im;
		else if (auto sc = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs);
				 sc && sc->sensorLabel == o.laser_label)
			last_scan = sc;
		else
			continue;
		if (!last_img || !last_scan ||
			std::abs(mrpt::system::timeDifference(last_img->timestamp, last_scan->timestamp)) > o.max_dt)
			continue;
		// A synchronised pair: is it one we use?
		const int k = r.pairs++;
		const auto img = std::move(last_img);
		const auto scan = std::move(last_scan);
		last_img.reset();
		last_scan.reset();
		if (k < o.first || (k - o.first) % o.every != 0) continue;
		if (o.max_frames > 0 && r.used >= o.max_frames) break;

		const cv::Mat bgr = decodeImage(*img, rp.camera);
		const TrainingFrame f = trainer.add(bgr, *scan);
		r.pixels += f.pixels;
		if (!o.figures_prefix.empty() && r.used == o.figures_frame)
		{
			writeImageAtomically(o.figures_prefix + "_birdseye.png", f.birds_eye);
			writeImageAtomically(o.figures_prefix + "_laser.png", f.laser_free);
			writeImageAtomically(o.figures_prefix + "_fused.png", f.fused);
		}
		++r.used;
		if (progress) progress(r.used);
	}
	if (r.used == 0)
	{
		std::string all;
		for (const auto& l : labels) all += (all.empty() ? "" : ", ") + l;
		throw std::runtime_error("no " + o.omni_label + " image had a " + o.laser_label + " scan within " +
								 std::to_string(o.max_dt) + " s in '" + o.input + "' (labels found: " +
								 (all.empty() ? "none" : all) + "); training needs both");
	}
	if (trainer.histogram().empty()) throw std::runtime_error("no free-floor pixel was found to train on");
	r.histogram = trainer.histogram();
	return r;
}

}  // namespace omnirange
