// The live sensor's path (COmniRangefinderSensor::doProcess) from a camera's
// JPEG to the observations handed to rawlog-grabber, per stage: decode the
// whole image (the observation keeps it), copy it into the observation,
// scan, make the CObservation2DRangeScan. Run:
//   build/tests/benchmarks/omnirange_bench_sensor
// Frames: the factory sample's 1024x768 JPEGs, with the factory ini; the
// floor's colours from the ring beyond the base of its first image.
#include <omnirange/core/Rangefinder.h>
#include <omnirange/io/ObservationImage.h>

#include <benchmark/benchmark.h>
#include <mrpt/obs/CObservationImage.h>

#include <chrono>
#include <filesystem>

using namespace omnirange;

namespace
{
const std::string kSource = OMNIRANGE_SOURCE_DIR;

std::vector<mrpt::obs::CObservationImage::Ptr> sampleFrames()
{
	std::vector<std::string> files;
	for (const auto& e : std::filesystem::directory_iterator(kSource + "/rawlogs/factory-sample_Images"))
		if (e.path().extension() == ".jpg") files.push_back(e.path().string());
	std::sort(files.begin(), files.end());
	std::vector<mrpt::obs::CObservationImage::Ptr> frames;
	for (const auto& f : files)
	{
		auto obs = mrpt::obs::CObservationImage::Create();
		obs->sensorLabel = "OMNICAM";
		obs->image.setExternalStorage(f);
		frames.push_back(obs);
	}
	return frames;
}

Rangefinder factoryRangefinder(const cv::Mat& first)
{
	const RangefinderParams p = RangefinderParams::loadFromFile(kSource + "/ini/factory.ini", "rangefinder");
	const OmniCameraModel camera(p.camera);
	ColourHistogram h;
	for (const cv::Vec3b& c : FloorRing(camera, floorBeyondBase(camera, p.scanner)).colours(first)) h.addPixel(&c[0]);
	return Rangefinder(p, ColourModel(h));
}

void BM_SensorFrameToObservations(benchmark::State& state)
{
	using Clock = std::chrono::steady_clock;
	const auto frames = sampleFrames();
	const Rangefinder rf = factoryRangefinder(decodeImage(*frames.front()));
	double decode = 0, copy = 0, scan = 0, observation = 0;
	std::size_t n = 0;
	for (auto _ : state)
	{
		const auto& img = frames[n++ % frames.size()];
		const auto t0 = Clock::now();
		const cv::Mat bgr = decodeImage(*img);
		const auto t1 = Clock::now();
		mrpt::img::CImage kept(bgr, mrpt::img::DEEP_COPY);
		const auto t2 = Clock::now();
		const RangeScan rays = rf.process(bgr);
		const auto t3 = Clock::now();
		const auto obs = rf.toObservation(rays, img->timestamp);
		const auto t4 = Clock::now();
		benchmark::DoNotOptimize(obs.get());
		const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
		decode += ms(t0, t1), copy += ms(t1, t2), scan += ms(t2, t3), observation += ms(t3, t4);
	}
	const double k = 1.0 / static_cast<double>(n);
	state.counters["decode_ms"] = decode * k;
	state.counters["copy_ms"] = copy * k;
	state.counters["scan_ms"] = scan * k;
	state.counters["observation_ms"] = observation * k;
}
BENCHMARK(BM_SensorFrameToObservations)->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
