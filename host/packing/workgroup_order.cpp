#include "packing/workgroup_order.h"

#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

std::uint32_t rowStride(std::uint32_t rows) {
    if (rows > kMaxOrderedRows)
        throw std::invalid_argument(
            "a dispatch of " + std::to_string(rows) +
            " rows of workgroups is more than the workgroup order supports (" +
            std::to_string(kMaxOrderedRows) + ")");
    if (rows <= 2) return 1;
    const double inverseGoldenSquared = 0.3819660112501051; // 1 / phi^2 = 2 - phi
    auto stride = std::uint32_t(std::lround(rows * inverseGoldenSquared));
    // Ends at rows - 1 at the latest, which is coprime to rows.
    while (std::gcd(stride, rows) != 1)
        ++stride;
    return stride;
}
