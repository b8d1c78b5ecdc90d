// The program's operator new and delete: blocks of a mebibyte or more come from
// base/recycled_pages.h, whose freed pages the next block takes without a page fault; the
// rest from malloc, as the library's own operator new does. Only in Raytracer itself (the
// tests' programs use the library's), and not in the sanitizer build, whose new and delete
// find misuse. The library's other forms (new[], nothrow, delete[]) call these.
#include "base/recycled_pages.h"

#include <cstdlib>
#include <new>

namespace {

// Below this, malloc keeps freed memory for reuse itself.
constexpr std::size_t kRecycledBytes = std::size_t(1) << 20;

} // namespace

void* operator new(std::size_t bytes) {
    for (;;) {
        void* block =
            bytes >= kRecycledBytes ? allocateRecycled(bytes) : std::malloc(bytes == 0 ? 1 : bytes);
        if (block) return block;
        const std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

void operator delete(void* block) noexcept {
    if (block && !releaseRecycled(block)) std::free(block);
}

void operator delete(void* block, std::size_t) noexcept {
    operator delete(block);
}
