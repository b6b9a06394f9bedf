// bvh_build.cpp — binned SAH construction of the BVH (Wald 2007) over an index array that is
// partitioned in place; the subtrees below the top levels are built on worker threads.
#include "bvh/bvh_build.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <numeric>
#include <string>
#include <thread>

#include "common/errors.h"
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

struct Range {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    std::uint32_t depth = 0;

    std::uint32_t count() const { return end - begin; }
};

// Read-only inputs shared by every builder thread.
struct BuildInput {
    std::span<const Aabb> bounds;
    std::vector<glm::vec3> centroids;
    BvhBuildOptions options;
};

struct RangeBounds {
    Aabb bounds;
    Aabb centroids;
};

struct Bin {
    Aabb bounds;
    std::uint32_t count = 0;
};

// Maps a centroid coordinate to its bin along one axis (Wald 2007, section 3.1: bins of equal
// width over the centroid bounds, not the node bounds, so that the end bins are never empty
// and some plane separates any two distinct centroids).
struct BinMapping {
    float origin = 0.0f;
    float scale = 0.0f;
    std::uint32_t lastBin = 0;

    std::uint32_t binOf(float c) const {
        float f = (c - origin) * scale;
        // NaN and the smallest centroid go to bin 0; the largest lands on binCount: clamp it.
        if (!(f > 0.0f)) return 0;
        return f < static_cast<float>(lastBin) ? static_cast<std::uint32_t>(f) : lastBin;
    }
};

struct SplitPlane {
    std::uint32_t axis = kNoAxis;
    std::uint32_t bin = 0; // bins 0..bin go left
    float cost = 0.0f;     // SAH cost scaled by the node's surface area
};

struct NodePlan {
    RangeBounds bounds;
    std::uint32_t mid = 0; // left child [begin, mid), right child [mid, end)
    bool leaf = true;
};

struct Pending {
    Range range;
    std::uint32_t parent = kNoParent;
    bool isRight = false;
};

// A subtree the top level leaves to the workers.
struct SubtreeTask {
    Range range;
    std::vector<BvhBuildNode> nodes; // depth first, indices local to this vector
};

BinMapping makeBinMapping(const Aabb& centroids, std::uint32_t axis, std::uint32_t binCount) {
    BinMapping m;
    m.origin = centroids.min[int(axis)];
    float extent = centroids.max[int(axis)] - centroids.min[int(axis)];
    m.scale = extent > 0.0f ? static_cast<float>(binCount) / extent : 0.0f;
    m.lastBin = binCount - 1;
    return m;
}

// Builds one subtree at a time into a node vector, depth first, reusing its scratch space
// so that the hot loop allocates nothing.
class SubtreeBuilder {
public:
    SubtreeBuilder(const BuildInput& input, std::span<std::uint32_t> order)
        : input_(input), order_(order), bins_(3 * std::size_t(input.options.binCount)),
          rightCosts_(input.options.binCount) {}

    // Appends the subtree over root to nodes. With tasks, a node (other than root) with at
    // most deferBelow primitives becomes a placeholder and its range a task.
    void build(Range root, std::vector<BvhBuildNode>& nodes, std::vector<SubtreeTask>* tasks,
               std::uint32_t deferBelow);

private:
    NodePlan planNode(Range range);
    RangeBounds measure(Range range) const;
    SplitPlane findBestSplit(Range range, const RangeBounds& rb);
    void fillBins(Range range, const BinMapping* mappings);
    void sweepAxis(std::uint32_t axis, const RangeBounds& rb, std::uint32_t count,
                   SplitPlane& best);
    std::uint32_t partition(Range range, const SplitPlane& split, const Aabb& centroids);
    std::uint32_t medianSplit(Range range, const Aabb& centroids);
    float leafCost(std::uint32_t count, float area) const;

    const BuildInput& input_;
    std::span<std::uint32_t> order_;
    std::vector<Bin> bins_; // binCount per axis, x then y then z
    std::vector<float> rightCosts_;
    std::vector<Pending> stack_;
};

void linkToParent(std::vector<BvhBuildNode>& nodes, const Pending& p, std::uint32_t index) {
    if (p.parent == kNoParent) return;
    (p.isRight ? nodes[p.parent].rightChild : nodes[p.parent].leftChild) = index;
}

