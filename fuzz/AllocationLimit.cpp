// Linked into every fuzz target: one allocation above 1 GiB throws
// std::bad_alloc, as it would on a machine without that memory. MRPT sizes
// strings and vectors from a rawlog's length fields before reading them, so
// a corrupt length asks for gigabytes; the reader must report that as an
// error (RawlogReader does), and this makes the fuzz run see it quickly and
// the same way under ASan, whose own operator new aborts instead of throwing.

#include <cstdlib>
#include <new>

namespace
{
constexpr std::size_t kLimit = std::size_t{1} << 30;

void* allocate(std::size_t size)
{
	if (size > kLimit) throw std::bad_alloc();
	if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
	throw std::bad_alloc();
}
}  // namespace

// Every form of new and delete is replaced, so that each pair meets in
// malloc and free (ASan checks that pairs match).
void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
	return size > kLimit ? nullptr : std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void* operator new(std::size_t size, std::align_val_t align)
{
	if (size > kLimit) throw std::bad_alloc();
	const std::size_t a = static_cast<std::size_t>(align);
	if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a)) return p;
	throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t align) { return operator new(size, align); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
