// bvh_flatten_test.cpp — the stackless layout: depth-first order, well-formed skip links, leaf
// ranges that cover the triangle array once, and the skip-link walk equal to the stack walk.
#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/bvh_flatten.h"
#include "bvh/bvh_traverse.h"
#include "bvh/synthetic_scenes.h"

namespace vkpt {
namespace {

struct BuiltScene {
    BvhTree tree;
    StackBvh stackBvh; // the tree laid out for the ordered stack walk
    std::vector<gpu::BvhNode> nodes;
    std::vector<gpu::Triangle> triangles; // BVH order
};

// The triangles in BVH order: triangle i is the input triangle primitiveOrder[i].
std::vector<gpu::Triangle> bvhOrderedTriangles(const std::vector<glm::vec3>& positions,
                                               const BvhTree& tree) {
    std::vector<gpu::Triangle> triangles;
    for (std::uint32_t source : tree.primitiveOrder) {
        const glm::vec3* p = &positions[3 * std::size_t(source)];
        triangles.push_back({p[0], 0u, p[1], NO_EMITTER, p[2], source});
    }
    return triangles;
}

BuiltScene buildScene(const std::vector<glm::vec3>& positions, BvhBuildOptions options = {},
                      FlattenOptions flatten = {}) {
    BuiltScene s;
    s.tree = buildBvh(triangleBounds(positions), options);
    s.nodes = flattenBvh(s.tree, flatten);
    s.triangles = bvhOrderedTriangles(positions, s.tree);
    s.stackBvh = makeStackBvh(s.tree, s.triangles);
    return s;
}

// A direction with no zero component, so that it orders children along every axis.
const glm::vec3 kViewDirection{-0.3f, 0.5f, -0.8f};

// Each scene flattened left child first and near child first along kViewDirection.
std::vector<BuiltScene> testScenes() {
    BvhBuildOptions wideLeaves;
    wideLeaves.maxLeafSize = 15;
    wideLeaves.traversalCost = 3.0f;
    std::vector<BuiltScene> scenes;
    for (FlattenOptions flatten : {FlattenOptions{}, FlattenOptions{kViewDirection}}) {
        scenes.push_back(buildScene(synthetic::randomSoup(3000, 21), {}, flatten));
        scenes.push_back(buildScene(synthetic::grid(40), {}, flatten));
        scenes.push_back(buildScene(synthetic::closedCube(12), {}, flatten));
        scenes.push_back(buildScene(synthetic::displacedSphere(30, 60), wideLeaves, flatten));
    }
    return scenes;
}

glm::vec3 centre(const gpu::BvhNode& n) {
    return 0.5f * n.boundsMin + 0.5f * n.boundsMax;
}

// Follows the walk a ray takes when it enters every box: it must visit each node once, in
// index order, and end at BVH_END.
std::vector<std::uint32_t> walkEnteringEveryBox(const std::vector<gpu::BvhNode>& nodes) {
    std::vector<std::uint32_t> visited;
    for (std::uint32_t i = 0; i != BVH_END && visited.size() <= nodes.size();) {
        visited.push_back(i);
        i = nodes[i].leafTriangles != 0 ? nodes[i].missIndex : i + 1;
    }
    return visited;
}

// The index after the subtree rooted at node, computed from the links alone.
std::uint32_t subtreeEnd(const std::vector<gpu::BvhNode>& nodes, std::uint32_t node) {
    if (nodes[node].leafTriangles != 0) return node + 1;
    return subtreeEnd(nodes, subtreeEnd(nodes, node + 1));
}

bool boxInside(const gpu::BvhNode& outer, const gpu::BvhNode& inner) {
    return glm::all(glm::lessThanEqual(outer.boundsMin, inner.boundsMin)) &&
           glm::all(glm::greaterThanEqual(outer.boundsMax, inner.boundsMax));
}

TEST(BvhFlatten, SkipLinksPointForwardAndEndAtBvhEnd) {
    for (const BuiltScene& s : testScenes()) {
        auto count = static_cast<std::uint32_t>(s.nodes.size());
        ASSERT_EQ(count, s.tree.nodes.size());
        for (std::uint32_t i = 0; i < count; ++i) {
            std::uint32_t miss = s.nodes[i].missIndex;
            EXPECT_TRUE(miss == BVH_END || (miss > i && miss < count)) << i;
        }
        EXPECT_EQ(s.nodes[0].missIndex, BVH_END);
        EXPECT_NE(s.nodes.back().leafTriangles, 0u); // the last node is a leaf
        EXPECT_EQ(s.nodes.back().missIndex, BVH_END);
    }
}

TEST(BvhFlatten, EveryNodeIsReachedOnceByAWalkThatEntersEveryBox) {
    for (const BuiltScene& s : testScenes()) {
        std::vector<std::uint32_t> visited = walkEnteringEveryBox(s.nodes);
        std::vector<std::uint32_t> expected(s.nodes.size());
        std::iota(expected.begin(), expected.end(), 0u);
        EXPECT_EQ(visited, expected);
    }
}

// Interior node i: first child at i + 1, second child where the first's subtree ends, and a
// miss anywhere in the subtree of i skips to where the subtree of i ends.
TEST(BvhFlatten, MissLinksSkipExactlyTheSubtree) {
    for (const BuiltScene& s : testScenes()) {
        auto count = static_cast<std::uint32_t>(s.nodes.size());
        for (std::uint32_t i = 0; i < count; ++i) {
            std::uint32_t end = subtreeEnd(s.nodes, i);
            EXPECT_EQ(s.nodes[i].missIndex, end == count ? BVH_END : end) << i;
            if (s.nodes[i].leafTriangles != 0) continue;
            std::uint32_t second = subtreeEnd(s.nodes, i + 1);
            ASSERT_LT(second, count);
            EXPECT_EQ(s.nodes[i + 1].missIndex, second);
            EXPECT_EQ(s.nodes[second].missIndex, s.nodes[i].missIndex);
            EXPECT_TRUE(boxInside(s.nodes[i], s.nodes[i + 1])) << i;
            EXPECT_TRUE(boxInside(s.nodes[i], s.nodes[second])) << i;
        }
    }
}

TEST(BvhFlatten, LeafRangesCoverTheTriangleArrayExactlyOnce) {
    for (const BuiltScene& s : testScenes()) {
        std::vector<int> covered(s.triangles.size(), 0);
        for (const gpu::BvhNode& n : s.nodes) {
            if (n.leafTriangles == 0) continue;
            std::uint32_t first = gpu::leafFirstTriangle(n.leafTriangles);
            std::uint32_t count = gpu::leafTriangleCount(n.leafTriangles);
            EXPECT_GE(count, 1u);
            EXPECT_LE(count, BVH_MAX_LEAF_TRIANGLES);
            ASSERT_LE(std::size_t(first) + count, s.triangles.size());
            for (std::uint32_t i = first; i < first + count; ++i)
                ++covered[i];
        }
        EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), std::ssize(covered));
    }
}