void deferSubtree(BvhBuildNode& placeholder, Range range, std::vector<SubtreeTask>& tasks) {
    placeholder.firstPrimitive = kDeferredSubtree;
    placeholder.rightChild = static_cast<std::uint32_t>(tasks.size());
    tasks.push_back({range, {}});
}

void SubtreeBuilder::build(Range root, std::vector<BvhBuildNode>& nodes,
                           std::vector<SubtreeTask>* tasks, std::uint32_t deferBelow) {
    stack_.clear();
    stack_.push_back({root, kNoParent, false});
    while (!stack_.empty()) {
        Pending p = stack_.back();
        stack_.pop_back();
        auto index = static_cast<std::uint32_t>(nodes.size());
        BvhBuildNode& node = nodes.emplace_back();
        linkToParent(nodes, p, index);
        if (tasks && p.parent != kNoParent && p.range.count() <= deferBelow) {
            deferSubtree(node, p.range, *tasks);
            continue;
        }
        NodePlan plan = planNode(p.range);
        node.bounds = plan.bounds.bounds;
        if (plan.leaf) {
            node.firstPrimitive = p.range.begin;
            node.primitiveCount = p.range.count();
            continue;
        }
        // Right first, so that the left child is popped next and lands at index + 1.
        stack_.push_back({{plan.mid, p.range.end, p.range.depth + 1}, index, true});
        stack_.push_back({{p.range.begin, plan.mid, p.range.depth + 1}, index, false});
    }
}

// Leaf or split, and where: a leaf when it is cheaper than the best binned split (or holds
// one primitive), a forced split above maxLeafSize.
NodePlan SubtreeBuilder::planNode(Range range) {
    NodePlan plan;
    plan.bounds = measure(range);
    std::uint32_t count = range.count();
    std::uint32_t maxLeaf = input_.options.maxLeafSize;
    if (count <= 1) return plan;
    if (range.depth >= kBvhMaxSahDepth) {
        if (count <= maxLeaf) return plan;
        plan.mid = medianSplit(range, plan.bounds.centroids);
        plan.leaf = false;
        return plan;
    }
    SplitPlane split = findBestSplit(range, plan.bounds);
    float area = plan.bounds.bounds.surfaceArea();
    bool noSplit = split.axis == kNoAxis;
    if (count <= maxLeaf && (noSplit || leafCost(count, area) <= split.cost)) return plan;
    plan.mid = noSplit ? range.begin + count / 2 // all centroids equal: halve the index range
                       : partition(range, split, plan.bounds.centroids);
    plan.leaf = false;
    return plan;
}

RangeBounds SubtreeBuilder::measure(Range range) const {
    RangeBounds rb;
    for (std::uint32_t i = range.begin; i < range.end; ++i) {
        std::uint32_t p = order_[i];
        rb.bounds.extend(input_.bounds[p]);
        rb.centroids.extend(input_.centroids[p]);
    }
    return rb;
}

// Costs are scaled by the node's area A so that a flat or point-like node (A = 0) needs no
// division: leaf = Ci·N·A, split = Ct·A + Ci·(A_L·N_L + A_R·N_R) (Wald 2007, eq. 1).
float SubtreeBuilder::leafCost(std::uint32_t count, float area) const {
    return input_.options.intersectionCost * static_cast<float>(count) * area;
}

SplitPlane SubtreeBuilder::findBestSplit(Range range, const RangeBounds& rb) {
    std::uint32_t binCount = input_.options.binCount;
    BinMapping mappings[3];
    for (std::uint32_t axis = 0; axis < 3; ++axis)
        mappings[axis] = makeBinMapping(rb.centroids, axis, binCount);
    fillBins(range, mappings);
    SplitPlane best;
    for (std::uint32_t axis = 0; axis < 3; ++axis)
        if (mappings[axis].scale > 0.0f) sweepAxis(axis, rb, range.count(), best);
    return best;
}

