// Binned SAH build (Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", 2007): at each node the primitives' centroids are sorted into kBins
// equal bins along the longest axis of their bounds, and the split between bins i and i+1
// that minimises the surface-area cost
//     Ct * A + A_left * N_left + A_right * N_right      (A: half the box surface area)
// is taken, unless a leaf (cost N * A) is no dearer and small enough. Primitive ids are
// partitioned in place in one array; nodes are written depth first straight into the
// output array, so the left child of a node is the next node. The two top levels build
// their subtrees on separate threads, each into its own array, spliced afterwards.
//
// Depth: traversal keeps at most one stack entry per level, so no leaf may be deeper
// than settings.maxDepth. A node whose SAH split could leave a child deeper than median
// splits from there would reach is split at the centroid median instead, which halves
// the count at each level; all-equal centroids (identical primitives) are split by
// position in the array. The depth limit therefore holds for any input.
#include "bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <future>
#include <limits>
#include <stdexcept>
#include <string>

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

// A range of primitives with its box and the box of its centroids.
struct Range {
    std::uint32_t begin = 0, end = 0;
    Box bounds, centroids;
    std::uint32_t size() const { return end - begin; }
};

gpu::GpuBvhNode makeNode(const Box& box, std::uint32_t index, std::uint32_t count) {
    return {glm::vec4(box.lo, std::bit_cast<float>(index)),
            glm::vec4(box.hi, std::bit_cast<float>(count))};
}

void setIndex(gpu::GpuBvhNode& node, std::uint32_t index) {
    node.boundsMinAndIndex.w = std::bit_cast<float>(index);
}
void setCount(gpu::GpuBvhNode& node, std::uint32_t count) {
    node.boundsMaxAndCount.w = std::bit_cast<float>(count);
}

class Builder {
  public:
    Builder(const PrimitiveBounds& input, const BvhSettings& settings)
        : boxes_(input.boxes.data()), sphereCount_(input.sphereCount), settings_(settings),
          centroids_(input.size() * 3) {
        order.resize(input.size());
        for (std::size_t id = 0; id < order.size(); ++id) {
            order[id] = std::uint32_t(id);
            for (std::size_t axis = 0; axis < 3; ++axis)
                centroids_[3 * id + axis] =
                    0.5f * (boxes_[6 * id + axis] + boxes_[6 * id + 3 + axis]);
        }
    }

    Range rangeOf(std::uint32_t begin, std::uint32_t end) const {
        Range range{begin, end, {}, {}};
        for (std::uint32_t i = begin; i < end; ++i) {
            range.bounds.grow(box(order[i]));
            range.centroids.grow(centroid(order[i]));
        }
        return range;
    }

    // Levels below a node of n primitives that median splits need in the worst case:
    // ceil(log2(ceil(n / maxLeafSize))), plus one to split a last leaf by kind.
    std::uint32_t levelsNeeded(std::uint32_t n) const {
        std::uint32_t leaves = (n + settings_.maxLeafSize - 1) / settings_.maxLeafSize;
        return std::uint32_t(std::bit_width(std::max(leaves, 1u) - 1)) + 1;
    }

    // Writes the subtree over range depth first to out; returns the depth of its deepest leaf.
    std::uint32_t build(const Range& range, std::uint32_t depth,
                        std::vector<gpu::GpuBvhNode>& out) {
        const std::uint32_t self = std::uint32_t(out.size());
        out.push_back(makeNode(range.bounds, 0, 0));
        const std::uint32_t n = range.size();
        if (n == 1) return makeLeaf(range, self, depth, out);

        const int axis = longestAxis(range.centroids);
        const float extent = range.centroids.hi[axis] - range.centroids.lo[axis];
        Range left, right;
        bool split = extent > 0.0f && sahSplit(range, axis, left, right);
        bool withinDepth = split && depth + 1 + levelsNeeded(std::max(left.size(), right.size())) <=
                                        settings_.maxDepth;
        if (n <= settings_.maxLeafSize && (!split || !withinDepth))
            return makeLeaf(range, self, depth, out);
        if (!withinDepth) medianSplit(range, axis, extent > 0.0f, left, right);

        std::uint32_t subtreeDepth = 0;
        if (depth < kParallelDepth && n >= kParallelMinimum && settings_.threads > 1) {
            std::vector<gpu::GpuBvhNode> leftNodes, rightNodes;
            auto leftTask =
                std::async(std::launch::async, [&] { return build(left, depth + 1, leftNodes); });
            std::uint32_t rightDepth = build(right, depth + 1, rightNodes);
            subtreeDepth = std::max(leftTask.get(), rightDepth);
            splice(leftNodes, out);
            setIndex(out[self], std::uint32_t(out.size()));
            splice(rightNodes, out);
        } else {
            subtreeDepth = build(left, depth + 1, out);
            setIndex(out[self], std::uint32_t(out.size()));
            subtreeDepth = std::max(subtreeDepth, build(right, depth + 1, out));
        }
        return subtreeDepth;
    }

