// bvh_build.cpp — binned SAH construction of the BVH (Wald 2007) over arrays of primitive
// references (box and index, 32 bytes), so that every pass reads and writes memory in order.
//
// Each node costs two passes over its references: one bins them, one partitions them into the
// other of two arrays (a node at depth d reads array d % 2), keeping each side's order. The
// children's boxes come from the winning split's bins, their centroid bounds from the
// partition, and the left side's size from the bins' counts, so no pass measures a range
// again and the partition knows where the right side starts (Wald 2007, section 3; Embree's
// builders do the same). The top levels' passes are split across threads by slices of the range,
// each slice binned apart and written at the offsets its bins' counts give; the subtrees below are
// built on worker threads. A stable partition gives every slicing the same order, so neither the
// tree nor its numbering depends on the thread count.
#include "bvh/bvh_build.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <numeric>
#include <string>

#include "bvh/box4.h"
#include "common/errors.h"
#include "common/worker_threads.h"
#include "shared/host_device.h"

namespace vkpt {

namespace {

constexpr std::uint32_t kNoAxis = 3;
constexpr std::uint32_t kNoParent = 0xffffffffu;
// firstPrimitive of a top-level placeholder whose subtree a worker builds (rightChild holds
// the task number); never present in a finished tree.
constexpr std::uint32_t kDeferredSubtree = 0xffffffffu;
// Below this many primitives one thread builds faster than it can hand out work.
constexpr std::size_t kParallelMinimum = std::size_t(1) << 16;
// A top-level node's passes are split across threads from this size.
constexpr std::uint32_t kSlicedNodeMinimum = 1u << 15;

// A primitive's box and its index in the input: two to a cache line, moved by the partition.
struct PrimitiveRef {
    glm::vec3 min;
    std::uint32_t index;
    glm::vec3 max;
    std::uint32_t unused;
};
static_assert(sizeof(PrimitiveRef) == 32);

// The same expression as Aabb::centre(), so that a box near ±FLT_MAX does not overflow.
glm::vec3 centroidOf(const PrimitiveRef& ref) {
    return 0.5f * ref.min + 0.5f * ref.max;
}

// The reference's box and centroid as vectors, for the inner loops.
struct RefVectors {
    Float4 min;
    Float4 max;
    Float4 centroid;
};

RefVectors vectorsOf(const PrimitiveRef& ref) {
    RefVectors v{loadXyz(ref.min), loadXyz(ref.max), {}};
    v.centroid = 0.5f * v.min + 0.5f * v.max;
    return v;
}

struct Range {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    std::uint32_t depth = 0;

    std::uint32_t count() const { return end - begin; }
};

// A node's boxes: its primitives' and their centroids'.
struct RangeBounds {
    Aabb bounds;
    Aabb centroids;
};

struct Bin {
    Box4 bounds;
    std::uint32_t count = 0;
};

// Maps centroids to bins along each axis (Wald 2007, section 3.1: bins of equal width over the
// centroid bounds, not the node bounds, so that the end bins are never empty and some plane
// separates any two distinct centroids). The binning and the partition both call binsOf, so
// that each reference lands on the side whose bins counted it.
struct BinMapping {
    Float4 origin = {};
    Float4 scale = {}; // 0 on an axis whose centroids are all equal
    Float4 lastBin = {};

    BinMapping(const Aabb& centroids, std::uint32_t binCount) {
        const auto bins = static_cast<float>(binCount);
        const auto last = static_cast<float>(binCount - 1);
        for (int axis = 0; axis < 3; ++axis) {
            const float extent = centroids.max[axis] - centroids.min[axis];
            origin[axis] = centroids.min[axis];
            scale[axis] = extent > 0.0f ? bins / extent : 0.0f;
            lastBin[axis] = last;
        }
    }