// One pass over the range bins all three axes at once.
void SubtreeBuilder::fillBins(Range range, const BinMapping* mappings) {
    std::uint32_t binCount = input_.options.binCount;
    std::fill(bins_.begin(), bins_.end(), Bin{});
    for (std::uint32_t i = range.begin; i < range.end; ++i) {
        std::uint32_t p = order_[i];
        const glm::vec3& c = input_.centroids[p];
        for (std::uint32_t axis = 0; axis < 3; ++axis) {
            Bin& bin = bins_[axis * binCount + mappings[axis].binOf(c[int(axis)])];
            bin.bounds.extend(input_.bounds[p]);
            ++bin.count;
        }
    }
}

// Sweeps the planes between bins: right-to-left areas first, then left to right. Ties keep
// the first plane found, so the result does not depend on anything but the input.
void SubtreeBuilder::sweepAxis(std::uint32_t axis, const RangeBounds& rb, std::uint32_t count,
                               SplitPlane& best) {
    std::uint32_t binCount = input_.options.binCount;
    const Bin* bins = &bins_[axis * binCount];
    Aabb right;
    std::uint32_t rightCount = 0;
    for (std::uint32_t i = binCount - 1; i > 0; --i) {
        right.extend(bins[i].bounds);
        rightCount += bins[i].count;
        rightCosts_[i] = right.surfaceArea() * static_cast<float>(rightCount);
    }
    float nodeTerm = input_.options.traversalCost * rb.bounds.surfaceArea();
    Aabb left;
    std::uint32_t leftCount = 0;
    for (std::uint32_t i = 0; i + 1 < binCount; ++i) {
        left.extend(bins[i].bounds);
        leftCount += bins[i].count;
        if (leftCount == 0 || leftCount == count) continue;
        float sides = left.surfaceArea() * static_cast<float>(leftCount) + rightCosts_[i + 1];
        float cost = nodeTerm + input_.options.intersectionCost * sides;
        if (best.axis == kNoAxis || cost < best.cost) best = {axis, i, cost};
    }
}

// Left: the centroids in bins 0..split.bin, by the same mapping that filled the bins, so that
// the children hold exactly the counts the sweep costed.
std::uint32_t SubtreeBuilder::partition(Range range, const SplitPlane& split,
                                        const Aabb& centroids) {
    BinMapping mapping = makeBinMapping(centroids, split.axis, input_.options.binCount);
    auto first = order_.begin() + range.begin;
    auto last = order_.begin() + range.end;
    int axis = int(split.axis);
    auto mid = std::partition(first, last, [&](std::uint32_t p) {
        return mapping.binOf(input_.centroids[p][axis]) <= split.bin;
    });
    return static_cast<std::uint32_t>(mid - order_.begin());
}

