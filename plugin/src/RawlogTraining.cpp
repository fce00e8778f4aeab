#include "omnirange/RawlogTraining.h"

#include "omnirange/AtomicWrite.h"
#include "omnirange/ImageScanPairer.h"
#include "omnirange/ObservationImage.h"
#include "omnirange/RawlogReader.h"


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
	ImageScanPairer pairer(o.omni_label, o.laser_label, o.max_dt);
	RawlogTrainingResult r;
	while (auto obj = reader.next())
	{
		if (!pairer.add(obj)) continue;
		// A synchronised pair: is it one we use?
		const int k = r.pairs++;
		if (k < o.first || (k - o.first) % o.every != 0) continue;
		if (o.max_frames > 0 && r.used >= o.max_frames) break;

		const auto& img = pairer.image();
		const auto& scan = pairer.scan();
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
	if (r.used == 0) throw std::runtime_error(pairer.noPairError(o.input));
	if (trainer.histogram().empty()) throw std::runtime_error("no free-floor pixel was found to train on");
	r.histogram = trainer.histogram();
	return r;
}

}  // namespace omnirange