    // NaN and the smallest centroid go to bin 0; the largest lands on binCount: clamp it.
    Int4 binsOf(const Float4& centroid) const {
        const Float4 zero = {};
        Float4 f = (centroid - origin) * scale;
        f = f > zero ? f : zero;
        f = f < lastBin ? f : lastBin;
        return __builtin_convertvector(f, Int4);
    }
};

struct SplitPlane {
    std::uint32_t axis = kNoAxis;
    std::uint32_t bin = 0;      // bins 0..bin go left
    std::uint32_t binCount = 0; // the node's bins per axis
    float cost = 0.0f;          // SAH cost scaled by the node's surface area
};

// A split node's children: where the range divides and each side's boxes.
struct NodeSplit {
    std::uint32_t mid = 0; // left child [begin, mid), right child [mid, end)
    RangeBounds left;
    RangeBounds right;
};

struct Pending {
    Range range;
    RangeBounds bounds;
    std::uint32_t parent = kNoParent;
    bool isRight = false;
};

// A subtree the top level leaves to the workers.
struct SubtreeTask {
    Range range;
    RangeBounds bounds;
    std::vector<BvhBuildNode> nodes; // depth first, indices local to this vector
};

RangeBounds measure(std::span<const PrimitiveRef> refs) {
    RangeBounds rb;
    for (const PrimitiveRef& ref : refs) {
        rb.bounds.extend(Aabb{ref.min, ref.max});
        rb.centroids.extend(centroidOf(ref));
    }
    return rb;
}

// The two reference arrays (a node at depth d reads refs[d % 2] and partitions into the
// other) and the tree's primitive order, which each leaf fills for its range.
struct BuildArrays {
    std::span<PrimitiveRef> refs[2];
    std::span<std::uint32_t> primitiveOrder;

    std::span<PrimitiveRef> source(const Range& range) const {
        return refs[range.depth % 2].subspan(range.begin, range.count());
    }
    std::span<PrimitiveRef> target(const Range& range) const {
        return refs[(range.depth + 1) % 2].subspan(range.begin, range.count());
    }
};

// Slice s of n of a range's [0, count): the same slices for the binning and the partition.
std::size_t sliceStart(std::size_t count, std::uint32_t s, std::uint32_t n) {
    return count * s / n;
}

// Adds one reference to its bin on each axis. Inlined, so that the two bin sets' updates of
// fillBins interleave.
[[gnu::always_inline]] inline void binReference(const PrimitiveRef& r, const BinMapping& mapping,
                                                std::uint32_t stride, Bin* bins) {
    const RefVectors ref = vectorsOf(r);
    const Int4 bin = mapping.binsOf(ref.centroid);
    for (std::uint32_t axis = 0; axis < 3; ++axis) {
        Bin& b = bins[axis * stride + std::uint32_t(bin[axis])];
        b.bounds.extend(ref.min, ref.max);
        ++b.count;
    }
}

// From this many references a slice is binned into two sets of bins, even and odd references
// apart, merged at the end: neighbouring references mostly share a bin, and each update of a
// bin waits for the previous one to be stored, so one set serialises the loop on that memory.
// Below it, clearing and merging the second set costs more than it saves.
constexpr std::size_t kTwoBinSetsMinimum = 64;

// Bins one slice's references on the three axes at once into `bins`; `spare` (as many bins)
// is scratch space.
void fillBins(std::span<const PrimitiveRef> refs, const BinMapping& mapping, std::uint32_t binCount,
              std::uint32_t stride, Bin* bins, Bin* spare) {
    for (std::uint32_t axis = 0; axis < 3; ++axis)
        std::fill_n(bins + axis * stride, binCount, Bin{});
    if (refs.size() < kTwoBinSetsMinimum) {
        for (const PrimitiveRef& r : refs)
            binReference(r, mapping, stride, bins);
        return;
    }
    for (std::uint32_t axis = 0; axis < 3; ++axis)
        std::fill_n(spare + axis * stride, binCount, Bin{});
    const std::size_t pairs = refs.size() / 2;
    for (std::size_t i = 0; i < pairs; ++i) {
        binReference(refs[2 * i], mapping, stride, bins);
        binReference(refs[2 * i + 1], mapping, stride, spare);
    }
    if (refs.size() % 2 != 0) binReference(refs.back(), mapping, stride, bins);
    for (std::uint32_t axis = 0; axis < 3; ++axis) {
        for (std::uint32_t i = 0; i < binCount; ++i) {
            Bin& b = bins[axis * stride + i];
            const Bin& other = spare[axis * stride + i];
            b.bounds.extend(other.bounds.min, other.bounds.max);
            b.count += other.count;
        }
    }
}

// Writes one slice's references to `left` and `right` in order, by the side of the plane
// their bin is on, and gathers each side's centroid bounds (sides[1] left, sides[0] right) in
// registers. A branch, not a select: references arrive in the input's order, which meshes
// keep spatially coherent, so the side comes in long runs that the predictor follows (a
// branch-free version measured 10 % slower on a million-triangle displaced sphere).
void scatter(std::span<const PrimitiveRef> refs, const BinMapping& mapping, const SplitPlane& plane,
             PrimitiveRef* left, PrimitiveRef* right, Box4* sides) {
    Box4 leftSide = sides[1], rightSide = sides[0];
    for (const PrimitiveRef& ref : refs) {
        const Float4 c = vectorsOf(ref).centroid;
        if (std::uint32_t(mapping.binsOf(c)[plane.axis]) <= plane.bin) {
            *left++ = ref;
            leftSide.extend(c);
        } else {
            *right++ = ref;
            rightSide.extend(c);
        }
    }
    sides[1] = leftSide;
    sides[0] = rightSide;
}

// Builds one subtree at a time into a node vector, depth first, reusing its scratch space
// so that the hot loop allocates nothing.
class SubtreeBuilder {
public:
    // Nodes of kSlicedNodeMinimum primitives or more are binned and partitioned by
    // sliceThreads threads.
    SubtreeBuilder(const BvhBuildOptions& options, const BuildArrays& arrays,
                   std::uint32_t sliceThreads = 1)
        : options_(options), arrays_(arrays), sliceThreads_(sliceThreads),
          sliceBins_(std::size_t(sliceThreads) * 6 * options.binCount),
          bins_(3 * std::size_t(options.binCount)), rightCosts_(options.binCount),
          sliceLeft_(sliceThreads), sliceLeftAt_(sliceThreads), sliceRightAt_(sliceThreads),
          sliceSides_(2 * std::size_t(sliceThreads)) {}

