#pragma once
// MRPT sizes strings, vectors and deques from a rawlog's length fields before
// it reads their contents, so a corrupt rawlog can ask for more memory than
// the machine has, element by element, until the kernel's out-of-memory
// killer ends something. The apps cap their own address space instead: then
// such a rawlog ends in std::bad_alloc, which the reader reports as an error
// naming the file (docs/robustness.md).

#include <cstddef>

namespace omnirange
{
/** Lowers this process's soft address-space limit (RLIMIT_AS) to half the
 * machine's physical memory, at least 4 GiB, unless it is lower already or
 * the process runs under AddressSanitizer (which reserves terabytes of
 * address space for itself). Returns the limit set, 0 if none. */
std::size_t capAddressSpaceAtHalfTheMemory();
/** Back to the hard limit: for a program this process starts (MRPT's own
 * programs have their own needs). */
void restoreAddressSpaceLimit();

}  // namespace omnirange
