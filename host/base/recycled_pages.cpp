#include "base/recycled_pages.h"

#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>
#include <unordered_map>
#include <vector>

#include <sys/mman.h>

namespace {

constexpr std::size_t kPage = 4096;
// Each piece is a mapping of its own once moved; past this many kept, the smallest are
// given back, so that the process stays far from the kernel's limit of mappings.
constexpr std::size_t kMostKeptPieces = 4096;

// The bookkeeping's own memory, straight from malloc: through operator new, which may be
// this file's caller, freeing it with the lock held would take the lock again.
template <typename T> struct MallocAllocator {
    using value_type = T;
    MallocAllocator() = default;
    template <typename U> MallocAllocator(const MallocAllocator<U>&) {}
    T* allocate(std::size_t count) {
        if (void* memory = std::malloc(count * sizeof(T))) return static_cast<T*>(memory);
        throw std::bad_alloc();
    }
    void deallocate(T* memory, std::size_t) { std::free(memory); }
    friend bool operator==(const MallocAllocator&, const MallocAllocator&) { return true; }
};
template <typename T> using Vector = std::vector<T, MallocAllocator<T>>;

// Whole pages inside one mapping (mremap moves a range of one mapping only).
struct Piece {
    char* address = nullptr;
    std::size_t bytes = 0;
};

struct Pages {
    std::mutex mutex;
    Vector<Piece> kept;
    std::size_t keptBytes = 0;
    std::unordered_map<const void*, Vector<Piece>, std::hash<const void*>,
                       std::equal_to<const void*>,
                       MallocAllocator<std::pair<const void* const, Vector<Piece>>>>
        live; // a block's pieces, in order
    std::size_t liveBytes = 0;
    int givingBack = 0; // PagesGivenBack alive
};

// Never destroyed: a block may be freed by another static object's destructor at exit.
Pages& pages() {
    alignas(Pages) static unsigned char storage[sizeof(Pages)];
    static Pages* const state = new (storage) Pages;
    return *state;
}

void* mapFresh(std::size_t bytes) {
    void* block =
        ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    return block == MAP_FAILED ? nullptr : block;
}

// The kept piece to take next: the smallest that covers `bytes` alone, else the largest.
std::size_t bestPiece(const Vector<Piece>& kept, std::size_t bytes) {
    std::size_t best = kept.size(), largest = 0;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        if (kept[i].bytes >= bytes && (best == kept.size() || kept[i].bytes < kept[best].bytes))
            best = i;
        if (kept[i].bytes > kept[largest].bytes) largest = i;
    }
    return best < kept.size() ? best : largest;
}

// Takes `bytes` from the front of kept piece i (all of it, or a part, the rest kept).
Piece takeFront(Pages& state, std::size_t i, std::size_t bytes) {
    Piece& piece = state.kept[i];
    const Piece taken{piece.address, bytes};
    piece.address += bytes;
    piece.bytes -= bytes;
    state.keptBytes -= bytes;
    if (piece.bytes == 0) {
        piece = state.kept.back();
        state.kept.pop_back();
    }
    return taken;
}

} // namespace

void* allocateRecycled(std::size_t bytes) {
    bytes = (bytes + kPage - 1) / kPage * kPage;
    if (bytes == 0) bytes = kPage;
    Pages& state = pages();
    const std::lock_guard lock(state.mutex);
    Vector<Piece> pieces;
    char* block = nullptr;
    const std::size_t first = bestPiece(state.kept, bytes);
    if (first < state.kept.size() && state.kept[first].bytes >= bytes) {
        // One kept piece covers the block: used where it lies.
        pieces.push_back(takeFront(state, first, bytes));
        block = pieces.front().address;
    } else {
        // New pages for the whole block, then as many of them as the kept pieces cover
        // replaced by those (mremap unmaps what lies where it moves a piece to).
        block = static_cast<char*>(mapFresh(bytes));
        if (!block) return nullptr;
        std::size_t placed = 0;
        while (placed < bytes && !state.kept.empty()) {
            const std::size_t i = bestPiece(state.kept, bytes - placed);
            const Piece piece = takeFront(state, i, std::min(state.kept[i].bytes, bytes - placed));
            void* moved = ::mremap(piece.address, piece.bytes, piece.bytes,
                                   MREMAP_MAYMOVE | MREMAP_FIXED, block + placed);
            if (moved == MAP_FAILED) { // not expected: the piece goes, the new pages stay
                ::munmap(piece.address, piece.bytes);
                break;
            }
            pieces.push_back({block + placed, piece.bytes});
            placed += piece.bytes;
        }
        if (placed < bytes) pieces.push_back({block + placed, bytes - placed});
    }
    state.liveBytes += bytes;
    state.live.emplace(block, std::move(pieces));
    return block;
}

bool releaseRecycled(void* block) {
    if (reinterpret_cast<std::uintptr_t>(block) % kPage != 0) return false; // not a block
    Pages& state = pages();
    const std::lock_guard lock(state.mutex);
    const auto found = state.live.find(block);
    if (found == state.live.end()) return false;
    for (const Piece& piece : found->second) {
        state.liveBytes -= piece.bytes;
        if (state.givingBack > 0) {
            ::munmap(piece.address, piece.bytes);
        } else {
            state.kept.push_back(piece);
            state.keptBytes += piece.bytes;
        }
    }
    state.live.erase(found);
    while (state.kept.size() > kMostKeptPieces) {
        std::size_t smallest = 0;
        for (std::size_t i = 1; i < state.kept.size(); ++i)
            if (state.kept[i].bytes < state.kept[smallest].bytes) smallest = i;
        ::munmap(state.kept[smallest].address, state.kept[smallest].bytes);
        state.keptBytes -= state.kept[smallest].bytes;
        state.kept[smallest] = state.kept.back();
        state.kept.pop_back();
    }
    return true;
}

namespace {

void giveBackKept(Pages& state) {
    for (const Piece& piece : state.kept)
        ::munmap(piece.address, piece.bytes);
    state.kept.clear();
    state.kept.shrink_to_fit();
    state.keptBytes = 0;
}

} // namespace

void trimRecycledPages() {
    Pages& state = pages();
    const std::lock_guard lock(state.mutex);
    giveBackKept(state);
}

PagesGivenBack::PagesGivenBack() {
    Pages& state = pages();
    const std::lock_guard lock(state.mutex);
    ++state.givingBack;
    giveBackKept(state);
}

PagesGivenBack::~PagesGivenBack() {
    Pages& state = pages();
    const std::lock_guard lock(state.mutex);
    --state.givingBack;
}

RecycledPagesState recycledPagesState() {
    Pages& state = pages();
    const std::lock_guard lock(state.mutex);
    return {state.keptBytes, state.kept.size(), state.live.size(), state.liveBytes};
}