    // Appends the subtree over root to nodes. With tasks, a node (other than root) with at
    // most deferBelow primitives becomes a placeholder and its range a task.
    void build(Range root, const RangeBounds& rootBounds, std::vector<BvhBuildNode>& nodes,
               std::vector<SubtreeTask>* tasks, std::uint32_t deferBelow);

private:
    bool splitNode(Range range, const RangeBounds& rb, NodeSplit& split);
    std::uint32_t slicesFor(Range range) const;
    SplitPlane findBestSplit(Range range, const RangeBounds& rb, std::uint32_t slices);
    void sweepAxis(std::uint32_t axis, const RangeBounds& rb, std::uint32_t count,
                   std::uint32_t binCount, SplitPlane& best);
    NodeSplit partition(Range range, const SplitPlane& plane, const Aabb& centroids,
                        std::uint32_t slices);
    NodeSplit splitAt(Range range, std::uint32_t mid) const;
    std::uint32_t medianOf(Range range, const Aabb& centroids) const;
    void makeLeaf(Range range, BvhBuildNode& node) const;
    float leafCost(std::uint32_t count, float area) const;
    Bin* sliceBins(std::uint32_t slice) {
        return sliceBins_.data() + std::size_t(slice) * 6 * options_.binCount;
    }
    Bin* spareBins(std::uint32_t slice) { return sliceBins(slice) + 3 * options_.binCount; }

