// What one change in omnirange-tuner costs (the target: <= 50 ms for
// 1024x768), as the window does it: the rangefinder rebuilt with the new
// value, the frame scanned, the image with every overlay and scaled to its
// shown width, the scan plot, the bird's-eye view rebuilt and drawn, the floor
// colours and the error plot. Frame 5 of the factory sample, a histogram
// trained on the sample. The window's conversion to a wxBitmap and its repaint
// need a display and come on top (the tuner's status bar shows the whole update).
#include <omnirange_tuner/Overlays.h>
#include <omnirange_tuner/TunerSession.h>

#include <omnirange/train/BirdsEyeView.h>

#include <opencv2/imgproc.hpp>

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

constexpr int kShownWidth = 660;  // the image's width in the window on a 1280x720 screen
constexpr int kPlot = 300, kSmall = 146;

cv::Mat shown(const cv::Mat& img)
{
	cv::Mat out;
	cv::resize(img, out, cv::Size(kShownWidth, img.rows * kShownWidth / img.cols), 0, 0, cv::INTER_AREA);
	return out;
}

static void BM_TunerUpdate(benchmark::State& state)
{
	auto& s = session();
	s.scan(5);  // the frame decoded once, as when a control changes
	const omnirange::tuner::LogScore score = s.scoreAll();
	const omnirange::tuner::OverlayOptions all{true, true, true, true, true, true, true, true, 8};
	bool flip = false;
	for (auto _ : state)
	{
		omnirange::RangefinderParams p = s.params();
		p.threshold = (flip = !flip) ? 0.08 : 0.075;  // a control changed: the rangefinder is rebuilt
		s.changeParams(p);
		const auto f = s.scan(5);
		benchmark::DoNotOptimize(shown(omnirange::tuner::drawOmniOverlay(f, s.rangefinder(), all)));
		benchmark::DoNotOptimize(omnirange::tuner::drawScanPlot(f, s.params(), kPlot));
		const omnirange::BirdsEyeView view(s.rangefinder().camera(), kSmall, 2 * s.params().scanner.max_range / kSmall);
		benchmark::DoNotOptimize(view.render(f.bgr));
		benchmark::DoNotOptimize(
			omnirange::tuner::drawFloorColours(s.colours(), s.rangefinder().classifier(), cv::Size(kSmall, kSmall)));
		benchmark::DoNotOptimize(omnirange::tuner::drawErrorPlot(score, 5, cv::Size(520, 64)));
	}
}
BENCHMARK(BM_TunerUpdate)->Unit(benchmark::kMillisecond);

/** Moving to another frame: its JPEG decoded, scanned and drawn; the bird's-eye view's table kept. */
static void BM_TunerNextFrame(benchmark::State& state)
{
	auto& s = session();
	int k = 0;
	const omnirange::tuner::OverlayOptions all{true, true, true, true, true, true, true, true, 8};
	const omnirange::BirdsEyeView view(s.rangefinder().camera(), kSmall, 2 * s.params().scanner.max_range / kSmall);
	for (auto _ : state)
	{
		const auto f = s.scan(k = (k + 1) % s.frames());
		benchmark::DoNotOptimize(shown(omnirange::tuner::drawOmniOverlay(f, s.rangefinder(), all)));
		benchmark::DoNotOptimize(omnirange::tuner::drawScanPlot(f, s.params(), kPlot));
		benchmark::DoNotOptimize(view.render(f.bgr));
	}
}
BENCHMARK(BM_TunerNextFrame)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
