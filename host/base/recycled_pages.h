// Large blocks of memory whose pages are used again instead of going back to the system.
// The start-up frees arrays of hundreds of megabytes in one phase and allocates as many in
// the next; each fresh page costs a page fault, the kernel zeroing it and charging it to the
// process: a fifth of all the start-up's CPU time at ten million triangles. A block freed
// here keeps its pages; the next block takes them, moved into place by mremap (page-table
// entries change hands: no copy, no fault), and only what they do not cover is new memory.
// The pages held never exceed the largest total of live blocks so far (a block takes kept
// pages before new ones), so the peak is the same, provided that the large memory of the
// time comes from here (PagesGivenBack where it does not) and that a block's room is
// written, not merely reserved (kept pages are held whether written or not). They stay
// held until trimRecycledPages or a PagesGivenBack. Blocks come zeroed only where their
// pages are new.
#pragma once

#include <cstddef>

// A page-aligned block of at least `bytes`; nullptr when the system has no memory for it.
// On all threads.
void* allocateRecycled(std::size_t bytes);

// Keeps block's pages for the next allocateRecycled and returns true, when block is one of
// allocateRecycled's; false, doing nothing, for any other pointer.
bool releaseRecycled(void* block);

// Gives every kept page back to the system: once a phase of large allocations is over.
void trimRecycledPages();

// While one lives, the kept pages are given back and so are a freed block's: for a phase
// in which memory also comes from elsewhere (a Vulkan driver's does not come through
// here), so that the pages kept would add to the peak.
class PagesGivenBack {
  public:
    PagesGivenBack();
    ~PagesGivenBack();
    PagesGivenBack(const PagesGivenBack&) = delete;
    PagesGivenBack& operator=(const PagesGivenBack&) = delete;
};

// What is held, for tests and for notes.
struct RecycledPagesState {
    std::size_t keptBytes = 0;  // freed pages waiting for a block
    std::size_t keptPieces = 0; // in so many mappings
    std::size_t liveBlocks = 0;
    std::size_t liveBytes = 0;
};
RecycledPagesState recycledPagesState();
