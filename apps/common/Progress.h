#pragma once
#include <unistd.h>

#include <cstdio>
#include <string>

namespace omnirange::app
{
/** "what: done/total" rewritten in place on a terminal; silent otherwise. */
inline void showProgress(const std::string& what, int done, int total)
{
	static const bool tty = ::isatty(2) != 0;
	if (!tty) return;
	std::fprintf(stderr, "\r%s: %d/%d", what.c_str(), done, total);
	if (done == total) std::fprintf(stderr, "\n");
	std::fflush(stderr);
}
}  // namespace omnirange::app
