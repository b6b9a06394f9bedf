// bvh_build_test.cpp — invariants of the binned SAH build on random, structured and degenerate
// inputs, its SAH cost against a median split, and its determinism across thread counts.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/bvh_build.h"
#include "bvh/synthetic_scenes.h"
#include "common/errors.h"

namespace vkpt::bvh_build_test {
namespace {

bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) &&
           glm::all(glm::greaterThanEqual(outer.max, inner.max));
}

bool sameBox(const Aabb& a, const Aabb& b) {
    return a.min == b.min && a.max == b.max;
}

// Checks every structural invariant of a built tree over the given primitive bounds: each node
// reached once, boxes tight and nested, leaves within the size limit, and each primitive in
// exactly one leaf.
class TreeChecker {
public:
    TreeChecker(const BvhTree& tree, std::span<const Aabb> bounds, std::uint32_t maxLeafSize)
        : tree_(tree), bounds_(bounds), maxLeafSize_(maxLeafSize) {}

    ::testing::AssertionResult check() {
        if (tree_.nodes.empty()) return fail("no root");
        if (tree_.primitiveOrder.size() != bounds_.size()) return fail("order size");
        reached_.assign(tree_.nodes.size(), 0);
        covered_.assign(bounds_.size(), 0);
        if (!walk(0, 0)) return ::testing::AssertionFailure() << error_;
        if (std::count(reached_.begin(), reached_.end(), 1) != std::ssize(reached_))
            return fail("a node is not reachable from the root");
        if (std::count(covered_.begin(), covered_.end(), 1) != std::ssize(covered_))
            return fail("a primitive is in no leaf or in two leaves");
        return ::testing::AssertionSuccess();
    }

private:
    ::testing::AssertionResult fail(const std::string& what) {
        return ::testing::AssertionFailure() << what;
    }

    bool walk(std::uint32_t node, std::uint32_t depth) {
        if (node >= tree_.nodes.size() || reached_[node]++) return note("node reached twice", node);
        if (depth > kBvhMaxDepth) return note("deeper than kBvhMaxDepth", node);
        const BvhBuildNode& n = tree_.nodes[node];
        if (n.isLeaf()) return checkLeaf(node, n);
        if (n.leftChild <= node || n.rightChild <= node) return note("child before parent", node);
        for (std::uint32_t child : {n.leftChild, n.rightChild})
            if (!walk(child, depth + 1)) return false;
        Aabb u = tree_.nodes[n.leftChild].bounds;
        u.extend(tree_.nodes[n.rightChild].bounds);
        if (!contains(n.bounds, tree_.nodes[n.leftChild].bounds) ||
            !contains(n.bounds, tree_.nodes[n.rightChild].bounds))
            return note("child box outside its parent's", node);
        return sameBox(u, n.bounds) || note("interior box not the union of its children", node);
    }

    bool checkLeaf(std::uint32_t node, const BvhBuildNode& n) {
        if (n.primitiveCount > maxLeafSize_) return note("leaf too large", node);
        if (n.primitiveCount == 0 && !bounds_.empty()) return note("empty leaf", node);
        if (std::size_t(n.firstPrimitive) + n.primitiveCount > bounds_.size())
            return note("leaf range past the end", node);
        Aabb u;
        for (std::uint32_t i = n.firstPrimitive; i < n.firstPrimitive + n.primitiveCount; ++i) {
            ++covered_[i];
            std::uint32_t p = tree_.primitiveOrder[i];
            if (p >= bounds_.size()) return note("primitive index out of range", node);
            u.extend(bounds_[p]);
        }
        return n.primitiveCount == 0 || sameBox(u, n.bounds) ||
               note("leaf box not the union of its primitives", node);
    }

    bool note(const char* what, std::uint32_t node) {
        error_ = std::string(what) + " at node " + std::to_string(node);
        return false;
    }

