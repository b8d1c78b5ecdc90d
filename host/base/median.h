// The median of a run of timings, as --bench and the CPU peers report it.
#pragma once

#include <algorithm>
#include <vector>

// The median of the values (the mean of the middle two for an even count); not empty.
inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}