// Left child first, the leaves meet the triangle array in order, as the tree's leaves do.
TEST(BvhFlatten, LeftFirstLeavesFollowTheTriangleArrayInOrder) {
    BuiltScene s = buildScene(synthetic::randomSoup(3000, 25));
    std::uint32_t next = 0;
    for (const gpu::BvhNode& n : s.nodes) {
        if (n.leafTriangles == 0) continue;
        EXPECT_EQ(gpu::leafFirstTriangle(n.leafTriangles), next);
        next += gpu::leafTriangleCount(n.leafTriangles);
    }
    EXPECT_EQ(next, s.triangles.size());
}

TEST(BvhFlatten, NearFirstDirectionPutsTheNearerChildFirst) {
    BuiltScene s = buildScene(synthetic::displacedSphere(30, 60), {}, {kViewDirection});
    auto count = static_cast<std::uint32_t>(s.nodes.size());
    std::uint32_t swapped = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
        if (s.nodes[i].leafTriangles != 0) continue;
        std::uint32_t second = subtreeEnd(s.nodes, i + 1);
        float gap = glm::dot(centre(s.nodes[second]) - centre(s.nodes[i + 1]), kViewDirection);
        EXPECT_GE(gap, 0.0f) << i;
    }
    // The same tree flattened left first differs, or the option did nothing.
    std::vector<gpu::BvhNode> leftFirst = flattenBvh(s.tree);
    for (std::uint32_t i = 0; i < count; ++i)
        swapped += leftFirst[i].leafTriangles != s.nodes[i].leafTriangles ? 1u : 0u;
    EXPECT_GT(swapped, 0u);
}