// The depth limit's fallback: an object-median split along the widest centroid axis, ties
// broken by primitive index so that the order is a total one and the result is unique.
std::uint32_t SubtreeBuilder::medianSplit(Range range, const Aabb& centroids) {
    glm::vec3 extent = centroids.max - centroids.min;
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    auto first = order_.begin() + range.begin;
    auto mid = first + range.count() / 2;
    std::nth_element(first, mid, order_.begin() + range.end, [&](std::uint32_t a, std::uint32_t b) {
        float ca = input_.centroids[a][axis];
        float cb = input_.centroids[b][axis];
        return ca < cb || (!(cb < ca) && a < b);
    });
    return static_cast<std::uint32_t>(mid - order_.begin());
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

BuildInput makeBuildInput(std::span<const Aabb> primitiveBounds, const BvhBuildOptions& options) {
    BuildInput input{primitiveBounds, {}, options};
    input.centroids.resize(primitiveBounds.size());
    for (std::size_t i = 0; i < primitiveBounds.size(); ++i)
        input.centroids[i] = primitiveBounds[i].centre();
    return input;
}

std::uint32_t resolveThreadCount(const BvhBuildOptions& options) {
    if (options.threadCount > 0) return options.threadCount;
    return std::max(1u, std::thread::hardware_concurrency());
}

// Workers take tasks largest first (only the schedule depends on this, not the result).
void buildTasksInParallel(const BuildInput& input, std::span<std::uint32_t> order,
                          std::vector<SubtreeTask>& tasks, std::uint32_t threadCount) {
    std::vector<std::size_t> schedule(tasks.size());
    std::iota(schedule.begin(), schedule.end(), std::size_t(0));
    std::stable_sort(schedule.begin(), schedule.end(), [&](std::size_t a, std::size_t b) {
        return tasks[a].range.count() > tasks[b].range.count();
    });
    std::atomic<std::size_t> next{0};
    std::vector<std::exception_ptr> errors(threadCount);
    auto work = [&](std::uint32_t worker) {
        try {
            SubtreeBuilder builder(input, order);
            for (std::size_t i = next++; i < schedule.size(); i = next++) {
                SubtreeTask& task = tasks[schedule[i]];
                task.nodes.reserve(2 * std::size_t(task.range.count()));
                builder.build(task.range, task.nodes, nullptr, 0);
            }
        } catch (...) {
            errors[worker] = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    for (std::uint32_t t = 1; t < threadCount; ++t)
        threads.emplace_back(work, t);
    work(0);
    for (std::thread& t : threads)
        t.join();
    for (const std::exception_ptr& e : errors)
        if (e) std::rethrow_exception(e);
}

// Copies the top levels depth first, splicing in each task's nodes at its placeholder, so
// that the final numbering is the one a single-threaded build gives.
void appendStitched(const std::vector<BvhBuildNode>& top, std::uint32_t node,
                    const std::vector<SubtreeTask>& tasks, std::vector<BvhBuildNode>& out) {
    const BvhBuildNode& n = top[node];
    if (n.firstPrimitive == kDeferredSubtree) {
        auto base = static_cast<std::uint32_t>(out.size());
        for (BvhBuildNode copy : tasks[n.rightChild].nodes) {
            if (copy.primitiveCount == 0) {
                copy.leftChild += base;
                copy.rightChild += base;
            }
            out.push_back(copy);
        }
        return;
    }
    auto index = static_cast<std::uint32_t>(out.size());
    out.push_back(n);
    if (n.primitiveCount > 0) return;
    out[index].leftChild = static_cast<std::uint32_t>(out.size());
    appendStitched(top, n.leftChild, tasks, out);
    out[index].rightChild = static_cast<std::uint32_t>(out.size());
    appendStitched(top, n.rightChild, tasks, out);
}

std::vector<BvhBuildNode> buildNodesInParallel(const BuildInput& input,
                                               std::span<std::uint32_t> order,
                                               std::uint32_t threadCount) {
    auto count = static_cast<std::uint32_t>(order.size());
    std::uint32_t deferBelow = std::max(count / (8 * threadCount), 1024u);
    std::vector<BvhBuildNode> top;
    std::vector<SubtreeTask> tasks;
    SubtreeBuilder(input, order).build({0, count, 0}, top, &tasks, deferBelow);
    buildTasksInParallel(input, order, tasks, threadCount);
    std::vector<BvhBuildNode> nodes;
    nodes.reserve(2 * std::size_t(count));
    appendStitched(top, 0, tasks, nodes);
    return nodes;
}

} // namespace

BvhTree buildBvh(std::span<const Aabb> primitiveBounds, const BvhBuildOptions& options) {
    checkOptions(options, primitiveBounds.size());
    BuildInput input = makeBuildInput(primitiveBounds, options);
    BvhTree tree;
    tree.primitiveOrder.resize(primitiveBounds.size());
    std::iota(tree.primitiveOrder.begin(), tree.primitiveOrder.end(), 0u);
    std::uint32_t threadCount = resolveThreadCount(options);
    auto count = static_cast<std::uint32_t>(primitiveBounds.size());
    if (threadCount > 1 && primitiveBounds.size() >= kParallelMinimum) {
        tree.nodes = buildNodesInParallel(input, tree.primitiveOrder, threadCount);
        return tree;
    }
    tree.nodes.reserve(2 * std::size_t(std::max(count, 1u)));
    SubtreeBuilder(input, tree.primitiveOrder).build({0, count, 0}, tree.nodes, nullptr, 0);
    return tree;
}

std::vector<Aabb> triangleBounds(std::span<const glm::vec3> positions) {
    VKPT_ASSERT(positions.size() % 3 == 0, "three vertices a triangle");
    std::vector<Aabb> bounds(positions.size() / 3);
    for (std::size_t i = 0; i < bounds.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k)
            bounds[i].extend(positions[3 * i + k]);
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
