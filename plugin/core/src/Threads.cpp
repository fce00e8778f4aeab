#include "omnirange/core/Threads.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <thread>

namespace omnirange
{
void useThreads(int threads)
{
	const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
	cv::setNumThreads(std::clamp(threads, 1, cores));
}
}  // namespace omnirange