    const BvhTree& tree_;
    std::span<const Aabb> bounds_;
    std::uint32_t maxLeafSize_;
    std::vector<int> reached_;
    std::vector<int> covered_;
    std::string error_;
};

::testing::AssertionResult isValidTree(const BvhTree& tree, std::span<const Aabb> bounds,
                                       std::uint32_t maxLeafSize = 4) {
    return TreeChecker(tree, bounds, maxLeafSize).check();
}

// The baseline for the SAH test: object-median splits along the widest centroid axis.
class MedianSplitBuilder {
public:
    MedianSplitBuilder(std::span<const Aabb> bounds, std::uint32_t maxLeafSize)
        : bounds_(bounds), maxLeafSize_(maxLeafSize) {}

    BvhTree build() {
        tree_.primitiveOrder.resize(bounds_.size());
        std::iota(tree_.primitiveOrder.begin(), tree_.primitiveOrder.end(), 0u);
        split(0, static_cast<std::uint32_t>(bounds_.size()));
        return std::move(tree_);
    }

private:
    std::uint32_t split(std::uint32_t begin, std::uint32_t end) {
        auto index = static_cast<std::uint32_t>(tree_.nodes.size());
        tree_.nodes.emplace_back();
        Aabb box, centroids;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.extend(bounds_[tree_.primitiveOrder[i]]);
            centroids.extend(bounds_[tree_.primitiveOrder[i]].centre());
        }
        tree_.nodes[index].bounds = box;
        if (end - begin <= maxLeafSize_) {
            tree_.nodes[index].firstPrimitive = begin;
            tree_.nodes[index].primitiveCount = end - begin;
            return index;
        }
        glm::vec3 e = centroids.max - centroids.min;
        int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        auto first = tree_.primitiveOrder.begin();
        std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(first + begin, first + mid, first + end, [&](auto a, auto b) {
            return bounds_[a].centre()[axis] < bounds_[b].centre()[axis];
        });
        std::uint32_t left = split(begin, mid);
        std::uint32_t right = split(mid, end);
        tree_.nodes[index].leftChild = left;
        tree_.nodes[index].rightChild = right;
        return index;
    }

    std::span<const Aabb> bounds_;
    std::uint32_t maxLeafSize_;
    BvhTree tree_;
};

std::vector<Aabb> boundsOf(const std::vector<glm::vec3>& positions) {
    return triangleBounds(positions);
}

// Two dense clusters far apart and a sparse haze: where a median split cuts badly.
std::vector<glm::vec3> clusteredSoup() {
    std::vector<glm::vec3> positions = synthetic::randomSoup(6000, 11, 1.0f, 0.05f);
    std::vector<glm::vec3> far = synthetic::randomSoup(2000, 12, 1.0f, 0.05f);
    for (glm::vec3& p : far)
        p += glm::vec3(100.0f, 0.0f, 0.0f);
    std::vector<glm::vec3> haze = synthetic::randomSoup(300, 13, 100.0f, 2.0f);
    positions.insert(positions.end(), far.begin(), far.end());
    positions.insert(positions.end(), haze.begin(), haze.end());
    return positions;
}

struct NamedScene {
    std::string name;
    std::vector<glm::vec3> positions;
};

std::vector<NamedScene> structuredScenes() {
    return {{"random soup", synthetic::randomSoup(20000, 1)},
            {"grid", synthetic::grid(100)},
            {"closed cube", synthetic::closedCube(30)},
            {"displaced sphere", synthetic::displacedSphere(60, 120)},
            {"clusters", clusteredSoup()}};
}

