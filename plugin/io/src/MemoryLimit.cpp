#include "omnirange/io/MemoryLimit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

// GCC says -fsanitize=address with __SANITIZE_ADDRESS__, clang with __has_feature.
#if defined(__SANITIZE_ADDRESS__)
#define OMNIRANGE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define OMNIRANGE_ASAN 1
#endif
#endif

namespace omnirange
{
std::size_t capAddressSpaceAtHalfTheMemory()
{
#ifdef OMNIRANGE_ASAN
	return 0;
#else
	const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
	if (pages <= 0 || page <= 0) return 0;
	const rlim_t cap = std::max<rlim_t>(static_cast<rlim_t>(pages) * static_cast<rlim_t>(page) / 2, rlim_t{4} << 30);
	rlimit now{};
	if (::getrlimit(RLIMIT_AS, &now) != 0) return 0;
	if (now.rlim_cur != RLIM_INFINITY && now.rlim_cur <= cap) return 0;
	const rlimit lower{std::min(cap, now.rlim_max), now.rlim_max};
	return ::setrlimit(RLIMIT_AS, &lower) == 0 ? static_cast<std::size_t>(lower.rlim_cur) : 0;
#endif
}

void restoreAddressSpaceLimit()
{
	rlimit now{};
	if (::getrlimit(RLIMIT_AS, &now) != 0) return;
	now.rlim_cur = now.rlim_max;
	::setrlimit(RLIMIT_AS, &now);
}

}  // namespace omnirange