    const BvhBuildOptions& options_;
    BuildArrays arrays_;
    std::uint32_t sliceThreads_;
    // Per slice: its bins, options_.binCount per axis, x then y then z; then as many spare.
    std::vector<Bin> sliceBins_;
    std::vector<Bin> bins_; // the slices' bins merged, same layout
    const Bin* merged_ = nullptr;
    std::vector<float> rightCosts_;
    std::vector<std::size_t> sliceLeft_, sliceLeftAt_, sliceRightAt_; // partition's, per slice
    std::vector<Box4> sliceSides_;                                    // right, left per slice
    std::vector<Pending> stack_;
};

void linkToParent(std::vector<BvhBuildNode>& nodes, const Pending& p, std::uint32_t index) {
    if (p.parent == kNoParent) return;
    (p.isRight ? nodes[p.parent].rightChild : nodes[p.parent].leftChild) = index;
}

void deferSubtree(BvhBuildNode& placeholder, const Pending& p, std::vector<SubtreeTask>& tasks) {
    placeholder.firstPrimitive = kDeferredSubtree;
    placeholder.rightChild = static_cast<std::uint32_t>(tasks.size());
    tasks.push_back({p.range, p.bounds, {}});
}

void SubtreeBuilder::build(Range root, const RangeBounds& rootBounds,
                           std::vector<BvhBuildNode>& nodes, std::vector<SubtreeTask>* tasks,
                           std::uint32_t deferBelow) {
    stack_.clear();
    stack_.push_back({root, rootBounds, kNoParent, false});
    NodeSplit split;
    while (!stack_.empty()) {
        const Pending p = stack_.back();
        stack_.pop_back();
        auto index = static_cast<std::uint32_t>(nodes.size());
        BvhBuildNode& node = nodes.emplace_back();
        linkToParent(nodes, p, index);
        if (tasks && p.parent != kNoParent && p.range.count() <= deferBelow) {
            deferSubtree(node, p, *tasks);
            continue;
        }
        node.bounds = p.bounds.bounds;
        if (!splitNode(p.range, p.bounds, split)) {
            makeLeaf(p.range, node);
            continue;
        }
        // Right first, so that the left child is popped next and lands at index + 1.
        const std::uint32_t depth = p.range.depth + 1;
        stack_.push_back({{split.mid, p.range.end, depth}, split.right, index, true});
        stack_.push_back({{p.range.begin, split.mid, depth}, split.left, index, false});
    }
}

void SubtreeBuilder::makeLeaf(Range range, BvhBuildNode& node) const {
    node.firstPrimitive = range.begin;
    node.primitiveCount = range.count();
    const std::span<const PrimitiveRef> refs = arrays_.source(range);
    for (std::uint32_t i = 0; i < range.count(); ++i)
        arrays_.primitiveOrder[range.begin + i] = refs[i].index;
}

// Leaf or split, and where: a leaf when it is cheaper than the best binned split (or holds
// one primitive), a forced split above maxLeafSize. Fills `split` and returns true to split.
bool SubtreeBuilder::splitNode(Range range, const RangeBounds& rb, NodeSplit& split) {
    std::uint32_t count = range.count();
    std::uint32_t maxLeaf = options_.maxLeafSize;
    if (count <= 1) return false;
    if (range.depth >= kBvhMaxSahDepth) {
        if (count <= maxLeaf) return false;
        split = splitAt(range, medianOf(range, rb.centroids));
        return true;
    }
    const std::uint32_t slices = slicesFor(range);
    SplitPlane plane = findBestSplit(range, rb, slices);
    float area = rb.bounds.surfaceArea();
    bool noPlane = plane.axis == kNoAxis;
    if (count <= maxLeaf && (noPlane || leafCost(count, area) <= plane.cost)) return false;
    // All centroids equal: no plane separates them, so halve the index range.
    split = noPlane ? splitAt(range, range.begin + count / 2)
                    : partition(range, plane, rb.centroids, slices);
    return true;
}

std::uint32_t SubtreeBuilder::slicesFor(Range range) const {
    return range.count() >= kSlicedNodeMinimum ? sliceThreads_ : 1u;
}

// Costs are scaled by the node's area A so that a flat or point-like node (A = 0) needs no
// division: leaf = Ci·N·A, split = Ct·A + Ci·(A_L·N_L + A_R·N_R) (Wald 2007, eq. 1).
float SubtreeBuilder::leafCost(std::uint32_t count, float area) const {
    return options_.intersectionCost * static_cast<float>(count) * area;
}

// A node of N primitives takes at most N bins: a small node (most nodes are) then costs a
// sweep over its own planes, not over binCount.
SplitPlane SubtreeBuilder::findBestSplit(Range range, const RangeBounds& rb, std::uint32_t slices) {
    const std::uint32_t binCount = std::clamp(range.count(), 2u, options_.binCount);
    const std::uint32_t stride = options_.binCount;
    const BinMapping mapping(rb.centroids, binCount);
    const std::span<const PrimitiveRef> refs = arrays_.source(range);
    if (slices == 1) {
        fillBins(refs, mapping, binCount, stride, sliceBins(0), spareBins(0));
        merged_ = sliceBins(0);
    } else {
        runOnWorkers(slices, [&](std::uint32_t s) {
            const std::size_t begin = sliceStart(refs.size(), s, slices);
            const std::size_t end = sliceStart(refs.size(), s + 1, slices);
            fillBins(refs.subspan(begin, end - begin), mapping, binCount, stride, sliceBins(s),
                     spareBins(s));
        });
        for (std::size_t i = 0; i < bins_.size(); ++i) {
            bins_[i] = sliceBins(0)[i];
            for (std::uint32_t s = 1; s < slices; ++s) {
                bins_[i].bounds.extend(sliceBins(s)[i].bounds.min, sliceBins(s)[i].bounds.max);
                bins_[i].count += sliceBins(s)[i].count;
            }
        }
        merged_ = bins_.data();
    }
    SplitPlane best;
    for (std::uint32_t axis = 0; axis < 3; ++axis)
        if (mapping.scale[axis] > 0.0f) sweepAxis(axis, rb, range.count(), binCount, best);
    return best;
}

// Sweeps the planes between bins: right-to-left areas first, then left to right. Ties keep
// the first plane found, so the result does not depend on anything but the input.
void SubtreeBuilder::sweepAxis(std::uint32_t axis, const RangeBounds& rb, std::uint32_t count,
                               std::uint32_t binCount, SplitPlane& best) {
    const Bin* bins = merged_ + axis * options_.binCount;
    Box4 right;
    std::uint32_t rightCount = 0;
    for (std::uint32_t i = binCount - 1; i > 0; --i) {
        right.extend(bins[i].bounds.min, bins[i].bounds.max);
        rightCount += bins[i].count;
        rightCosts_[i] = right.surfaceArea() * static_cast<float>(rightCount);
    }
    float nodeTerm = options_.traversalCost * rb.bounds.surfaceArea();
    Box4 left;
    std::uint32_t leftCount = 0;
    for (std::uint32_t i = 0; i + 1 < binCount; ++i) {
        left.extend(bins[i].bounds.min, bins[i].bounds.max);
        leftCount += bins[i].count;
        if (leftCount == 0 || leftCount == count) continue;
        float sides = left.surfaceArea() * static_cast<float>(leftCount) + rightCosts_[i + 1];
        float cost = nodeTerm + options_.intersectionCost * sides;
        if (best.axis == kNoAxis || cost < best.cost) best = {axis, i, binCount, cost};
    }
}

// Left: the references in bins 0..plane.bin, so that the children hold exactly the counts
// the sweep costed. Each slice writes its left references after the left ones of the slices
// before it, and its right ones likewise after the left side: the offsets come from each
// slice's own bin counts. The children's boxes are the unions of their bins.
NodeSplit SubtreeBuilder::partition(Range range, const SplitPlane& plane, const Aabb& centroids,
                                    std::uint32_t slices) {
    const BinMapping mapping(centroids, plane.binCount);
    const std::uint32_t stride = options_.binCount;
    const std::span<const PrimitiveRef> from = arrays_.source(range);
    PrimitiveRef* const to = arrays_.target(range).data();
    // Each slice's left count, then where its two sides start in `to`.
    std::size_t leftTotal = 0;
    for (std::uint32_t s = 0; s < slices; ++s) {
        const Bin* bins = sliceBins(s) + plane.axis * stride;
        std::size_t left = 0;
        for (std::uint32_t b = 0; b <= plane.bin; ++b)
            left += bins[b].count;
        sliceLeft_[s] = left;
        leftTotal += left;
    }
    std::size_t leftAt = 0, rightAt = leftTotal;
    for (std::uint32_t s = 0; s < slices; ++s) {
        const std::size_t size =
            sliceStart(from.size(), s + 1, slices) - sliceStart(from.size(), s, slices);
        sliceLeftAt_[s] = leftAt;
        sliceRightAt_[s] = rightAt;
        leftAt += sliceLeft_[s];
        rightAt += size - sliceLeft_[s];
    }
    Box4* sides = sliceSides_.data();
    auto scatterSlice = [&](std::uint32_t s) {
        const std::size_t begin = sliceStart(from.size(), s, slices);
        const std::size_t end = sliceStart(from.size(), s + 1, slices);
        scatter(from.subspan(begin, end - begin), mapping, plane, to + sliceLeftAt_[s],
                to + sliceRightAt_[s], &sides[2 * s]);
    };
    std::fill_n(sides, 2 * slices, Box4{});
    if (slices == 1) {
        scatterSlice(0);
    } else {
        runOnWorkers(slices, scatterSlice);
    }
    Box4 leftCentroids = sides[1], rightCentroids = sides[0];
    for (std::uint32_t s = 1; s < slices; ++s) {
        leftCentroids.extend(sides[2 * s + 1].min, sides[2 * s + 1].max);
        rightCentroids.extend(sides[2 * s].min, sides[2 * s].max);
    }
    NodeSplit split;
    split.mid = range.begin + std::uint32_t(leftTotal);
    split.left.centroids = leftCentroids.toAabb();
    split.right.centroids = rightCentroids.toAabb();
    const Bin* bins = merged_ + plane.axis * stride;
    Box4 left, right;
    for (std::uint32_t b = 0; b < plane.binCount; ++b)
        (b <= plane.bin ? left : right).extend(bins[b].bounds.min, bins[b].bounds.max);
    split.left.bounds = left.toAabb();
    split.right.bounds = right.toAabb();
    return split;
}

// A split at a given place (the fallbacks': no plane, or the depth limit): the references
// copied over as they stand and both sides measured.
NodeSplit SubtreeBuilder::splitAt(Range range, std::uint32_t mid) const {
    const std::span<const PrimitiveRef> from = arrays_.source(range);
    const std::span<PrimitiveRef> to = arrays_.target(range);
    std::copy(from.begin(), from.end(), to.begin());
    const std::uint32_t leftCount = mid - range.begin;
    NodeSplit split;
    split.mid = mid;
    split.left = measure(to.first(leftCount));
    split.right = measure(to.subspan(leftCount));
    return split;
}

// The depth limit's fallback: an object-median split along the widest centroid axis, ties
// broken by primitive index so that the order is a total one and the result is unique.
std::uint32_t SubtreeBuilder::medianOf(Range range, const Aabb& centroids) const {
    glm::vec3 extent = centroids.max - centroids.min;
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::span<PrimitiveRef> refs = arrays_.source(range);
    auto mid = refs.begin() + range.count() / 2;
    std::nth_element(refs.begin(), mid, refs.end(),
                     [&](const PrimitiveRef& a, const PrimitiveRef& b) {
                         float ca = centroidOf(a)[axis];
                         float cb = centroidOf(b)[axis];
                         return ca < cb || (!(cb < ca) && a.index < b.index);
                     });
    return range.begin + static_cast<std::uint32_t>(mid - refs.begin());
}

void checkOptions(const BvhBuildOptions& options, std::size_t primitiveCount) {
    VKPT_ASSERT(options.binCount >= 2, "binned SAH needs at least two bins");
    VKPT_ASSERT(options.maxLeafSize >= 1 && options.maxLeafSize <= BVH_MAX_LEAF_TRIANGLES,
                "a leaf holds 1 to 15 triangles (4 bits of a wide node's leafCounts)");
    if (primitiveCount >= BVH_MAX_TRIANGLES)
        throw InputError("scene has " + std::to_string(primitiveCount) +
                         " triangles; the BVH holds at most " +
                         std::to_string(BVH_MAX_TRIANGLES - 1));
}

// The references in input order and the root's boxes, a slice per thread.
RangeBounds fillRefs(std::span<const Aabb> bounds, std::span<PrimitiveRef> refs,
                     std::uint32_t threadCount) {
    std::vector<RangeBounds> slices(threadCount);
    forEachSlice(bounds.size(), threadCount,
                 [&](std::size_t begin, std::size_t end, std::uint32_t worker) {
                     for (std::size_t i = begin; i < end; ++i)
                         refs[i] = {bounds[i].min, std::uint32_t(i), bounds[i].max, 0u};
                     slices[worker] = measure(refs.subspan(begin, end - begin));
                 });
    RangeBounds root;
    for (const RangeBounds& slice : slices) {
        root.bounds.extend(slice.bounds);
        root.centroids.extend(slice.centroids);
    }
    return root;
}

// Workers take tasks largest first (only the schedule depends on this, not the result).
void buildTasksInParallel(const BvhBuildOptions& options, const BuildArrays& arrays,
                          std::vector<SubtreeTask>& tasks, std::uint32_t threadCount) {
    std::vector<std::size_t> schedule(tasks.size());
    std::iota(schedule.begin(), schedule.end(), std::size_t(0));
    std::stable_sort(schedule.begin(), schedule.end(), [&](std::size_t a, std::size_t b) {
        return tasks[a].range.count() > tasks[b].range.count();
    });
    std::atomic<std::size_t> next{0};
    runOnWorkers(threadCount, [&](std::uint32_t) {
        SubtreeBuilder builder(options, arrays);
        for (std::size_t i = next++; i < schedule.size(); i = next++) {
            SubtreeTask& task = tasks[schedule[i]];
            task.nodes.reserve(2 * std::size_t(task.range.count()));
            builder.build(task.range, task.bounds, task.nodes, nullptr, 0);
        }
    });
}

// The top levels are stored depth first, so the final numbering is theirs with each
// placeholder replaced by its task's nodes: one scan gives every top node and task its
// place, and the tasks are copied there in parallel. The result is the numbering a
// single-threaded build gives.
std::vector<BvhBuildNode> stitch(const std::vector<BvhBuildNode>& top,
                                 const std::vector<SubtreeTask>& tasks, std::uint32_t threadCount) {
    auto deferred = [&](std::size_t i) { return top[i].firstPrimitive == kDeferredSubtree; };
    std::vector<std::uint32_t> finalIndex(top.size());
    std::vector<std::uint32_t> placeholders;
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < top.size(); ++i) {
        finalIndex[i] = next;
        if (deferred(i)) placeholders.push_back(std::uint32_t(i));
        next += deferred(i) ? std::uint32_t(tasks[top[i].rightChild].nodes.size()) : 1u;
    }
    std::vector<BvhBuildNode> nodes(next);
    for (std::size_t i = 0; i < top.size(); ++i) {
        if (deferred(i)) continue;
        BvhBuildNode n = top[i];
        if (n.primitiveCount == 0) {
            n.leftChild = finalIndex[n.leftChild];
            n.rightChild = finalIndex[n.rightChild];
        }
        nodes[finalIndex[i]] = n;
    }
    std::atomic<std::size_t> taken{0};
    runOnWorkers(threadCount, [&](std::uint32_t) {
        for (std::size_t k = taken++; k < placeholders.size(); k = taken++) {
            const std::uint32_t base = finalIndex[placeholders[k]];
            BvhBuildNode* out = nodes.data() + base;
            for (BvhBuildNode n : tasks[top[placeholders[k]].rightChild].nodes) {
                if (n.primitiveCount == 0) {
                    n.leftChild += base;
                    n.rightChild += base;
                }
                *out++ = n;
            }
        }
    });
    return nodes;
}

// The top levels on this thread, each node's passes sliced across every thread; the subtrees
// below on the workers.
std::vector<BvhBuildNode> buildNodesInParallel(const BvhBuildOptions& options,
                                               const BuildArrays& arrays, const RangeBounds& root,
                                               std::uint32_t threadCount) {
    auto count = static_cast<std::uint32_t>(arrays.primitiveOrder.size());
    std::uint32_t deferBelow = std::max(count / (8 * threadCount), 1024u);
    std::vector<BvhBuildNode> top;
    std::vector<SubtreeTask> tasks;
    SubtreeBuilder(options, arrays, threadCount)
        .build({0, count, 0}, root, top, &tasks, deferBelow);
    buildTasksInParallel(options, arrays, tasks, threadCount);
    return stitch(top, tasks, threadCount);
}

} // namespace