std::vector<glm::vec3> identicalTriangles(std::uint32_t count) {
    std::vector<glm::vec3> positions;
    for (std::uint32_t i = 0; i < count; ++i)
        positions.insert(positions.end(),
                         {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
    return positions;
}

bool sameTree(const BvhTree& a, const BvhTree& b) {
    if (a.primitiveOrder != b.primitiveOrder || a.nodes.size() != b.nodes.size()) return false;
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        const BvhBuildNode& x = a.nodes[i];
        const BvhBuildNode& y = b.nodes[i];
        if (!sameBox(x.bounds, y.bounds) || x.leftChild != y.leftChild ||
            x.rightChild != y.rightChild || x.firstPrimitive != y.firstPrimitive ||
            x.primitiveCount != y.primitiveCount)
            return false;
    }
    return true;
}

TEST(Aabb, StartsEmptyAndGrowsToItsPoints) {
    Aabb box;
    EXPECT_TRUE(box.empty());
    EXPECT_EQ(box.surfaceArea(), 0.0f);
    box.extend(glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_FALSE(box.empty());
    EXPECT_EQ(box.surfaceArea(), 0.0f);
    box.extend(glm::vec3(2.0f, 4.0f, 6.0f));
    EXPECT_EQ(box.surfaceArea(), 2.0f * (1.0f * 2.0f + 2.0f * 3.0f + 3.0f * 1.0f));
    EXPECT_EQ(box.centre(), glm::vec3(1.5f, 3.0f, 4.5f));
}

TEST(BvhBuild, TriangleBoundsEncloseTheThreeVertices) {
    std::vector<glm::vec3> p{{0.0f, 5.0f, -1.0f}, {2.0f, 1.0f, 0.0f}, {1.0f, 3.0f, 4.0f}};
    std::vector<Aabb> b = triangleBounds(p);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(b[0].min, glm::vec3(0.0f, 1.0f, -1.0f));
    EXPECT_EQ(b[0].max, glm::vec3(2.0f, 5.0f, 4.0f));
}

TEST(BvhBuild, EveryTriangleInExactlyOneLeafWithNestedTightBoxes) {
    for (const NamedScene& scene : structuredScenes()) {
        std::vector<Aabb> bounds = boundsOf(scene.positions);
        EXPECT_TRUE(isValidTree(buildBvh(bounds), bounds)) << scene.name;
    }
}

TEST(BvhBuild, NodesComeDepthFirstWithTheLeftChildNext) {
    std::vector<Aabb> bounds = boundsOf(synthetic::randomSoup(5000, 2));
    BvhTree tree = buildBvh(bounds);
    for (std::uint32_t i = 0; i < tree.nodes.size(); ++i) {
        if (!tree.nodes[i].isLeaf()) {
            ASSERT_EQ(tree.nodes[i].leftChild, i + 1) << i;
        }
    }
}

TEST(BvhBuild, LeafSizesStayWithinEveryMaximum) {
    std::vector<Aabb> bounds = boundsOf(synthetic::randomSoup(5000, 3));
    for (std::uint32_t maxLeaf : {1u, 2u, 4u, 8u, 15u}) {
        BvhBuildOptions options;
        options.maxLeafSize = maxLeaf;
        options.traversalCost = 50.0f; // wants huge leaves, so the limit is what stops them
        BvhTree tree = buildBvh(bounds, options);
        EXPECT_TRUE(isValidTree(tree, bounds, maxLeaf)) << maxLeaf;
        EXPECT_EQ(computeBvhStats(tree, options).maxLeafSize, maxLeaf) << maxLeaf;
    }
}

TEST(BvhBuild, SahCostNoWorseThanAMedianSplit) {
    for (const NamedScene& scene : structuredScenes()) {
        std::vector<Aabb> bounds = boundsOf(scene.positions);
        BvhStats sah = computeBvhStats(buildBvh(bounds));
        BvhStats median = computeBvhStats(MedianSplitBuilder(bounds, 4).build());
        EXPECT_LE(sah.sahCost, median.sahCost) << scene.name;
        RecordProperty(scene.name + " sah/median",
                       std::to_string(sah.sahCost) + "/" + std::to_string(median.sahCost));
    }
}

TEST(BvhBuild, MakesALeafWhenSplittingCostsMore) {
    std::vector<Aabb> bounds = boundsOf(synthetic::randomSoup(4, 4, 1.0f, 1.0f));
    BvhBuildOptions options;
    options.traversalCost = 100.0f;
    EXPECT_EQ(buildBvh(bounds, options).nodes.size(), 1u);
    options.traversalCost = 0.01f;
    std::vector<Aabb> apart = boundsOf(synthetic::randomSoup(4, 4, 100.0f, 0.1f));
    EXPECT_EQ(buildBvh(apart, options).nodes.size(), 7u); // four leaves of one triangle
}

TEST(BvhBuild, StatsMatchAHandComputedTwoLeafTree) {
    // Two unit right triangles, one at the origin and one 9 units along x.
    std::vector<glm::vec3> p{{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f},  {0.0f, 1.0f, 0.0f},
                             {9.0f, 0.0f, 0.0f}, {10.0f, 0.0f, 0.0f}, {9.0f, 1.0f, 0.0f}};
    BvhBuildOptions options;
    options.maxLeafSize = 1;
    BvhTree tree = buildBvh(triangleBounds(p), options);
    BvhStats stats = computeBvhStats(tree, options);
    EXPECT_EQ(stats.nodeCount, 3u);
    EXPECT_EQ(stats.leafCount, 2u);
    EXPECT_EQ(stats.maxDepth, 1u);
    EXPECT_EQ(stats.maxLeafSize, 1u);
    // Root area 2·(10·1) = 20, each leaf 2·(1·1) = 2: cost 1 + 2·(2/20) = 1.2.
    EXPECT_FLOAT_EQ(stats.sahCost, 1.2f);
    EXPECT_EQ(stats.buildSeconds, 0.0);
}

TEST(BvhBuild, TimedBuildReportsItsTimeAndTheSameTree) {
    std::vector<Aabb> bounds = boundsOf(synthetic::randomSoup(3000, 5));
    TimedBvh timed = buildBvhTimed(bounds);
    EXPECT_GT(timed.stats.buildSeconds, 0.0);
    EXPECT_TRUE(sameTree(timed.tree, buildBvh(bounds)));
    EXPECT_EQ(timed.stats.nodeCount, timed.tree.nodes.size());
}

TEST(BvhBuild, ZeroTrianglesGiveOneEmptyLeaf) {
    BvhTree tree = buildBvh({});
    ASSERT_EQ(tree.nodes.size(), 1u);
    EXPECT_TRUE(tree.nodes[0].isLeaf());
    EXPECT_EQ(tree.nodes[0].primitiveCount, 0u);
    EXPECT_TRUE(tree.primitiveOrder.empty());
    BvhStats stats = computeBvhStats(tree);
    EXPECT_EQ(stats.nodeCount, 1u);
    EXPECT_EQ(stats.leafCount, 1u);
    EXPECT_EQ(stats.sahCost, 0.0f);
}

TEST(BvhBuild, OneTriangleIsOneLeaf) {
    std::vector<Aabb> bounds = boundsOf(synthetic::randomSoup(1, 6));
    BvhTree tree = buildBvh(bounds);
    ASSERT_EQ(tree.nodes.size(), 1u);
    EXPECT_EQ(tree.nodes[0].primitiveCount, 1u);
    EXPECT_TRUE(isValidTree(tree, bounds));
    EXPECT_EQ(computeBvhStats(tree).sahCost, 1.0f);
}

// No plane separates identical centroids: the build halves the index range instead, which
// gives a balanced tree of full leaves.
TEST(BvhBuild, IdenticalTrianglesGiveABalancedTree) {
    std::vector<Aabb> bounds = boundsOf(identicalTriangles(10000));
    BvhTree tree = buildBvh(bounds);
    EXPECT_TRUE(isValidTree(tree, bounds));
    BvhStats stats = computeBvhStats(tree);
    EXPECT_LE(stats.maxDepth, 12u); // ⌈log2(10000 / 4)⌉ = 12
    EXPECT_EQ(stats.maxLeafSize, 4u);
}

TEST(BvhBuild, IdenticalPointTrianglesWithZeroAreaStillSplit) {
    std::vector<glm::vec3> points(3 * 100, glm::vec3(1.0f, 2.0f, 3.0f));
    std::vector<Aabb> bounds = boundsOf(points);
    BvhTree tree = buildBvh(bounds);
    EXPECT_TRUE(isValidTree(tree, bounds));
    EXPECT_TRUE(std::isfinite(computeBvhStats(tree).sahCost));
}

TEST(BvhBuild, HugeCountOfCoplanarTrianglesBuildsAValidShallowTree) {
    std::vector<Aabb> bounds = boundsOf(synthetic::grid(400)); // 320,000 triangles, z = 0
    BvhTree tree = buildBvh(bounds);
    EXPECT_TRUE(isValidTree(tree, bounds));
    BvhStats stats = computeBvhStats(tree);
    EXPECT_LE(stats.maxDepth, 30u);
    EXPECT_EQ(tree.nodes[0].bounds.min.z, 0.0f);
    EXPECT_EQ(tree.nodes[0].bounds.max.z, 0.0f);
}

// Triangles at x = 1.1^i: each binned split peels off only the last few, so without the
// depth limit the tree would be a chain hundreds of nodes deep.
TEST(BvhBuild, DepthStaysBoundedOnExponentiallySpacedTriangles) {
    std::vector<glm::vec3> positions;
    for (int i = 0; i < 900; ++i) {
        float x = std::pow(1.1f, static_cast<float>(i));
        float s = 0.01f * x;
        positions.insert(positions.end(), {{x, 0.0f, 0.0f}, {x + s, 0.0f, 0.0f}, {x, s, 0.0f}});
    }
    std::vector<Aabb> bounds = boundsOf(positions);
    BvhTree tree = buildBvh(bounds);
    EXPECT_TRUE(isValidTree(tree, bounds));
    BvhStats stats = computeBvhStats(tree);
    EXPECT_LE(stats.maxDepth, kBvhMaxDepth);
    RecordProperty("maxDepth", std::to_string(stats.maxDepth));
}

TEST(BvhBuild, SameTreeForAnyThreadCount) {
    std::vector<Aabb> bounds = boundsOf(synthetic::displacedSphere(300, 400)); // 240,000
    BvhBuildOptions options;
    options.threadCount = 1;
    BvhTree reference = buildBvh(bounds, options);
    EXPECT_TRUE(isValidTree(reference, bounds));
    for (std::uint32_t threads : {2u, 3u, 8u}) {
        options.threadCount = threads;
        EXPECT_TRUE(sameTree(buildBvh(bounds, options), reference)) << threads << " threads";
    }
}

TEST(BvhBuild, RejectsOptionsOutsideThePackedLeafWord) {
    std::vector<Aabb> bounds = boundsOf(synthetic::randomSoup(10, 7));
    BvhBuildOptions options;
    options.maxLeafSize = 16;
    EXPECT_THROW(buildBvh(bounds, options), InternalError);
    options.maxLeafSize = 0;
    EXPECT_THROW(buildBvh(bounds, options), InternalError);
    options = {};
    options.binCount = 1;
    EXPECT_THROW(buildBvh(bounds, options), InternalError);
}

TEST(BvhBuild, AnyBinCountGivesAValidTree) {
    std::vector<Aabb> bounds = boundsOf(synthetic::closedCube(20));
    for (std::uint32_t bins : {2u, 3u, 16u, 64u}) {
        BvhBuildOptions options;
        options.binCount = bins;
        EXPECT_TRUE(isValidTree(buildBvh(bounds, options), bounds)) << bins << " bins";
    }
}

} // namespace
} // namespace vkpt::bvh_build_test
