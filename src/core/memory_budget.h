// How much memory a computation may take: the machine's physical memory, and refusing, with the numbers, a
// request that cannot fit (a mesh of billions of elements, a dense matrix of terabytes) before it is
// attempted. Failing later in the allocator says only "std::bad_alloc", and may first push the machine into
// swap.
#pragma once

#include <cstddef>
#include <string>

namespace rt {

// Physical memory of this machine in bytes (sysconf); RT_MEMORY_LIMIT_MB in the environment lowers it (tests
// and sanitizer runs use it to stay small).
double memoryBudgetBytes();

// "512 MB", "1.5 GB", "3.2 TB".
std::string formatBytes(double bytes);

// "12,345,678" for counts in messages.
std::string formatCount(double count);

}  // namespace rt
