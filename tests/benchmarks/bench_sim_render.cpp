// ms per rendered 1024x768 omnicam frame, on one core, in the stock worlds:
//   build/tests/benchmarks/omnirange_bench_sim_render --benchmark_repetitions=5
// The frame includes the per-frame ray casts, shading, anti-aliasing and
// noise; not the JPEG encoding (BM_EncodeJpeg times that alone).
#include <omnirange_sim/OmniRenderer.h>
#include <omnirange_sim/Route.h>

#include <benchmark/benchmark.h>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

namespace
{
using namespace omnirange::sim;
const std::string kSource = OMNIRANGE_SOURCE_DIR;

void BM_RenderFrame(benchmark::State& state, const std::string& name)
{
	cv::setNumThreads(1);
	const World world = loadWorld(kSource + "/worlds/" + name + ".world");
	const Route route = loadRoute(kSource + "/worlds/" + name + ".route");
	const auto poses = sampleTrajectory(route, 0.4, 0.6, 0.4);
	const RobotParams robot;
	const OmniRenderer renderer(world, robot);
	std::size_t k = 0;
	for (auto _ : state)
	{
		cv::Mat img = renderer.render(poses[k % poses.size()], k);
		benchmark::DoNotOptimize(img.data);
		k += 7;
	}
}
BENCHMARK_CAPTURE(BM_RenderFrame, factory, std::string("factory"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RenderFrame, maze, std::string("maze"))->Unit(benchmark::kMillisecond);

void BM_EncodeJpeg(benchmark::State& state)
{
	cv::setNumThreads(1);
	const World world = loadWorld(kSource + "/worlds/factory.world");
	const RobotParams robot;
	const cv::Mat img = OmniRenderer(world, robot).render({-6, -3, 0}, 1);
	std::vector<uchar> buf;
	for (auto _ : state) cv::imencode(".jpg", img, buf, {cv::IMWRITE_JPEG_QUALITY, 90});
}
BENCHMARK(BM_EncodeJpeg)->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
