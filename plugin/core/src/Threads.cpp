#include "omnirange/core/Threads.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <exception>
#include <vector>
#include <thread>

namespace omnirange
{
void useThreads(int threads)
{
	const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
	cv::setNumThreads(std::clamp(threads, 1, cores));
}

void forEachOnThreads(int n, const std::function<void(int)>& body)
{
	std::vector<std::exception_ptr> errors(static_cast<std::size_t>(std::max(0, n)));
	cv::parallel_for_(cv::Range(0, n), [&](const cv::Range& r) {
		for (int i = r.start; i < r.end; ++i) try
			{
				body(i);
			}
			catch (...)
			{
				errors[i] = std::current_exception();
			}
	});
	for (const std::exception_ptr& e : errors)
		if (e) std::rethrow_exception(e);
}
}  // namespace omnirange