TEST(BvhFlatten, LeafBoxesHoldTheirTriangles) {
    for (const BuiltScene& s : testScenes()) {
        for (const gpu::BvhNode& n : s.nodes) {
            std::uint32_t first = gpu::leafFirstTriangle(n.leafTriangles);
            std::uint32_t count = n.leafTriangles ? gpu::leafTriangleCount(n.leafTriangles) : 0;
            for (std::uint32_t i = first; i < first + count; ++i) {
                for (glm::vec3 v : {s.triangles[i].v0, s.triangles[i].v1, s.triangles[i].v2}) {
                    EXPECT_TRUE(glm::all(glm::lessThanEqual(n.boundsMin, v)) &&
                                glm::all(glm::lessThanEqual(v, n.boundsMax)));
                }
            }
        }
    }
}

// The flat order is the tree's preorder, so it does not depend on how the tree numbers its
// nodes: a tree stored with nodes 1..n-1 in reverse (children before parents) flattens to the
// same array.
TEST(BvhFlatten, DoesNotDependOnTheTreeNodeNumbering) {
    BuiltScene s = buildScene(synthetic::randomSoup(500, 22));
    auto count = static_cast<std::uint32_t>(s.tree.nodes.size());
    auto renumber = [&](std::uint32_t i) { return i == 0 ? 0 : count - i; };
    BvhTree shuffled = s.tree;
    for (std::uint32_t i = 0; i < count; ++i) {
        BvhBuildNode n = s.tree.nodes[i];
        if (!n.isLeaf()) {
            n.leftChild = renumber(n.leftChild);
            n.rightChild = renumber(n.rightChild);
        }
        shuffled.nodes[renumber(i)] = n;
    }
    std::vector<gpu::BvhNode> flat = flattenBvh(shuffled);
    ASSERT_EQ(flat.size(), s.nodes.size());
    for (std::size_t i = 0; i < flat.size(); ++i) {
        EXPECT_EQ(flat[i].missIndex, s.nodes[i].missIndex) << i;
        EXPECT_EQ(flat[i].leafTriangles, s.nodes[i].leafTriangles) << i;
        EXPECT_EQ(flat[i].boundsMin, s.nodes[i].boundsMin) << i;
        EXPECT_EQ(flat[i].boundsMax, s.nodes[i].boundsMax) << i;
    }
}

TEST(BvhFlatten, OneTriangleIsOneLeafNode) {
    BuiltScene s = buildScene(synthetic::randomSoup(1, 23));
    ASSERT_EQ(s.nodes.size(), 1u);
    EXPECT_EQ(s.nodes[0].missIndex, BVH_END);
    EXPECT_EQ(s.nodes[0].leafTriangles, gpu::packLeafTriangles(0, 1));
}

TEST(BvhFlatten, EmptyTreeIsOneEmptyLeafThatNoRayHits) {
    BvhTree tree = buildBvh({});
    std::vector<gpu::BvhNode> nodes = flattenBvh(tree);
    ASSERT_EQ(nodes.size(), 1u);
    EXPECT_EQ(nodes[0].missIndex, BVH_END);
    EXPECT_EQ(nodes[0].leafTriangles, kEmptyLeafTriangles);
    EXPECT_NE(nodes[0].leafTriangles, 0u);
    EXPECT_EQ(gpu::leafTriangleCount(nodes[0].leafTriangles), 0u);
    RayQuery ray{glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, -1.0f)};
    EXPECT_FALSE(closestHitStackless(nodes, {}, ray).hit);
    EXPECT_FALSE(anyHitStackless(nodes, {}, ray));
    StackBvh stackBvh = makeStackBvh(tree, {});
    EXPECT_FALSE(closestHitStack(stackBvh, ray).hit);
    EXPECT_FALSE(anyHitStack(stackBvh, ray));
}

TEST(BvhFlatten, StacklessMatchesRecursive) {
    synthetic::Rng rng(24);
    for (const BuiltScene& s : testScenes()) {
        Aabb bounds = s.tree.nodes[0].bounds;
        glm::vec3 margin = 0.5f * (bounds.max - bounds.min);
        for (int i = 0; i < 2500; ++i) {
            RayQuery ray{rng.inBox(bounds.min - margin, bounds.max + margin), rng.unitVector()};
            ClosestHit stack = closestHitStack(s.stackBvh, ray);
            ClosestHit stackless = closestHitStackless(s.nodes, s.triangles, ray);
            ASSERT_EQ(stack.hit, stackless.hit) << i;
            if (!stack.hit) continue;
            EXPECT_EQ(stack.t, stackless.t) << i;
            if (stack.triangle == stackless.triangle) {
                EXPECT_EQ(stack.u, stackless.u);
                EXPECT_EQ(stack.v, stackless.v);
            }
        }
    }
}

} // namespace
} // namespace vkpt
