#pragma once
// How many threads OpenCV's parallel loops (rendering, scanning) may use, and one such loop.

#include <functional>

namespace omnirange
{
/** Lets OpenCV use `threads` threads, at most as many as the machine has
 * cores: more would gain nothing, and TBB would say so on stderr. */
void useThreads(int threads);
/** body(i) for every i in [0, n) on OpenCV's threads; then the first
 * exception thrown (by index), if any, is thrown again here. */
void forEachOnThreads(int n, const std::function<void(int)>& body);
}  // namespace omnirange