BvhTree buildBvh(std::span<const Aabb> primitiveBounds, const BvhBuildOptions& options) {
    checkOptions(options, primitiveBounds.size());
    const auto count = static_cast<std::uint32_t>(primitiveBounds.size());
    const bool parallel = count >= kParallelMinimum;
    const std::uint32_t threadCount = parallel ? resolveThreadCount(options.threadCount) : 1u;
    // Left uninitialised: every element is written before it is read.
    std::unique_ptr<PrimitiveRef[]> refs[2] = {
        std::make_unique_for_overwrite<PrimitiveRef[]>(count),
        std::make_unique_for_overwrite<PrimitiveRef[]>(count)};
    BvhTree tree;
    tree.primitiveOrder.resize(count);
    const BuildArrays arrays{{std::span(refs[0].get(), count), std::span(refs[1].get(), count)},
                             tree.primitiveOrder};
    const RangeBounds root = fillRefs(primitiveBounds, arrays.refs[0], threadCount);
    if (threadCount > 1) {
        tree.nodes = buildNodesInParallel(options, arrays, root, threadCount);
    } else {
        tree.nodes.reserve(2 * std::size_t(std::max(count, 1u)));
        SubtreeBuilder(options, arrays).build({0, count, 0}, root, tree.nodes, nullptr, 0);
    }
    return tree;
}

