// Frees a vector's storage at once. `values = {}` does not: it assigns an empty
// initializer list, which keeps the capacity (and a large array's pages) until the vector
// itself goes.
#pragma once

#include <vector>

template <typename T, typename Allocator> void release(std::vector<T, Allocator>& values) {
    std::vector<T, Allocator>().swap(values);
}
