// Binned SAH build (Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", 2007): at each node the primitives' centroids are sorted into kBins
// equal bins along the longest axis of their bounds, and the split between bins i and i+1
// that minimises the surface-area cost
//     Ct * A + A_left * N_left + A_right * N_right      (A: half the box surface area)
// is taken, unless a leaf (cost N * A) is no dearer and small enough. The primitives' boxes
// with their ids are partitioned in place in one array, so that a node's primitives lie
// side by side in memory. An interior node is written depth first straight into
// the output array when it is reached, and gets its children's references (box, node index
// or leaf) once they are built, so the left child of a node, if interior, is the next node;
// a leaf is only a reference in its parent (shared.h).
//
// On several threads the top levels are split one level at a time, the nodes of a level at
// once, until every range left is below a task size; those ranges are then built as tasks,
// the largest first, each into its own array, and copied into place. The nodes' order is
// the depth-first order of the one-thread build, and so is every split: the tree is the same.
//
// Depth: traversal keeps at most one stack entry per level, so no leaf may be deeper
// than settings.maxDepth. A node whose SAH split could leave a child deeper than median
// splits from there would reach is split at the centroid median instead, which halves
// the count at each level; all-equal centroids (identical primitives) are split by
// position in the array. The depth limit therefore holds for any input.
#include "packing/bvh.h"

#include "packing/bvh_boxes.h"

#include "base/parallel.h"
#include "base/phase_progress.h"
#include "base/populated_memory.h"
#include "base/release.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace {

constexpr int kBins = 16;
using bvh_boxes::Bin;
using bvh_boxes::Box;
using bvh_boxes::Box4;
using bvh_boxes::boxOf;
using bvh_boxes::centroidOf;
using bvh_boxes::Float4;
using bvh_boxes::highCorner;
using bvh_boxes::kInfinity;
using bvh_boxes::lowCorner;
// On several threads, ranges below a task size are built whole by one thread: about
// kTasksPerThread tasks a thread, so that the last to finish leaves the others idle for
// little of the build, and none below kSmallestTask, whose hand-out would cost more than
// it shares.
constexpr std::uint32_t kTasksPerThread = 16;
constexpr std::uint32_t kSmallestTask = 16384;
static_assert(kSmallestTask > BVH_MAX_LEAF_COUNT, "a range above the task size is never a leaf");

// Ranges at least this big are bounded and binned on all threads, in blocks whose results
// are merged: boxes grow exactly and counts add up in any order, so the tree is the same.
constexpr std::uint32_t kParallelPass = 1u << 17;