std::vector<Aabb> triangleBounds(std::span<const glm::vec3> positions) {
    VKPT_ASSERT(positions.size() % 3 == 0, "three vertices a triangle");
    std::vector<Aabb> bounds(positions.size() / 3);
    const std::uint32_t threads = bounds.size() >= kParallelMinimum ? resolveThreadCount(0) : 1u;
    forEachSlice(bounds.size(), threads, [&](std::size_t begin, std::size_t end, std::uint32_t) {
        for (std::size_t i = begin; i < end; ++i)
            for (std::size_t k = 0; k < 3; ++k)
                bounds[i].extend(positions[3 * i + k]);
    });
    return bounds;
}

namespace {

struct StatsEntry {
    std::uint32_t node;
    std::uint32_t depth;
};

// A flat root (area 0, e.g. every triangle the same point) makes relative areas meaningless;
// then every ray that reaches the root is taken to reach every node.
float relativeArea(const Aabb& bounds, float rootArea) {
    return rootArea > 0.0f ? bounds.surfaceArea() / rootArea : 1.0f;
}

} // namespace

BvhStats computeBvhStats(const BvhTree& tree, const BvhBuildOptions& options) {
    BvhStats stats;
    if (tree.nodes.empty()) return stats;
    float rootArea = tree.nodes[0].bounds.surfaceArea();
    double cost = 0.0;
    std::vector<StatsEntry> stack{{0, 0}};
    while (!stack.empty()) {
        StatsEntry e = stack.back();
        stack.pop_back();
        const BvhBuildNode& n = tree.nodes[e.node];
        ++stats.nodeCount;
        stats.maxDepth = std::max(stats.maxDepth, e.depth);
        double area = relativeArea(n.bounds, rootArea);
        if (n.isLeaf()) {
            ++stats.leafCount;
            stats.maxLeafSize = std::max(stats.maxLeafSize, n.primitiveCount);
            cost += area * options.intersectionCost * n.primitiveCount;
            continue;
        }
        cost += area * options.traversalCost;
        stack.push_back({n.rightChild, e.depth + 1});
        stack.push_back({n.leftChild, e.depth + 1});
    }
    stats.sahCost = static_cast<float>(cost);
    return stats;
}

TimedBvh buildBvhTimed(std::span<const Aabb> primitiveBounds, const BvhBuildOptions& options) {
    TimedBvh result;
    auto start = std::chrono::steady_clock::now();
    result.tree = buildBvh(primitiveBounds, options);
    std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
    result.stats = computeBvhStats(result.tree, options);
    result.stats.buildSeconds = seconds.count();
    return result;
}

} // namespace vkpt
