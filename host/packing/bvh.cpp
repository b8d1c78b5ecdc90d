// Binned SAH build (Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", 2007): at each node the primitives' centroids are sorted into kBins
// equal bins along the longest axis of their bounds, and the split between bins i and i+1
// that minimises the surface-area cost
//     Ct * A + A_left * N_left + A_right * N_right      (A: half the box surface area)
// is taken, unless a leaf (cost N * A) is no dearer and small enough. Primitive ids are
// partitioned in place in one array. An interior node is written depth first straight into
// the output array when it is reached, and gets its children's references (box, node index
// or leaf) once they are built, so the left child of a node, if interior, is the next node;
// a leaf is only a reference in its parent (shared.h). The two top levels build their
// subtrees on separate threads, each into its own array, spliced afterwards.
//
// Depth: traversal keeps at most one stack entry per level, so no leaf may be deeper
// than settings.maxDepth. A node whose SAH split could leave a child deeper than median
// splits from there would reach is split at the centroid median instead, which halves
// the count at each level; all-equal centroids (identical primitives) are split by
// position in the array. The depth limit therefore holds for any input.
#include "packing/bvh.h"

#include "base/parallel.h"
#include "base/phase_progress.h"
#include "base/populated_memory.h"
#include "base/release.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace {

constexpr int kBins = 16;
// Subtrees at least this big, at depths below kParallelDepth, go to a second thread:
// depth 0 and 1 give up to four concurrent subtrees, enough to balance uneven splits.
constexpr std::uint32_t kParallelMinimum = 16384;
constexpr std::uint32_t kParallelDepth = 2;

constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Box {
    glm::vec3 lo{kInfinity};
    glm::vec3 hi{-kInfinity};
    void grow(const Box& other) {
        lo = glm::min(lo, other.lo);
        hi = glm::max(hi, other.hi);
    }
    void grow(const glm::vec3& point) {
        lo = glm::min(lo, point);
        hi = glm::max(hi, point);
    }
    // Half the surface area; 0 for an empty box.
    float halfArea() const {
        glm::vec3 e = glm::max(hi - lo, glm::vec3(0.0f));
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

// Ranges at least this big are bounded and binned on all threads, in blocks whose results
// are merged: boxes grow exactly and counts add up in any order, so the tree is the same.
constexpr std::uint32_t kParallelPass = 1u << 17;

// A range of primitives with its box and the box of its centroids.
struct Range {
    std::uint32_t begin = 0, end = 0;
    Box bounds, centroids;
    std::uint32_t size() const { return end - begin; }
};

// A bin of the SAH sweep: the boxes of its primitives and of their centroids, and their count.
struct Bin {
    Box bounds, centroids;
    std::uint32_t count = 0;
};
using Bins = std::array<Bin, kBins>;

void mergeBins(const Bins& from, Bins& into) {
    for (int i = 0; i < kBins; ++i) {
        into[i].bounds.grow(from[i].bounds);
        into[i].centroids.grow(from[i].centroids);
        into[i].count += from[i].count;
    }
}

BvhChild interiorChild(const Box& box, std::uint32_t node) {
    return {box.lo, box.hi, false, node, 0, false};
}

// first is an index into the builder's order until buildBvh renumbers it to a slot.
BvhChild leafChild(const Box& box, std::uint32_t first, std::uint32_t count, bool spheres) {
    return {box.lo, box.hi, true, first, count, spheres};
}

// A built subtree: its reference, as its parent stores it, and the depth of its deepest leaf.
struct Subtree {
    BvhChild child;
    std::uint32_t depth = 0;
};

// Room for the interior nodes of a subtree of n primitives, at most n - 1 (its leaves hold
// one or more each), and for a lone leaf's root: address space, whose pages cost only once
// written, so that no array of nodes grows by copying itself.
void reserveNodes(std::vector<gpu::GpuBvhNode>& nodes, std::uint32_t n) {
    nodes.reserve(std::size_t(n) + 1);
}

// [begin, end) as the passes over it are shared: whole when below kParallelPass or built on
// one thread, else in blocks for all threads.
std::vector<IndexRange> passBlocks(std::uint32_t begin, std::uint32_t end, unsigned threads) {
    if (end - begin < kParallelPass || threads < 2) return {{begin, end}};
    std::vector<IndexRange> blocks = splitRange(end - begin, kParallelPass / 2);
    for (IndexRange& block : blocks)
        block = {begin + block.begin, begin + block.end};
    return blocks;
}

// pass(from, to) over each of passBlocks, on `threads`: its results in block order.
template <typename Result, typename Pass>
std::vector<Result> mapBlocks(std::uint32_t begin, std::uint32_t end, unsigned threads,
                              const Pass& pass) {
    const std::vector<IndexRange> blocks = passBlocks(begin, end, threads);
    std::vector<Result> results(blocks.size());
    parallelFor(
        blocks.size(),
        [&](std::size_t b) {
            results[b] = pass(std::uint32_t(blocks[b].begin), std::uint32_t(blocks[b].end));
        },
        threads);
    return results;
}

// pass(begin, end) at once when the range is below kParallelPass or one thread builds (as
// for all but the largest nodes: no allocation, no call through parallelFor), else over
// the blocks of passBlocks on all threads, merge(part, into) adding each block's result to
// the first's in block order.
template <typename Pass, typename Merge>
auto reduceBlocks(std::uint32_t begin, std::uint32_t end, unsigned threads, const Pass& pass,
                  const Merge& merge) {
    using Result = std::invoke_result_t<Pass, std::uint32_t, std::uint32_t>;
    if (end - begin < kParallelPass || threads < 2) return pass(begin, end);
    const std::vector<Result> parts = mapBlocks<Result>(begin, end, threads, pass);
    Result total = parts.front();
    for (std::size_t k = 1; k < parts.size(); ++k)
        merge(parts[k], total);
    return total;
}

class Builder {
  public:
    Builder(const PrimitiveBounds& input, const BvhSettings& settings)
        : progress("Building the hierarchy", input.size()), boxes_(input.boxes.data()),
          sphereCount_(input.sphereCount), settings_(settings),
          threads_(settings.threads ? settings.threads : workerThreads()) {
        resizePopulated(order, input.size());
        resizePopulated(centroids_, input.size() * 3);
        const std::vector<IndexRange> blocks = passBlocks(0, std::uint32_t(order.size()), threads_);
        parallelFor(
            blocks.size(),
            [&](std::size_t b) {
                for (std::size_t id = blocks[b].begin; id < blocks[b].end; ++id) {
                    order[id] = std::uint32_t(id);
                    for (std::size_t axis = 0; axis < 3; ++axis)
                        centroids_[3 * id + axis] =
                            0.5f * (boxes_[6 * id + axis] + boxes_[6 * id + 3 + axis]);
                }
            },
            threads_);
    }

    // threads: those the pass may take; 1 below the root, where the subtrees built at once
    // already keep the threads busy.
    Range rangeOf(std::uint32_t begin, std::uint32_t end, unsigned threads = 1) const {
        Range range = reduceBlocks(
            begin, end, threads,
            [&](std::uint32_t from, std::uint32_t to) {
                Range part;
                for (std::uint32_t i = from; i < to; ++i) {
                    part.bounds.grow(box(order[i]));
                    part.centroids.grow(centroid(order[i]));
                }
                return part;
            },
            [](const Range& part, Range& into) {
                into.bounds.grow(part.bounds);
                into.centroids.grow(part.centroids);
            });
        range.begin = begin;
        range.end = end;
        return range;
    }

    // Levels below a node of n primitives that median splits need in the worst case:
    // ceil(log2(ceil(n / maxLeafSize))), plus one to split a last leaf by kind.
    std::uint32_t levelsNeeded(std::uint32_t n) const {
        std::uint32_t leaves = (n + settings_.maxLeafSize - 1) / settings_.maxLeafSize;
        return std::uint32_t(std::bit_width(std::max(leaves, 1u) - 1)) + 1;
    }

    // Writes the interior nodes of the subtree over range depth first to out.
    Subtree build(const Range& range, std::uint32_t depth, std::vector<gpu::GpuBvhNode>& out) {
        const std::uint32_t n = range.size();
        if (n == 1) return makeLeaf(range, depth, out);

        const int axis = longestAxis(range.centroids);
        const float extent = range.centroids.hi[axis] - range.centroids.lo[axis];
        Range left, right;
        // The root's passes take every thread; below it the subtrees do.
        const unsigned passThreads = depth == 0 ? threads_ : 1;
        bool split = extent > 0.0f && sahSplit(range, axis, passThreads, left, right);
        bool withinDepth = split && depth + 1 + levelsNeeded(std::max(left.size(), right.size())) <=
                                        settings_.maxDepth;
        if (n <= settings_.maxLeafSize && (!split || !withinDepth))
            return makeLeaf(range, depth, out);
        if (!withinDepth) medianSplit(range, axis, extent > 0.0f, passThreads, left, right);

        const std::uint32_t self = std::uint32_t(out.size());
        out.emplace_back();
        Subtree leftTree, rightTree;
        if (depth < kParallelDepth && n >= kParallelMinimum && threads_ > 1) {
            std::vector<gpu::GpuBvhNode> leftNodes, rightNodes;
            reserveNodes(leftNodes, left.size());
            reserveNodes(rightNodes, right.size());
            parallelFor(
                2,
                [&](std::size_t side) {
                    if (side == 0)
                        leftTree = build(left, depth + 1, leftNodes);
                    else
                        rightTree = build(right, depth + 1, rightNodes);
                },
                2);
            splice(leftNodes, leftTree.child, out);
            release(leftNodes);
            splice(rightNodes, rightTree.child, out);
        } else {
            leftTree = build(left, depth + 1, out);
            rightTree = build(right, depth + 1, out);
        }
        setBvhChild(out[self], BvhSide::Left, leftTree.child);
        setBvhChild(out[self], BvhSide::Right, rightTree.child);
        return {interiorChild(range.bounds, self), std::max(leftTree.depth, rightTree.depth)};
    }

    std::vector<std::uint32_t> order; // primitive ids; each leaf owns a consecutive range
    PhaseProgress progress;           // the primitives in leaves so far

  private:
    Box box(std::uint32_t id) const {
        const float* b = boxes_ + 6 * std::size_t(id);
        return {{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
    }
    glm::vec3 centroid(std::uint32_t id) const {
        const float* c = centroids_.data() + 3 * std::size_t(id);
        return {c[0], c[1], c[2]};
    }
    float centroid(std::uint32_t id, int axis) const {
        return centroids_[3 * std::size_t(id) + axis];
    }

    static int longestAxis(const Box& box) {
        glm::vec3 e = box.hi - box.lo;
        return e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    }

    // The binned SAH split of range along axis, if it is cheaper than a leaf or the range
    // is too big for one. Partitions the range and fills left and right.
    bool sahSplit(const Range& range, int axis, unsigned threads, Range& left, Range& right) {
        const float lo = range.centroids.lo[axis];
        const float scale = float(kBins) / (range.centroids.hi[axis] - lo);
        if (!std::isfinite(scale)) return false; // a subnormal extent: nothing to bin
        auto binOf = [&](std::uint32_t id) {
            return std::min(kBins - 1, int((centroid(id, axis) - lo) * scale));
        };
        const Bins bins = reduceBlocks(
            range.begin, range.end, threads,
            [&](std::uint32_t from, std::uint32_t to) {
                Bins blockBins;
                for (std::uint32_t i = from; i < to; ++i) {
                    std::uint32_t id = order[i];
                    Bin& bin = blockBins[binOf(id)];
                    bin.bounds.grow(box(id));
                    bin.centroids.grow(centroid(id));
                    ++bin.count;
                }
                return blockBins;
            },
            mergeBins);
        // Sweep from the right for the right side's cost of each plane, then from the left.
        std::array<float, kBins - 1> rightCost{};
        Box accumulated;
        std::uint32_t count = 0;
        for (int i = kBins - 1; i > 0; --i) {
            accumulated.grow(bins[i].bounds);
            count += bins[i].count;
            rightCost[i - 1] = count ? accumulated.halfArea() * float(count) : kInfinity;
        }
        int best = -1;
        float bestCost = kInfinity;
        accumulated = Box{};
        count = 0;
        for (int i = 0; i < kBins - 1; ++i) {
            accumulated.grow(bins[i].bounds);
            count += bins[i].count;
            if (count == 0) continue;
            float cost = accumulated.halfArea() * float(count) + rightCost[i];
            if (cost < bestCost) {
                bestCost = cost;
                best = i;
            }
        }
        const float area = range.bounds.halfArea();
        const float leafCost = area * float(range.size());
        if (best < 0) return false;
        if (range.size() <= settings_.maxLeafSize &&
            leafCost <= settings_.traversalCost * area + bestCost)
            return false;

        auto first = order.begin() + range.begin;
        auto middle = std::partition(first, order.begin() + range.end,
                                     [&](std::uint32_t id) { return binOf(id) <= best; });
        std::uint32_t mid = std::uint32_t(middle - order.begin());
        left = {range.begin, mid, {}, {}};
        right = {mid, range.end, {}, {}};
        for (int i = 0; i < kBins; ++i) {
            Range& side = i <= best ? left : right;
            side.bounds.grow(bins[i].bounds);
            side.centroids.grow(bins[i].centroids);
        }
        return true;
    }

    // Halves the range at the centroid median along axis (by array position when every
    // centroid is the same).
    void medianSplit(const Range& range, int axis, bool sortByCentroid, unsigned threads,
                     Range& left, Range& right) {
        std::uint32_t mid = range.begin + range.size() / 2;
        if (sortByCentroid)
            std::nth_element(order.begin() + range.begin, order.begin() + mid,
                             order.begin() + range.end, [&](std::uint32_t a, std::uint32_t b) {
                                 return centroid(a, axis) < centroid(b, axis);
                             });
        left = rangeOf(range.begin, mid, threads);
        right = rangeOf(mid, range.end, threads);
    }

    // A leaf over range; a range holding both kinds becomes an interior node over a sphere
    // leaf and a triangle leaf, since a leaf indexes one array.
    Subtree makeLeaf(const Range& range, std::uint32_t depth, std::vector<gpu::GpuBvhNode>& out) {
        progress.advance(range.size());
        auto first = order.begin() + range.begin, last = order.begin() + range.end;
        auto isSphere = [&](std::uint32_t id) { return id < sphereCount_; };
        auto middle = std::partition(first, last, isSphere);
        if (middle == first || middle == last)
            return {leafChild(range.bounds, range.begin, range.size(), middle == last), depth};
        std::uint32_t mid = std::uint32_t(middle - order.begin());
        Range spheres = rangeOf(range.begin, mid), triangles = rangeOf(mid, range.end);
        const std::uint32_t self = std::uint32_t(out.size());
        out.emplace_back();
        setBvhChild(out[self], BvhSide::Left,
                    leafChild(spheres.bounds, spheres.begin, spheres.size(), true));
        setBvhChild(out[self], BvhSide::Right,
                    leafChild(triangles.bounds, triangles.begin, triangles.size(), false));
        return {interiorChild(range.bounds, self), depth + 1};
    }

    // Appends a subtree built in its own array, moving its node indices along: those of its
    // nodes' interior children and that of its own reference, if interior.
    static void splice(const std::vector<gpu::GpuBvhNode>& subtree, BvhChild& root,
                       std::vector<gpu::GpuBvhNode>& out) {
        const std::uint32_t offset = std::uint32_t(out.size());
        for (gpu::GpuBvhNode node : subtree) {
            for (BvhSide side : {BvhSide::Left, BvhSide::Right}) {
                BvhChild child = bvhChild(node, side);
                if (child.leaf) continue;
                child.index += offset;
                setBvhChild(node, side, child);
            }
            out.push_back(node);
        }
        if (!root.leaf) root.index += offset;
    }

    const float* boxes_;
    std::uint32_t sphereCount_;
    BvhSettings settings_;
    unsigned threads_;             // above 1: the top subtrees are built two at a time
    std::vector<float> centroids_; // 3 floats per primitive
};

// The two sides of a node's fields (shared.h).
struct ChildFields {
    const glm::vec4& minAndRef;
    const glm::vec4& max;
};

ChildFields fields(const gpu::GpuBvhNode& node, BvhSide side) {
    if (side == BvhSide::Left) return {node.leftMinAndRef, node.leftMax};
    return {node.rightMinAndRef, node.rightMax};
}

} // namespace

BvhChild bvhChild(const gpu::GpuBvhNode& node, BvhSide side) {
    const ChildFields f = fields(node, side);
    const std::uint32_t reference = std::bit_cast<std::uint32_t>(f.minAndRef.w);
    BvhChild child{glm::vec3(f.minAndRef), glm::vec3(f.max)};
    child.leaf = (reference & BVH_LEAF) != 0;
    if (!child.leaf) {
        child.index = reference;
        return child;
    }
    child.index = reference & BVH_FIRST_MASK;
    child.count = (reference >> BVH_COUNT_SHIFT) & BVH_MAX_LEAF_COUNT;
    child.spheres = (reference & BVH_LEAF_SPHERES) != 0;
    return child;
}

void setBvhChild(gpu::GpuBvhNode& node, BvhSide side, const BvhChild& child) {
    if (child.leaf && child.count > BVH_MAX_LEAF_COUNT)
        throw std::invalid_argument("setBvhChild: a leaf of " + std::to_string(child.count) +
                                    " primitives does not fit its count field");
    if (child.leaf && child.index > BVH_FIRST_MASK)
        throw std::invalid_argument("setBvhChild: a leaf's first primitive " +
                                    std::to_string(child.index) + " does not fit its reference");
    if (!child.leaf && child.index >= BVH_LEAF)
        throw std::invalid_argument("setBvhChild: node index " + std::to_string(child.index) +
                                    " does not fit its reference");
    const std::uint32_t reference = child.leaf
                                        ? BVH_LEAF | (child.spheres ? BVH_LEAF_SPHERES : 0u) |
                                              child.count << BVH_COUNT_SHIFT | child.index
                                        : child.index;
    const glm::vec4 minAndRef(child.lo, std::bit_cast<float>(reference));
    const glm::vec4 max(child.hi, 0.0f);
    if (side == BvhSide::Left) {
        node.leftMinAndRef = minAndRef;
        node.leftMax = max;
    } else {
        node.rightMinAndRef = minAndRef;
        node.rightMax = max;
    }
}

Bvh buildBvh(const PrimitiveBounds& input, const BvhSettings& settings) {
    Bvh bvh;
    const std::size_t n = input.size();
    if (n == 0) return bvh;
    if (n > BVH_MAX_PRIMITIVES || input.sphereCount > n)
        throw std::invalid_argument("buildBvh: " + std::to_string(n) + " primitives are too many");
    if (settings.maxLeafSize < 1 || settings.maxLeafSize > BVH_MAX_LEAF_COUNT)
        throw std::invalid_argument("buildBvh: maxLeafSize must be from 1 to " +
                                    std::to_string(BVH_MAX_LEAF_COUNT));

    Builder builder(input, settings);
    const unsigned threads = settings.threads ? settings.threads : workerThreads();
    Range root = builder.rangeOf(0, std::uint32_t(n), threads);
    if (builder.levelsNeeded(root.size()) > settings.maxDepth)
        throw std::invalid_argument("buildBvh: " + std::to_string(n) +
                                    " primitives cannot fit in " +
                                    std::to_string(settings.maxDepth) + " levels");
    reserveNodes(bvh.nodes, std::uint32_t(n));
    const Subtree tree = builder.build(root, 0, bvh.nodes);
    bvh.depth = tree.depth;
    if (tree.child.leaf) {
        // The shader starts at node 0, an interior node: the lone leaf gets one, with an
        // empty leaf beside it whose box is a point (shared.h).
        BvhChild empty = leafChild(Box{tree.child.lo, tree.child.lo}, 0, 0, false);
        bvh.nodes.emplace_back();
        setBvhChild(bvh.nodes[0], BvhSide::Left, tree.child);
        setBvhChild(bvh.nodes[0], BvhSide::Right, empty);
    }

    // The leaves in depth-first order are the leaf order, and their ranges of builder.order
    // follow one another in that order: a primitive's slot is the number of its kind before
    // it in builder.order, and a leaf's first slot that of its first primitive.
    // On all threads: each block's spheres counted, then its slots numbered from the counts
    // of the blocks before it.
    const std::vector<std::uint32_t>& order = builder.order;
    const std::vector<std::uint32_t> blockSpheres = mapBlocks<std::uint32_t>(
        0, std::uint32_t(n), threads, [&](std::uint32_t from, std::uint32_t to) {
            return std::uint32_t(
                std::count_if(order.begin() + from, order.begin() + to,
                              [&](std::uint32_t id) { return id < input.sphereCount; }));
        });
    const std::vector<IndexRange> blocks = passBlocks(0, std::uint32_t(n), threads);
    std::vector<std::uint32_t> slotAt;
    resizePopulated(slotAt, n);
    bvh.sphereOrder.resize(input.sphereCount);
    resizePopulated(bvh.triangleOrder, n - input.sphereCount);
    std::vector<std::uint32_t> spheresBefore(blocks.size() + 1, 0);
    for (std::size_t b = 0; b < blocks.size(); ++b)
        spheresBefore[b + 1] = spheresBefore[b] + blockSpheres[b];
    parallelFor(
        blocks.size(),
        [&](std::size_t b) {
            std::uint32_t spheres = spheresBefore[b];
            auto triangles = std::uint32_t(blocks[b].begin - spheres);
            for (std::size_t i = blocks[b].begin; i < blocks[b].end; ++i) {
                const std::uint32_t id = order[i];
                if (id < input.sphereCount) {
                    slotAt[i] = spheres;
                    bvh.sphereOrder[spheres++] = id;
                } else {
                    slotAt[i] = triangles;
                    bvh.triangleOrder[triangles++] = id - input.sphereCount;
                }
            }
        },
        threads);
    const std::vector<IndexRange> nodeBlocks = splitRange(bvh.nodes.size(), 1 << 15);
    parallelFor(
        nodeBlocks.size(),
        [&](std::size_t b) {
            for (std::size_t k = nodeBlocks[b].begin; k < nodeBlocks[b].end; ++k)
                for (BvhSide side : {BvhSide::Left, BvhSide::Right}) {
                    gpu::GpuBvhNode& node = bvh.nodes[k];
                    BvhChild child = bvhChild(node, side);
                    if (!child.leaf || child.count == 0) continue;
                    child.index = slotAt[child.index];
                    setBvhChild(node, side, child);
                }
        },
        threads);
    return bvh;
}