    std::vector<std::uint32_t> order; // primitive ids; each leaf owns a consecutive range

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
    bool sahSplit(const Range& range, int axis, Range& left, Range& right) {
        struct Bin {
            Box bounds, centroids;
            std::uint32_t count = 0;
        };
        const float lo = range.centroids.lo[axis];
        const float scale = float(kBins) / (range.centroids.hi[axis] - lo);
        if (!std::isfinite(scale)) return false; // a subnormal extent: nothing to bin
        auto binOf = [&](std::uint32_t id) {
            return std::min(kBins - 1, int((centroid(id, axis) - lo) * scale));
        };
        std::array<Bin, kBins> bins;
        for (std::uint32_t i = range.begin; i < range.end; ++i) {
            std::uint32_t id = order[i];
            Bin& bin = bins[binOf(id)];
            bin.bounds.grow(box(id));
            bin.centroids.grow(centroid(id));
            ++bin.count;
        }
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
    void medianSplit(const Range& range, int axis, bool sortByCentroid, Range& left, Range& right) {
        std::uint32_t mid = range.begin + range.size() / 2;
        if (sortByCentroid)
            std::nth_element(order.begin() + range.begin, order.begin() + mid,
                             order.begin() + range.end, [&](std::uint32_t a, std::uint32_t b) {
                                 return centroid(a, axis) < centroid(b, axis);
                             });
        left = rangeOf(range.begin, mid);
        right = rangeOf(mid, range.end);
    }

    // Node self becomes a leaf over range; a range holding both kinds becomes an interior
    // node over a sphere leaf and a triangle leaf, since a leaf indexes one array.
    std::uint32_t makeLeaf(const Range& range, std::uint32_t self, std::uint32_t depth,
                           std::vector<gpu::GpuBvhNode>& out) {
        auto first = order.begin() + range.begin, last = order.begin() + range.end;
        auto isSphere = [&](std::uint32_t id) { return id < sphereCount_; };
        auto middle = std::partition(first, last, isSphere);
        if (middle == first || middle == last) {
            std::uint32_t kind = middle == last ? BVH_LEAF_SPHERES : 0u;
            setIndex(out[self], range.begin); // an index into order until finish() renumbers it
            setCount(out[self], range.size() | kind);
            return depth;
        }
        std::uint32_t mid = std::uint32_t(middle - order.begin());
        Range spheres = rangeOf(range.begin, mid), triangles = rangeOf(mid, range.end);
        out.push_back(makeNode(spheres.bounds, spheres.begin, spheres.size() | BVH_LEAF_SPHERES));
        setIndex(out[self], std::uint32_t(out.size()));
        out.push_back(makeNode(triangles.bounds, triangles.begin, triangles.size()));
        return depth + 1;
    }

    // Appends a subtree built in its own array, moving its right-child indices along.
    static void splice(const std::vector<gpu::GpuBvhNode>& subtree,
                       std::vector<gpu::GpuBvhNode>& out) {
        const std::uint32_t offset = std::uint32_t(out.size());
        for (gpu::GpuBvhNode node : subtree) {
            if (!isLeaf(node)) setIndex(node, rightChild(node) + offset);
            out.push_back(node);
        }
    }

    const float* boxes_;
    std::uint32_t sphereCount_;
    BvhSettings settings_;
    std::vector<float> centroids_; // 3 floats per primitive
};

} // namespace

bool isLeaf(const gpu::GpuBvhNode& node) {
    return std::bit_cast<std::uint32_t>(node.boundsMaxAndCount.w) != 0;
}
std::uint32_t rightChild(const gpu::GpuBvhNode& node) {
    return std::bit_cast<std::uint32_t>(node.boundsMinAndIndex.w);
}
std::uint32_t firstPrimitive(const gpu::GpuBvhNode& node) {
    return rightChild(node);
}
std::uint32_t primitiveCount(const gpu::GpuBvhNode& node) {
    return std::bit_cast<std::uint32_t>(node.boundsMaxAndCount.w) & BVH_COUNT_MASK;
}
bool holdsSpheres(const gpu::GpuBvhNode& node) {
    return (std::bit_cast<std::uint32_t>(node.boundsMaxAndCount.w) & BVH_LEAF_SPHERES) != 0;
}

Bvh buildBvh(const PrimitiveBounds& input, const BvhSettings& settings) {
    Bvh bvh;
    const std::size_t n = input.size();
    if (n == 0) return bvh;
    if (n > BVH_COUNT_MASK || input.sphereCount > n)
        throw std::invalid_argument("buildBvh: " + std::to_string(n) + " primitives are too many");
    if (settings.maxLeafSize < 1)
        throw std::invalid_argument("buildBvh: maxLeafSize must be at least 1");

    Builder builder(input, settings);
    Range root = builder.rangeOf(0, std::uint32_t(n));
    if (builder.levelsNeeded(root.size()) > settings.maxDepth)
        throw std::invalid_argument("buildBvh: " + std::to_string(n) +
                                    " primitives cannot fit in " +
                                    std::to_string(settings.maxDepth) + " levels");
    bvh.nodes.reserve(n);
    bvh.depth = builder.build(root, 0, bvh.nodes);

    // Leaves in array order are the leaf order: give each its slots in its kind's array.
    for (gpu::GpuBvhNode& node : bvh.nodes) {
        if (!isLeaf(node)) continue;
        const std::uint32_t begin = firstPrimitive(node), count = primitiveCount(node);
        std::vector<std::uint32_t>& slots =
            holdsSpheres(node) ? bvh.sphereOrder : bvh.triangleOrder;
        const std::uint32_t idBase = holdsSpheres(node) ? 0 : input.sphereCount;
        setIndex(node, std::uint32_t(slots.size()));
        for (std::uint32_t i = begin; i < begin + count; ++i)
            slots.push_back(builder.order[i] - idBase);
    }
    return bvh;
}
