// bvh_stack_layout_test.cpp — the stack walk's layout (makeStackBvh) is the tree, rearranged:
// every interior node's children sit in one pair with the tree's boxes and leaf ranges, every
// pair is reached once, pairs form blocks of at most three levels, and the primitives are the
// ones given. (That walks over it find what brute force finds is bvh_traverse_test's job.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "bvh/bvh_stack_layout.h"
#include "bvh/synthetic_scenes.h"
#include "common/errors.h"

namespace vkpt::bvh_stack_layout_test {
namespace {

struct Built {
    BvhTree tree;
    std::vector<gpu::Triangle> triangles; // BVH order
    StackBvh bvh;
};

Built build(const std::vector<glm::vec3>& positions) {
    Built b;
    b.tree = buildBvh(triangleBounds(positions));
    for (std::uint32_t source : b.tree.primitiveOrder) {
        const glm::vec3* p = &positions[3 * std::size_t(source)];
        b.triangles.push_back({p[0], 0u, p[1], NO_EMITTER, p[2], source});
    }
    b.bvh = makeStackBvh(b.tree, b.triangles);
    return b;
}

std::vector<Built> scenes() {
    std::vector<Built> all;
    all.push_back(build(synthetic::randomSoup(3000, 5)));
    all.push_back(build(synthetic::grid(40)));
    all.push_back(build(synthetic::displacedSphere(60, 120)));
    all.push_back(build(synthetic::closedCube(3)));
    return all;
}

Aabb childBox(const StackBvhPair& pair, int side) {
    Aabb box;
    for (int k = 0; k < 3; ++k) {
        box.min[k] = pair.slabs[k][side];
        box.max[k] = pair.slabs[k][2 + side];
    }
    return box;
}

// Walks the tree and the layout together from the root, counting visits of each pair.
class LayoutChecker {
public:
    explicit LayoutChecker(const Built& b) : b_(b), visits_(b.bvh.pairs.size(), 0) {}

    void check(std::uint32_t treeNode, StackBvhChild child) {
        const BvhBuildNode& n = b_.tree.nodes[treeNode];
        ASSERT_EQ(child.isLeaf(), n.isLeaf()) << treeNode;
        if (n.isLeaf()) {
            EXPECT_EQ(child.first, n.firstPrimitive);
            EXPECT_EQ(child.primitiveCount(), n.primitiveCount);
            return;
        }
        ASSERT_LT(child.first, b_.bvh.pairs.size());
        ++visits_[child.first];
        const StackBvhPair& pair = b_.bvh.pairs[child.first];
        for (int side = 0; side < 2; ++side) {
            const std::uint32_t treeChild = side == 0 ? n.leftChild : n.rightChild;
            Aabb box = childBox(pair, side);
            EXPECT_EQ(box.min, b_.tree.nodes[treeChild].bounds.min);
            EXPECT_EQ(box.max, b_.tree.nodes[treeChild].bounds.max);
            check(treeChild, pair.child[side]);
        }
    }

    const std::vector<int>& visits() const { return visits_; }

private:
    const Built& b_;
    std::vector<int> visits_;
};

TEST(StackBvhLayout, IsTheTreeWithEachPairReachedOnce) {
    for (const Built& b : scenes()) {
        ASSERT_FALSE(b.bvh.empty);
        EXPECT_EQ(b.bvh.nodeCount(), b.tree.nodes.size());
        EXPECT_EQ(b.bvh.rootBounds.min, b.tree.nodes[0].bounds.min);
        EXPECT_EQ(b.bvh.rootBounds.max, b.tree.nodes[0].bounds.max);
        LayoutChecker checker(b);
        checker.check(0, b.bvh.root);
        for (int v : checker.visits())
            EXPECT_EQ(v, 1);
    }
}

// Block starts partition the pairs into runs of at most 7 (three levels), each run starting
// where the last one ended: a prefetch of a block reads exactly its own pairs.
TEST(StackBvhLayout, BlocksPartitionThePairsIntoThreeLevelRuns) {
    for (const Built& b : scenes()) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> blocks; // first, pairs
        std::vector<StackBvhChild> pending{b.bvh.root};
        while (!pending.empty()) {
            StackBvhChild c = pending.back();
            pending.pop_back();
            if (c.isLeaf()) continue;
            if (c.blockPairs() > 0) blocks.push_back({c.first, c.blockPairs()});
            for (const StackBvhChild& next : b.bvh.pairs[c.first].child)
                pending.push_back(next);
        }
        std::sort(blocks.begin(), blocks.end());
        std::uint32_t expected = 0;
        for (auto [first, pairs] : blocks) {
            EXPECT_EQ(first, expected);
            EXPECT_GE(pairs, 1u);
            EXPECT_LE(pairs, (1u << kStackBvhBlockLevels) - 1);
            expected = first + pairs;
        }
        EXPECT_EQ(expected, b.bvh.pairs.size());
    }
}

TEST(StackBvhLayout, PairsFillOneCacheLineEachAndPrimitivesAreCopied) {
    Built b = build(synthetic::randomSoup(500, 9));
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(b.bvh.pairs.data()) % 64, 0u);
    ASSERT_EQ(b.bvh.primitives.size(), b.triangles.size());
    for (std::size_t i = 0; i < b.triangles.size(); ++i)
        EXPECT_EQ(b.bvh.primitives[i].sourceIndex, b.triangles[i].sourceIndex);
}

TEST(StackBvhLayout, EmptyAndOneLeafTrees) {
    StackBvh empty = makeStackBvh(buildBvh({}), {});
    EXPECT_TRUE(empty.empty);
    Built one = build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    EXPECT_FALSE(one.bvh.empty);
    EXPECT_TRUE(one.bvh.root.isLeaf());
    EXPECT_EQ(one.bvh.root.primitiveCount(), 1u);
    EXPECT_TRUE(one.bvh.pairs.empty());
}

TEST(StackBvhLayout, RefusesLeavesOfMoreThanFifteenPrimitives) {
    BvhTree tree;
    tree.nodes.resize(1);
    tree.nodes[0].primitiveCount = 16;
    tree.primitiveOrder.resize(16);
    std::vector<gpu::Triangle> triangles(16);
    EXPECT_THROW(makeStackBvh(tree, triangles), InputError);
}

} // namespace
} // namespace vkpt::bvh_stack_layout_test
