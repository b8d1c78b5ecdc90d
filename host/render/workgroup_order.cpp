#include "render/workgroup_order.h"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

std::uint32_t workgroupStride(std::uint32_t workgroupCount) {
    if (workgroupCount > kMaxOrderedWorkgroups)
        throw std::invalid_argument("a dispatch of " + std::to_string(workgroupCount) +
                                    " workgroups is more than the workgroup order supports (" +
                                    std::to_string(kMaxOrderedWorkgroups) + ")");
    if (workgroupCount <= 2) return 1;
    const double inverseGoldenSquared = 0.3819660112501051; // 1 / phi^2 = 2 - phi
    auto stride = std::uint32_t(std::lround(workgroupCount * inverseGoldenSquared));
    // Ends at workgroupCount - 1 at the latest, which is coprime to workgroupCount.
    while (std::gcd(stride, workgroupCount) != 1)
        ++stride;
    return stride;
}
