#include "omnirange/train/RawlogTraining.h"

#include <omnirange/config/Output.h>
#include "omnirange/io/ObservationImage.h"
#include "omnirange/io/RawlogProcessor.h"

#include <mrpt/obs/CObservationImage.h>

namespace omnirange
{
void RawlogTrainingOptions::validate() const
{
	require(every >= 1, "every must be >= 1");
	require(first >= 0 && max_frames >= 0 && until >= 0, "first, until and max_frames must be >= 0");
	require(figures_frame >= 0, "figures_frame must be >= 0");
	requirePairingDt(max_dt);
	TrainingParams::table().requireRanges(training);
}

RawlogTrainingResult trainFromRawlog(const RangefinderParams& rp, const RawlogTrainingOptions& o, Progress* progress)
{
	using mrpt::obs::CObservation2DRangeScan;
	using mrpt::obs::CObservationImage;
	o.validate();
	rp.validate();
	const OmniCameraModel camera(rp.camera);
	// Beyond the base, out to the max range the scans will use.
	HistogramTrainer trainer(camera, rp.sensor_pose, floorBeyondBase(camera, rp.scanner), rp.scanner.max_range,
							 o.training);

	RawlogProcessor loop(o.input);
	RawlogTrainingResult r;
	loop.onPair<CObservationImage, CObservation2DRangeScan>(
		o.omni_label, o.laser_label, o.max_dt,
		[&](const CObservationImage::Ptr& image, const CObservation2DRangeScan::Ptr& laser) {
			const int k = r.pairs++;
			if (!o.selects(k)) return;  // keep counting the pairs
			if (o.max_frames > 0 && r.used >= o.max_frames) return loop.stop();
			const TrainingFrame f = trainer.add(decodeImage(*image, rp.camera), *laser);
			r.pixels += f.pixels;
			r.obstacle_pixels += f.obstacle_pixels;
			// Kept, not written: a run that fails later (a cut image) must not have replaced them.
			if (!o.figures_prefix.empty() && r.used == o.figures_frame) r.figures = f;
			++r.used;
		});
	loop.run(progress);
	if (r.pairs == 0) throw std::runtime_error(loop.describeNoPair() + "; training needs both");
	if (r.used == 0)
		throw std::runtime_error("none of the " + std::to_string(r.pairs) + " image/scan pairs of '" + o.input +
								 "' was selected (first = " + std::to_string(o.first) + ")");
	if (!o.figures_prefix.empty() && o.figures_frame >= r.used)
		throw std::runtime_error("figures_frame " + std::to_string(o.figures_frame) + " is past the " +
								 std::to_string(r.used) + " pairs used");
	if (trainer.histogram().empty()) throw std::runtime_error("no free-floor pixel was found to train on");
	r.model = trainer.model();
	return r;
}

std::vector<std::pair<std::string, cv::Mat>> figureFiles(const RawlogTrainingResult& r, const std::string& prefix)
{
	return {{prefix + "_birdseye.png", r.figures.birds_eye},
			{prefix + "_laser.png", r.figures.laser_free},
			{prefix + "_fused.png", r.figures.fused}};
}

}  // namespace omnirange
