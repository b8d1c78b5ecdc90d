#include "base/populated_memory.h"

#include "base/parallel.h"

#include <cstdint>
#include <sys/mman.h>

void populatePages(void* data, std::size_t bytes) {
    constexpr std::uintptr_t page = 4096;
    const auto address = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t first = (address + page - 1) / page, last = (address + bytes) / page;
    if (last <= first) return;
    const std::vector<IndexRange> ranges = splitRange(last - first, 256); // 1 MiB at least
    parallelFor(ranges.size(), [&](std::size_t k) {
        ::madvise(reinterpret_cast<void*>((first + ranges[k].begin) * page),
                  (ranges[k].end - ranges[k].begin) * page, MADV_POPULATE_WRITE);
    });
}