// A range of primitives with its box and the box of its centroids.
struct Range {
    std::uint32_t begin = 0, end = 0;
    Box bounds, centroids;
    std::uint32_t size() const { return end - begin; }
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

// Room for the nodes of a subtree of n primitives, so that its array rarely grows by
// copying itself: at most n + 1 are made (n - 1 interior nodes when every leaf holds one
// primitive, and a lone leaf's root), far fewer when leaves hold several (a third of n for
// a smooth mesh). Half of n is reserved: room never written would still be held when a
// block's pages are kept ones (base/recycled_pages.h).
void reserveNodes(std::vector<gpu::GpuBvhNode>& nodes, std::uint32_t n) {
    nodes.reserve(std::size_t(n) / 2 + 1);
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
    // Takes the input's boxes as its own array, numbering them in place.
    Builder(PrimitiveBounds&& input, const BvhSettings& settings)
        : progress("Building the hierarchy", input.size()), refs_(std::move(input.boxes)),
          sphereCount_(input.sphereCount), settings_(settings),
          threads_(settings.threads ? settings.threads : workerThreads()) {
        const std::vector<IndexRange> blocks = passBlocks(0, std::uint32_t(refs_.size()), threads_);
        parallelFor(
            blocks.size(),
            [&](std::size_t b) {
                for (std::size_t id = blocks[b].begin; id < blocks[b].end; ++id) {
                    refs_[id].id = std::uint32_t(id);
                    refs_[id].zero = 0.0f;
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
                    part.bounds.grow(boxOf(refs_[i]));
                    part.centroids.grow(centroidOf(refs_[i]));
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

    // Writes the interior nodes of the tree over root depth first to out: on one thread as
    // build does, else in tasks (buildInTasks).
    Subtree buildTree(const Range& root, std::vector<gpu::GpuBvhNode>& out) {
        if (threads_ >= 2) return buildInTasks(root, out);
        reserveNodes(out, root.size());
        return build(root, 0, out);
    }

    unsigned threads() const { return threads_; }
    // The id of the primitive at position i of the order, in which each leaf owns a
    // consecutive range.
    std::uint32_t idAt(std::size_t i) const { return refs_[i].id; }

    PhaseProgress progress; // the primitives in leaves so far

  private:
    // How the node over range is made: a leaf, or an interior node over left and right
    // (order partitioned between them). passThreads: those its passes may take.
    struct Split {
        bool leaf = true;
        Range left, right;
    };
    Split splitOf(const Range& range, std::uint32_t depth, unsigned passThreads) {
        const std::uint32_t n = range.size();
        if (n == 1) return {};
        const int axis = longestAxis(range.centroids);
        const float extent = range.centroids.hi[axis] - range.centroids.lo[axis];
        Split split{false, {}, {}};
        const bool binned =
            extent > 0.0f && sahSplit(range, axis, passThreads, split.left, split.right);
        const bool withinDepth =
            binned && depth + 1 + levelsNeeded(std::max(split.left.size(), split.right.size())) <=
                          settings_.maxDepth;
        if (n <= settings_.maxLeafSize && (!binned || !withinDepth)) return {};
        if (!withinDepth)
            medianSplit(range, axis, extent > 0.0f, passThreads, split.left, split.right);
        return split;
    }

    // Writes the interior nodes of the subtree over range depth first to out, on this thread.
    Subtree build(const Range& range, std::uint32_t depth, std::vector<gpu::GpuBvhNode>& out) {
        const Split split = splitOf(range, depth, 1);
        if (split.leaf) return makeLeaf(range, depth, out);
        const std::uint32_t self = std::uint32_t(out.size());
        out.emplace_back();
        const Subtree left = build(split.left, depth + 1, out);
        const Subtree right = build(split.right, depth + 1, out);
        setBvhChild(out[self], BvhSide::Left, left.child);
        setBvhChild(out[self], BvhSide::Right, right.child);
        return {interiorChild(range.bounds, self), std::max(left.depth, right.depth)};
    }

    // A node of the top levels: interior, over two top nodes or tasks (their indices, a
    // task's marked by kTaskBit).
    static constexpr std::uint32_t kTaskBit = 1u << 31;
    struct TopNode {
        Range range;
        std::uint32_t depth = 0;
        std::uint32_t left = 0, right = 0;
    };
    // A range below the task size, built whole on one thread into its own array.
    struct Task {
        Range range;
        std::uint32_t depth = 0;
        std::vector<gpu::GpuBvhNode> nodes; // the subtree's, numbered from 0
        Subtree tree;
        std::size_t offset = 0; // where its nodes go in the output
    };
    struct TopLevels {
        std::vector<TopNode> nodes; // the root first
        std::vector<Task> tasks;
    };

    Subtree buildInTasks(const Range& root, std::vector<gpu::GpuBvhNode>& out) {
        const std::uint32_t taskSize =
            std::max(kSmallestTask, root.size() / (kTasksPerThread * threads_));
        if (root.size() < taskSize) {
            reserveNodes(out, root.size());
            return build(root, 0, out);
        }
        TopLevels top = splitTopLevels(root, taskSize);
        buildTasks(top.tasks);
        return assemble(top, out);
    }

    // The top levels split a level at a time, until every range left is below taskSize:
    // a level's nodes at once (the largest first), each on one thread, or one node's on all.
    TopLevels splitTopLevels(const Range& root, std::uint32_t taskSize) {
        TopLevels top;
        top.nodes.push_back({root, 0});
        // A child: a top node of the next level, or a task.
        auto place = [&](const Range& range, std::uint32_t depth,
                         std::vector<std::uint32_t>& next) {
            if (range.size() < taskSize) {
                top.tasks.push_back({range, depth, {}, {}, 0});
                return std::uint32_t(top.tasks.size() - 1) | kTaskBit;
            }
            top.nodes.push_back({range, depth});
            next.push_back(std::uint32_t(top.nodes.size() - 1));
            return next.back();
        };
        for (std::vector<std::uint32_t> level{0}; !level.empty();) {
            std::sort(level.begin(), level.end(), [&](std::uint32_t a, std::uint32_t b) {
                return top.nodes[a].range.size() > top.nodes[b].range.size();
            });
            std::vector<Split> splits(level.size());
            const unsigned passThreads = level.size() == 1 ? threads_ : 1;
            parallelFor(
                level.size(),
                [&](std::size_t k) {
                    const TopNode& node = top.nodes[level[k]];
                    splits[k] = splitOf(node.range, node.depth, passThreads);
                },
                threads_);
            std::vector<std::uint32_t> next;
            for (std::size_t k = 0; k < level.size(); ++k) {
                const std::uint32_t depth = top.nodes[level[k]].depth + 1;
                const std::uint32_t left = place(splits[k].left, depth, next);
                const std::uint32_t right = place(splits[k].right, depth, next);
                top.nodes[level[k]].left = left;
                top.nodes[level[k]].right = right;
            }
            level = std::move(next);
        }
        return top;
    }

    // Every task built, the largest first, so that a large one does not start last.
    void buildTasks(std::vector<Task>& tasks) {
        std::vector<std::size_t> bySize(tasks.size());
        std::iota(bySize.begin(), bySize.end(), std::size_t(0));
        std::stable_sort(bySize.begin(), bySize.end(), [&](std::size_t a, std::size_t b) {
            return tasks[a].range.size() > tasks[b].range.size();
        });
        parallelFor(
            tasks.size(),
            [&](std::size_t k) {
                Task& task = tasks[bySize[k]];
                reserveNodes(task.nodes, task.range.size());
                task.tree = build(task.range, task.depth, task.nodes);
            },
            threads_);
    }

    // The top nodes and the tasks' nodes written to out in the order build would have
    // written them (depth first), and the top nodes' children set.
    Subtree assemble(TopLevels& top, std::vector<gpu::GpuBvhNode>& out) {
        std::vector<std::size_t> placeOf(top.nodes.size());
        std::size_t count = out.size();
        auto number = [&](auto& self, std::uint32_t reference) -> void {
            if (reference & kTaskBit) {
                Task& task = top.tasks[reference & ~kTaskBit];
                task.offset = count;
                count += task.nodes.size();
                return;
            }
            placeOf[reference] = count++;
            self(self, top.nodes[reference].left);
            self(self, top.nodes[reference].right);
        };
        number(number, 0);
        resizePopulated(out, count);
        parallelFor(
            top.tasks.size(),
            [&](std::size_t k) {
                Task& task = top.tasks[k];
                moveNodes(task.nodes, task.offset, out);
                if (!task.tree.child.leaf) task.tree.child.index += std::uint32_t(task.offset);
                release(task.nodes);
            },
            threads_);
        auto link = [&](auto& self, std::uint32_t reference) -> Subtree {
            if (reference & kTaskBit) return top.tasks[reference & ~kTaskBit].tree;
            const TopNode& node = top.nodes[reference];
            const Subtree left = self(self, node.left), right = self(self, node.right);
            gpu::GpuBvhNode& written = out[placeOf[reference]];
            setBvhChild(written, BvhSide::Left, left.child);
            setBvhChild(written, BvhSide::Right, right.child);
            return {interiorChild(node.range.bounds, std::uint32_t(placeOf[reference])),
                    std::max(left.depth, right.depth)};
        };
        return link(link, 0);
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
        auto binOf = [&](const PrimitiveBox& ref) {
            return std::min(kBins - 1, int((centroidOf(ref, axis) - lo) * scale));
        };
        const Bins bins = reduceBlocks(
            range.begin, range.end, threads,
            [&](std::uint32_t from, std::uint32_t to) {
                auto add = [&](Bins& into, const PrimitiveBox& ref) {
                    Bin& bin = into[binOf(ref)];
                    const Float4 boxLo = lowCorner(ref), boxHi = highCorner(ref);
                    const Float4 centroid = 0.5f * (boxLo + boxHi);
                    bin.bounds.grow(boxLo, boxHi);
                    bin.centroids.grow(centroid, centroid);
                    ++bin.count;
                };
                Bins blockBins;
                std::uint32_t i = from;
                if (to - from >= 64) {
                    Bins odd;
                    for (; i + 1 < to; i += 2) {
                        add(blockBins, refs_[i]);
                        add(odd, refs_[i + 1]);
                    }
                    mergeBins(odd, blockBins);
                }
                for (; i < to; ++i)
                    add(blockBins, refs_[i]);
                return blockBins;
            },
            mergeBins);
        // The planes just after each filled bin but the last: a plane after an empty bin
        // costs what the plane before it does (an empty box grows nothing), and one with
        // nothing on a side is no split. Swept from the right for the right side's cost of
        // each, then from the left; the first of equal costs is taken.
        std::array<int, kBins> filled{};
        int filledCount = 0;
        for (int i = 0; i < kBins; ++i)
            if (bins[i].count) filled[filledCount++] = i;
        std::array<float, kBins> rightCost{};
        Box4 accumulated;
        std::uint32_t count = 0;
        for (int j = filledCount - 1; j > 0; --j) {
            accumulated.grow(bins[filled[j]].bounds);
            count += bins[filled[j]].count;
            rightCost[j - 1] = accumulated.halfArea() * float(count);
        }
        int best = -1;
        float bestCost = kInfinity;
        accumulated = Box4{};
        count = 0;
        for (int j = 0; j + 1 < filledCount; ++j) {
            accumulated.grow(bins[filled[j]].bounds);
            count += bins[filled[j]].count;
            const float cost = accumulated.halfArea() * float(count) + rightCost[j];
            if (cost < bestCost) {
                bestCost = cost;
                best = filled[j];
            }
        }
        const float area = range.bounds.halfArea();
        const float leafCost = area * float(range.size());
        if (best < 0) return false;
        if (range.size() <= settings_.maxLeafSize &&
            leafCost <= settings_.traversalCost * area + bestCost)
            return false;

        auto first = refs_.begin() + range.begin;
        auto middle = std::partition(first, refs_.begin() + range.end,
                                     [&](const PrimitiveBox& ref) { return binOf(ref) <= best; });
        std::uint32_t mid = std::uint32_t(middle - refs_.begin());
        Bin leftBins, rightBins;
        for (int i = 0; i < kBins; ++i) {
            Bin& side = i <= best ? leftBins : rightBins;
            side.bounds.grow(bins[i].bounds);
            side.centroids.grow(bins[i].centroids);
        }
        left = {range.begin, mid, leftBins.bounds.box(), leftBins.centroids.box()};
        right = {mid, range.end, rightBins.bounds.box(), rightBins.centroids.box()};
        return true;
    }

    // Halves the range at the centroid median along axis (by array position when every
    // centroid is the same).
    void medianSplit(const Range& range, int axis, bool sortByCentroid, unsigned threads,
                     Range& left, Range& right) {
        std::uint32_t mid = range.begin + range.size() / 2;
        if (sortByCentroid)
            std::nth_element(refs_.begin() + range.begin, refs_.begin() + mid,
                             refs_.begin() + range.end,
                             [&](const PrimitiveBox& a, const PrimitiveBox& b) {
                                 return centroidOf(a, axis) < centroidOf(b, axis);
                             });
        left = rangeOf(range.begin, mid, threads);
        right = rangeOf(mid, range.end, threads);
    }

    // A leaf over range; a range holding both kinds becomes an interior node over a sphere
    // leaf and a triangle leaf, since a leaf indexes one array.
    Subtree makeLeaf(const Range& range, std::uint32_t depth, std::vector<gpu::GpuBvhNode>& out) {
        progress.advance(range.size());
        auto first = refs_.begin() + range.begin, last = refs_.begin() + range.end;
        auto isSphere = [&](const PrimitiveBox& ref) { return ref.id < sphereCount_; };
        auto middle = std::partition(first, last, isSphere);
        if (middle == first || middle == last)
            return {leafChild(range.bounds, range.begin, range.size(), middle == last), depth};
        std::uint32_t mid = std::uint32_t(middle - refs_.begin());
        Range spheres = rangeOf(range.begin, mid), triangles = rangeOf(mid, range.end);
        const std::uint32_t self = std::uint32_t(out.size());
        out.emplace_back();
        setBvhChild(out[self], BvhSide::Left,
                    leafChild(spheres.bounds, spheres.begin, spheres.size(), true));
        setBvhChild(out[self], BvhSide::Right,
                    leafChild(triangles.bounds, triangles.begin, triangles.size(), false));
        return {interiorChild(range.bounds, self), depth + 1};
    }

    // Writes a subtree built in its own array to out from offset on, moving the node
    // indices of its nodes' interior children along (a reference below BVH_LEAF is one).
    static void moveNodes(const std::vector<gpu::GpuBvhNode>& subtree, std::size_t offset,
                          std::vector<gpu::GpuBvhNode>& out) {
        auto moved = [&](float reference) {
            const auto bits = std::bit_cast<std::uint32_t>(reference);
            return std::bit_cast<float>(bits & BVH_LEAF ? bits : bits + std::uint32_t(offset));
        };
        for (std::size_t k = 0; k < subtree.size(); ++k) {
            gpu::GpuBvhNode node = subtree[k];
            node.leftMinAndRef.w = moved(node.leftMinAndRef.w);
            node.rightMinAndRef.w = moved(node.rightMinAndRef.w);
            out[offset + k] = node;
        }
    }

    std::vector<PrimitiveBox> refs_; // partitioned in place: each node's are consecutive
    std::uint32_t sphereCount_;
    BvhSettings settings_;
    unsigned threads_; // above 1: the build runs in tasks (buildInTasks)
};

} // namespace

Bvh buildBvh(PrimitiveBounds input, const BvhSettings& settings) {
    Bvh bvh;
    const std::size_t n = input.size();
    if (n == 0) return bvh;
    if (n > BVH_MAX_PRIMITIVES || input.sphereCount > n)
        throw std::invalid_argument("buildBvh: " + std::to_string(n) + " primitives are too many");
    if (settings.maxLeafSize < 1 || settings.maxLeafSize > BVH_MAX_LEAF_COUNT)
        throw std::invalid_argument("buildBvh: maxLeafSize must be from 1 to " +
                                    std::to_string(BVH_MAX_LEAF_COUNT));

    const std::uint32_t sphereCount = input.sphereCount;
    Builder builder(std::move(input), settings);
    const unsigned threads = builder.threads();
    Range root = builder.rangeOf(0, std::uint32_t(n), threads);
    if (builder.levelsNeeded(root.size()) > settings.maxDepth)
        throw std::invalid_argument("buildBvh: " + std::to_string(n) +
                                    " primitives cannot fit in " +
                                    std::to_string(settings.maxDepth) + " levels");
    const Subtree tree = builder.buildTree(root, bvh.nodes);
    bvh.depth = tree.depth;
    if (tree.child.leaf) {
        // The shader starts at node 0, an interior node: the lone leaf gets one, with an
        // empty leaf beside it whose box is a point (shared.h).
        BvhChild empty = leafChild(Box{tree.child.lo, tree.child.lo}, 0, 0, false);
        bvh.nodes.emplace_back();
        setBvhChild(bvh.nodes[0], BvhSide::Left, tree.child);
        setBvhChild(bvh.nodes[0], BvhSide::Right, empty);
    }

    // The leaves in depth-first order are the leaf order, and their ranges of the builder's
    // order follow one another in that order: a primitive's slot is the number of its kind
    // before it in that order, and a leaf's first slot that of its first primitive.
    // On all threads: each block's spheres counted, then its slots numbered from the counts
    // of the blocks before it.
    const std::vector<IndexRange> blocks = passBlocks(0, std::uint32_t(n), threads);
    const std::vector<std::size_t> spheresBefore = countsBefore(
        blocks,
        [&](IndexRange block) {
            std::size_t spheres = 0;
            for (std::size_t i = block.begin; i < block.end; ++i)
                spheres += builder.idAt(i) < sphereCount;
            return spheres;
        },
        threads);
    std::vector<std::uint32_t> slotAt;
    resizePopulated(slotAt, n);
    bvh.sphereOrder.resize(sphereCount);
    resizePopulated(bvh.triangleOrder, n - sphereCount);
    parallelFor(
        blocks.size(),
        [&](std::size_t b) {
            auto spheres = std::uint32_t(spheresBefore[b]);
            auto triangles = std::uint32_t(blocks[b].begin - spheres);
            for (std::size_t i = blocks[b].begin; i < blocks[b].end; ++i) {
                const std::uint32_t id = builder.idAt(i);
                if (id < sphereCount) {
                    slotAt[i] = spheres;
                    bvh.sphereOrder[spheres++] = id;
                } else {
                    slotAt[i] = triangles;
                    bvh.triangleOrder[triangles++] = id - sphereCount;
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
