// One decoded 1024x768 omnicam frame -> one 360-ray scan, with the paper's
// parameters (N = 20, K = 2, Theta = 0.05). Run:
//   build/tests/benchmarks/omnirange_bench_rangefinder --benchmark_repetitions=10
// (defaults otherwise: the sub-pixel boundary.) The frame is a room drawn through the camera model: a noisy floor texture,
// walls between 0.8 m and 3.5 m, and a doorway the rays see past max range.
#include "SyntheticOmni.h"

#include <omnirange/core/Rangefinder.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

using namespace omnirange;

namespace
{
cv::Mat noisy(const cv::Mat& img, std::uint32_t seed)
{
	cv::Mat out = img.clone();
	std::mt19937 rng(seed);
	std::normal_distribution<float> n(0.f, 6.f);
	for (auto it = out.begin<cv::Vec3b>(); it != out.end<cv::Vec3b>(); ++it)
		for (int c = 0; c < 3; ++c)
			(*it)[c] = cv::saturate_cast<std::uint8_t>((*it)[c] + n(rng));
	return out;
}

struct Scene
{
	RangefinderParams params;
	cv::Mat frame;
	ColourHistogram histogram;

	/** open: no wall within max range, so every scanline is read to its end
	 * (the worst case). */
	explicit Scene(bool open)
	{
		const OmniCameraModel cam{params.camera};
		const cv::Mat clean = test::drawOmni(cam, [open](const FloorPoint& f) {
			if (open) return std::hypot(f.x, f.y) > 4.5;
			const bool doorway = f.x < -1.0 && std::abs(f.y) < 0.5;
			return (f.x > 1.6 || f.x < -3.5 || f.y > 0.8 || f.y < -2.4) && !doorway;
		});
		frame = noisy(clean, 1);
		// Train on the floor pixels of a second noisy frame of the same room.
		const cv::Mat train = noisy(clean, 2);
		cv::Mat mask(clean.size(), CV_8UC1);
		for (int v = 0; v < clean.rows; ++v)
			for (int u = 0; u < clean.cols; ++u)
				mask.at<std::uint8_t>(v, u) = clean.at<cv::Vec3b>(v, u) == test::kFloor ? 255 : 0;
		histogram.addImage(train, mask);
	}
};

const Scene& scene(bool open)
{
	static const Scene room(false), field(true);
	return open ? field : room;
}

/** Times rf on the scene's frame, counting the last scan's hits. */
void timeScans(benchmark::State& state, const Rangefinder& rf, const Scene& scene)
{
	int hits = 0, unsure = 0;
	for (auto _ : state)
	{
		const RangeScan scan = rf.process(scene.frame);
		hits = scan.count(RayStatus::Hit), unsure = scan.count(RayStatus::Unsure);
		benchmark::DoNotOptimize(scan.rays.data());
	}
	state.counters["hit_rays"] = hits;
	state.counters["unsure_rays"] = unsure;
}

void BM_FrameToScan(benchmark::State& state)
{
	const Scene& scene = ::scene(state.range(0) != 0);
	timeScans(state, Rangefinder(scene.params, scene.histogram), scene);
}
// Arg 0: the room; arg 1: open floor, every ray to max range.
BENCHMARK(BM_FrameToScan)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/** The same without the doubt (sure_run = 0, the paper's two outcomes): what
 * the second search along each ray's free stretch costs. */
void BM_FrameToScanWithoutDoubt(benchmark::State& state)
{
	const Scene& scene = ::scene(state.range(0) != 0);
	RangefinderParams p = scene.params;
	p.scanner.sure_run = 0;
	timeScans(state, Rangefinder(p, scene.histogram), scene);
}
BENCHMARK(BM_FrameToScanWithoutDoubt)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_FrameToObservation(benchmark::State& state)
{
	const Scene& scene = ::scene(false);
	const Rangefinder rf(scene.params, scene.histogram);
	for (auto _ : state)
	{
		auto obs = rf.toObservation(rf.process(scene.frame), mrpt::Clock::now());
		benchmark::DoNotOptimize(obs.get());
	}
}
BENCHMARK(BM_FrameToObservation)->Unit(benchmark::kMillisecond);

// The same frame with what the defaults add when the histogram file records
// the floor's colour: exposure compensation (the ring's median, classifying
// through gains) and the sub-pixel boundary (on by default in both). The
// training light is 5 % brighter, past the dead band, so the gains are used
// (within it the compensation costs the ring's median only). Arg 1: with the
// brightness step as well, as learning may set it.
void BM_FrameToScanCompensated(benchmark::State& state)
{
	const Scene& scene = ::scene(false);
	RangefinderParams p = scene.params;
	p.scanner.step_threshold = state.range(0) != 0 ? 0.35 : 0.0;
	ColourModel model(scene.histogram);
	const OmniCameraModel cam{scene.params.camera};
	model.reference = FloorRing(cam, cam.distanceFromRho(scene.params.scanner.base_radius) + 0.05).medianColour(scene.frame);
	for (double& c : model.reference) c *= 1.05;
	const Rangefinder rf(p, model);
	for (auto _ : state)
	{
		const RangeScan scan = rf.process(scene.frame);
		benchmark::DoNotOptimize(scan.rays.data());
	}
}
BENCHMARK(BM_FrameToScanCompensated)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The compensated frame's stages, as shares of the whole [%]: where a faster
// frame must come from.
void BM_StageShares(benchmark::State& state)
{
	const Scene& scene = ::scene(false);
	ColourModel model(scene.histogram);
	const OmniCameraModel cam{scene.params.camera};
	model.reference = FloorRing(cam, cam.distanceFromRho(scene.params.scanner.base_radius) + 0.05).medianColour(scene.frame);
	for (double& c : model.reference) c *= 1.05;
	const Rangefinder rf(scene.params, model);
	StageTimes sum;
	for (auto _ : state)
	{
		StageTimes t;
		const RangeScan scan = rf.process(scene.frame, nullptr, &t);
		benchmark::DoNotOptimize(scan.rays.data());
		sum.light += t.light, sum.scan += t.scan, sum.outliers += t.outliers, sum.walls += t.walls;
	}
	const double all = sum.light + sum.scan + sum.outliers + sum.walls;
	state.counters["light_%"] = 100 * sum.light / all;
	state.counters["scan_%"] = 100 * sum.scan / all;
	state.counters["outliers_%"] = 100 * sum.outliers / all;
	state.counters["walls_%"] = 100 * sum.walls / all;
}
BENCHMARK(BM_StageShares)->Unit(benchmark::kMillisecond);

// The room with the brightness step on (learning switches it on where it
// helps): each scanline is read again for steps up to the colour's hit.
void BM_FrameToScanWithBrightnessStep(benchmark::State& state)
{
	const Scene& scene = ::scene(state.range(0) != 0);
	RangefinderParams p = scene.params;
	p.scanner.step_threshold = 0.35;
	const Rangefinder rf(p, scene.histogram);
	int by_step = 0;
	for (auto _ : state)
	{
		const RangeScan scan = rf.process(scene.frame);
		by_step = 0;
		for (const Ray& r : scan.rays) by_step += r.by_step;
		benchmark::DoNotOptimize(scan.rays.data());
	}
	state.counters["rays_ended_by_step"] = by_step;
}
BENCHMARK(BM_FrameToScanWithBrightnessStep)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The room with a learned edge bias: every bin set, so each hit is moved.
void BM_FrameToScanWithEdgeBias(benchmark::State& state)
{
	const Scene& scene = ::scene(false);
	RangefinderParams p = scene.params;
	p.scanner.edge_bias.assign(kEdgeContrastBins, 0.03);
	timeScans(state, Rangefinder(p, scene.histogram), scene);
}
BENCHMARK(BM_FrameToScanWithEdgeBias)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
