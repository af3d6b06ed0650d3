#pragma once

// Live heap bytes of the executable that links allocationcounter.cpp, which
// replaces the global operator new and delete (every form) to count the
// usable size of each block (malloc_usable_size: the request rounded up to
// the allocator's granule, not its per-block header). Only the series
// benchmark links it, so no other figure pays for the counting.

#include <cstddef>

namespace allocations {

std::size_t live();
// The highest live() since the last resetPeak() (which sets it to live()).
std::size_t peak();
void resetPeak();

} // namespace allocations
