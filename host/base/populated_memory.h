// Large arrays whose pages are mapped on all threads at once. A fresh array's first touch
// (a page fault, the kernel zeroing the page) costs more than anything written into it
// after: a million-triangle model's arrays take 120 MB, and one thread faulting them in took
// 47 ms of the 110 its OBJ file took to read. MADV_POPULATE_WRITE (Linux 5.14) maps a range
// in one call; each thread maps its share. Only advice: where the kernel does not know it,
// the first write faults as before.
#pragma once

#include <cstddef>
#include <vector>

// Maps the whole pages of [data, data + bytes) for writing, the ranges shared among threads.
void populatePages(void* data, std::size_t bytes);

// values with size elements (the new ones value-initialised), its storage exactly that large
// when it had to grow, the new elements' pages mapped by populatePages first (also those of
// storage reserved before and not yet written).
template <typename T> void resizePopulated(std::vector<T>& values, std::size_t size) {
    if (size > values.capacity()) {
        std::vector<T> larger;
        larger.reserve(size);
        populatePages(larger.data(), size * sizeof(T));
        larger.insert(larger.end(), values.begin(), values.end());
        values.swap(larger);
    } else if (size > values.size()) {
        populatePages(values.data() + values.size(), (size - values.size()) * sizeof(T));
    }
    values.resize(size);
}

// Room for at least size elements, its pages mapped by populatePages: for an array that one
// thread then fills by push_back, whose page faults would otherwise come one at a time.
template <typename T> void reservePopulated(std::vector<T>& values, std::size_t size) {
    values.reserve(size);
    populatePages(values.data() + values.size(), (values.capacity() - values.size()) * sizeof(T));
}
