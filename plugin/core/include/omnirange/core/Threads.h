#pragma once
// How many threads OpenCV's parallel loops (rendering, scanning) may use.

namespace omnirange
{
/** Lets OpenCV use `threads` threads, at most as many as the machine has
 * cores: more would gain nothing, and TBB would say so on stderr. */
void useThreads(int threads);
}  // namespace omnirange
