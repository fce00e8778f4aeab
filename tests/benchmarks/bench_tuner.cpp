// What one change in omnirange-tuner costs (the target: <= 50 ms for
// 1024x768): scan the frame, draw the image with every overlay, the scan
// plot and the floor colours. Frame 5 of the factory sample, a histogram
// trained on the sample. The window's own conversion to a wxBitmap and its
// repaint come on top (the tuner's status bar shows the whole update).
#include <omnirange_tuner/Overlays.h>
#include <omnirange_tuner/TunerSession.h>

#include <benchmark/benchmark.h>

#include <filesystem>

namespace
{
omnirange::tuner::TunerSession& session()
{
	static omnirange::tuner::TunerSession s = [] {
		omnirange::tuner::SessionOptions o;
		o.rawlog = std::string(OMNIRANGE_SOURCE_DIR) + "/rawlogs/factory-sample.rawlog";
		o.ini = std::string(OMNIRANGE_SOURCE_DIR) + "/ini/factory.ini";
		omnirange::tuner::TunerSession t(o);
		t.train((std::filesystem::temp_directory_path() / "omnirange_bench_tuner.hist").string());
		return t;
	}();
	return s;
}
}  // namespace

static void BM_TunerUpdate(benchmark::State& state)
{
	auto& s = session();
	s.scan(5);  // the frame decoded once, as when a control changes
	const omnirange::tuner::OverlayOptions all{true, true, true, true, true, true, true, true, 8};
	for (auto _ : state)
	{
		const auto f = s.scan(5);
		benchmark::DoNotOptimize(omnirange::tuner::drawOmniOverlay(f, s.rangefinder(), all));
		benchmark::DoNotOptimize(omnirange::tuner::drawScanPlot(f, s.params(), 340));
		benchmark::DoNotOptimize(
			omnirange::tuner::drawFloorColours(s.colours(), s.rangefinder().classifier(), cv::Size(168, 168)));
	}
}
BENCHMARK(BM_TunerUpdate)->Unit(benchmark::kMillisecond);

/** Moving to another frame also decodes its JPEG. */
static void BM_TunerNextFrame(benchmark::State& state)
{
	auto& s = session();
	int k = 0;
	const omnirange::tuner::OverlayOptions all{true, true, true, true, true, true, true, true, 8};
	for (auto _ : state)
	{
		const auto f = s.scan(k = (k + 1) % s.frames());
		benchmark::DoNotOptimize(omnirange::tuner::drawOmniOverlay(f, s.rangefinder(), all));
		benchmark::DoNotOptimize(omnirange::tuner::drawScanPlot(f, s.params(), 340));
	}
}
BENCHMARK(BM_TunerNextFrame)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
