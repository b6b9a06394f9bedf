// bvh_wide_test.cpp — the device's 8-wide compressed BVH: every primitive in one leaf child,
// leaf primitives contiguous per node in slot order, contiguous internal children that know
// their parent, conservative quantised boxes within one grid step of the exact ones (also at
// extreme scales), slots ordered by octant, depth within the walk's bit stack even for the
// deepest binary trees, and the walk's bit stack and slot arithmetic.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/bvh_wide.h"
#include "bvh/synthetic_scenes.h"
#include "shared/wide_bvh.h"

namespace vkpt::bvh_wide_test {
namespace {

using glm::uvec4;

// A node's first texel, as the walk fetches it.
uvec4 uvec4Header(const gpu::WideBvhNode& n) {
    return {n.childBase, n.parent, n.slotsAndExponents, n.primitiveBase};
}

struct WideScene {
    std::vector<Aabb> bounds; // per input primitive
    BvhTree tree;
    std::vector<gpu::WideBvhNode> nodes;
};

WideScene buildWide(const std::vector<glm::vec3>& positions, BvhBuildOptions options = {},
                    CollapseOrder order = CollapseOrder::LargestArea) {
    WideScene s;
    s.bounds = triangleBounds(positions);
    s.tree = buildBvh(s.bounds, options);
    s.nodes = flattenWideBvh(s.tree, order);
    return s;
}

std::vector<WideScene> testScenes() {
    BvhBuildOptions wideLeaves;
    wideLeaves.maxLeafSize = 15;
    wideLeaves.traversalCost = 3.0f;
    std::vector<WideScene> scenes;
    scenes.push_back(buildWide(synthetic::randomSoup(3000, 21)));
    scenes.push_back(buildWide(synthetic::grid(40)));
    scenes.push_back(buildWide(synthetic::closedCube(12)));
    scenes.push_back(buildWide(synthetic::displacedSphere(30, 60), wideLeaves));
    scenes.push_back(buildWide(synthetic::displacedSphere(30, 60), {}, CollapseOrder::Tallest));
    // 40,000 triangles: large enough that subtrees are collapsed as blocks and laid out after
    // the nodes above them.
    scenes.push_back(buildWide(synthetic::displacedSphere(100, 200)));
    return scenes;
}

// Every leaf child of the tree as (node, slot, first primitive, count).
struct LeafChild {
    std::uint32_t node, slot, first, count;
};

std::vector<LeafChild> leafChildren(const std::vector<gpu::WideBvhNode>& nodes) {
    std::vector<LeafChild> leaves;
    for (std::uint32_t n = 0; n < nodes.size(); ++n) {
        for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
            const std::uint32_t count = gpu::wideLeafCount(nodes[n].leafCounts, slot);
            if (count == 0) continue;
            leaves.push_back(
                {n, slot, nodes[n].primitiveBase + gpu::wideLeafOffset(nodes[n].leafCounts, slot),
                 count});
        }
    }
    return leaves;
}

bool isInternal(const gpu::WideBvhNode& node, std::uint32_t slot) {
    return ((gpu::wideInternalSlots(uvec4Header(node)) >> slot) & 1u) != 0;
}

TEST(BvhWide, EveryPrimitiveIsInExactlyOneLeafChild) {
    for (const WideScene& s : testScenes()) {
        std::vector<int> seen(s.tree.primitiveOrder.size(), 0);
        for (const LeafChild& leaf : leafChildren(s.nodes))
            for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i)
                ++seen.at(i);
        EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
        std::vector<std::uint32_t> order = s.tree.primitiveOrder;
        std::sort(order.begin(), order.end());
        std::vector<std::uint32_t> identity(order.size());
        std::iota(identity.begin(), identity.end(), 0u);
        EXPECT_EQ(order, identity) << "primitiveOrder is a permutation of the input";
    }
}

// A node's leaf children hold consecutive primitives from primitiveBase in slot order, and the
// binary tree's leaves were renumbered to the same ranges.
TEST(BvhWide, LeafPrimitivesFollowEachOtherInSlotOrder) {
    for (const WideScene& s : testScenes()) {
        std::uint32_t expected = 0;
        std::uint32_t node = 0;
        for (const LeafChild& leaf : leafChildren(s.nodes)) {
            if (leaf.node != node) {
                node = leaf.node;
                expected = s.nodes[node].primitiveBase;
            }
            EXPECT_EQ(leaf.first, expected) << "node " << leaf.node << " slot " << leaf.slot;
            expected += leaf.count;
        }
        std::vector<std::uint32_t> leafStarts;
        for (const BvhBuildNode& n : s.tree.nodes)
            if (n.isLeaf()) leafStarts.push_back(n.firstPrimitive);
        std::vector<std::uint32_t> childStarts;
        for (const LeafChild& leaf : leafChildren(s.nodes))
            childStarts.push_back(leaf.first);
        std::sort(leafStarts.begin(), leafStarts.end());
        std::sort(childStarts.begin(), childStarts.end());
        EXPECT_EQ(leafStarts, childStarts);
    }
}

TEST(BvhWide, InternalChildrenAreContiguousAndKnowTheirParent) {
    for (const WideScene& s : testScenes()) {
        EXPECT_EQ(s.nodes[0].parent, BVH_END);
        std::vector<int> parents(s.nodes.size(), 0);
        for (std::uint32_t n = 0; n < s.nodes.size(); ++n) {
            const uvec4 header = uvec4Header(s.nodes[n]);
            std::uint32_t rank = 0;
            for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
                if (!isInternal(s.nodes[n], slot)) continue;
                const std::uint32_t child = gpu::wideChildIndex(header, slot);
                EXPECT_EQ(child, s.nodes[n].childBase + rank++);
                ASSERT_LT(child, s.nodes.size());
                EXPECT_EQ(s.nodes[child].parent, n);
                ++parents[child];
                EXPECT_EQ(gpu::wideLeafCount(s.nodes[n].leafCounts, slot), 0u);
            }
        }
        for (std::uint32_t n = 1; n < s.nodes.size(); ++n)
            EXPECT_EQ(parents[n], 1) << "node " << n << " is the child of one node";
        EXPECT_LE(computeWideBvhStats(s.nodes).depth, WIDE_BVH_MAX_DEPTH);
    }
}

bool contains(const Aabb& outer, const Aabb& inner) {
    return glm::all(glm::lessThanEqual(outer.min, inner.min)) &&
           glm::all(glm::greaterThanEqual(outer.max, inner.max));
}

// The exact box of each node's subtree, from the primitives up through the parent links.
std::vector<Aabb> exactNodeBoxes(const WideScene& s) {
    std::vector<Aabb> boxes(s.nodes.size());
    for (const LeafChild& leaf : leafChildren(s.nodes))
        for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i)
            boxes[leaf.node].extend(s.bounds[s.tree.primitiveOrder[i]]);
    for (std::size_t n = s.nodes.size(); n-- > 1;)
        boxes[s.nodes[n].parent].extend(boxes[n]);
    return boxes;
}

// Each decoded child box holds its child exactly, and no side lies more than one grid step
// (2^e of its axis) outside the child's exact box.
TEST(BvhWide, QuantisedChildBoxesAreConservativeAndTight) {
    for (const WideScene& s : testScenes()) {
        const std::vector<Aabb> exact = exactNodeBoxes(s);
        for (std::uint32_t n = 0; n < s.nodes.size(); ++n) {
            const auto decoded = decodeChildBoxes(s.nodes[n]);
            const glm::vec3 step = gpu::wideGridScale(uvec4Header(s.nodes[n]));
            for (const LeafChild& leaf : leafChildren({s.nodes[n]})) {
                Aabb child;
                for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i)
                    child.extend(s.bounds[s.tree.primitiveOrder[i]]);
                EXPECT_TRUE(contains(decoded[leaf.slot], child)) << "node " << n;
                EXPECT_TRUE(glm::all(glm::lessThanEqual(child.min - decoded[leaf.slot].min, step)));
                EXPECT_TRUE(glm::all(glm::lessThanEqual(decoded[leaf.slot].max - child.max, step)));
            }
            for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
                if (!isInternal(s.nodes[n], slot)) continue;
                const std::uint32_t child = gpu::wideChildIndex(uvec4Header(s.nodes[n]), slot);
                EXPECT_TRUE(contains(decoded[slot], exact[child])) << "node " << n;
            }
        }
    }
}

// Boxes a millionth of a unit wide a billion units out, boxes spanning most of the float
// range, and boxes at the smallest normal scales: the decoded boxes still hold them.
TEST(BvhWide, QuantisationHoldsAtExtremeScales) {
    for (float scale : {1e-30f, 1e-6f, 1.0f, 1e9f, 1e30f}) {
        for (float offset : {0.0f, 1e9f, -3e30f}) {
            std::vector<glm::vec3> positions = synthetic::randomSoup(200, 5, 10.0f, 0.5f);
            for (glm::vec3& p : positions)
                p = p * scale + glm::vec3(offset);
            WideScene s = buildWide(positions);
            for (std::uint32_t n = 0; n < s.nodes.size(); ++n) {
                const auto decoded = decodeChildBoxes(s.nodes[n]);
                for (const LeafChild& leaf : leafChildren({s.nodes[n]}))
                    for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i)
                        EXPECT_TRUE(
                            contains(decoded[leaf.slot], s.bounds[s.tree.primitiveOrder[i]]))
                            << "scale " << scale << " offset " << offset;
            }
        }
    }
    std::vector<glm::vec3> huge = {{-3e38f, -3e38f, 0.0f}, {3e38f, -3e38f, 0.0f},
                                   {0.0f, 3e38f, 1e38f},   {1.0f, 1.0f, 1.0f},
                                   {2.0f, 1.0f, 1.0f},     {1.0f, 2.0f, 1.0f}};
    WideScene s = buildWide(huge);
    const auto decoded = decodeChildBoxes(s.nodes[0]);
    for (const LeafChild& leaf : leafChildren({s.nodes[0]}))
        for (std::uint32_t i = leaf.first; i < leaf.first + leaf.count; ++i)
            EXPECT_TRUE(contains(decoded[leaf.slot], s.bounds[s.tree.primitiveOrder[i]]));
}

// Eight clusters at the corners of a cube: the root has them as its eight children, and slot
// s holds the cluster a ray of octant s meets first, the corner opposite its direction.
TEST(BvhWide, SlotsHoldTheNearestChildOfTheirOctant) {
    std::vector<glm::vec3> positions;
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 c((corner & 1) ? 10.0f : -10.0f, (corner & 2) ? 10.0f : -10.0f,
                    (corner & 4) ? 10.0f : -10.0f);
        for (glm::vec3 p : synthetic::randomSoup(20, std::uint32_t(corner), 1.0f, 0.2f))
            positions.push_back(c + p);
    }
    WideScene s = buildWide(positions);
    const auto decoded = decodeChildBoxes(s.nodes[0]);
    for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
        // A ray of octant s travels towards −1 on the axes whose bit is set: it enters the cube
        // at the corner with +10 there and −10 elsewhere.
        const glm::vec3 centre = decoded[slot].centre();
        for (int axis = 0; axis < 3; ++axis) {
            const bool negative = ((slot >> axis) & 1u) != 0;
            EXPECT_EQ(centre[axis] > 0.0f, negative) << "slot " << slot << " axis " << axis;
        }
    }
}

// Triangles at x = 1.1^i make a deep binary tree (46 levels); each wide level opened tallest
// first spans three binary ones.
TEST(BvhWide, OpeningTheTallestChildFirstCutsTheDepthByThree) {
    std::vector<glm::vec3> positions;
    for (int i = 0; i < 900; ++i) {
        float x = std::pow(1.1f, static_cast<float>(i));
        float d = 0.01f * x;
        positions.insert(positions.end(), {{x, 0.0f, 0.0f}, {x + d, 0.0f, 0.0f}, {x, d, 0.0f}});
    }
    WideScene s = buildWide(positions);
    const std::uint32_t binaryDepth = computeBvhStats(s.tree).maxDepth;
    EXPECT_GE(binaryDepth, 40u);
    EXPECT_LE(computeWideBvhStats(s.nodes).depth, WIDE_BVH_MAX_DEPTH);
    EXPECT_LE(collapseBvh(s.tree, CollapseOrder::Tallest).depth, (binaryDepth + 2) / 3);
}

// A tree made by hand to defeat the largest-area collapse: a chain of 80 nodes, each with a
// complete three-level subtree of flat plates beside it that are all larger than the rest of
// the chain, so every wide node spends its eight slots on the plates and the chain advances
// one level per wide level. The collapse notices the 80 levels and opens tallest first.
class ChainOfPlates {
public:
    explicit ChainOfPlates(std::uint32_t length) {
        float side = 1.0f;
        std::vector<std::uint32_t> chain;
        for (std::uint32_t i = 0; i < length; ++i, side *= 0.9f) {
            chain.push_back(addNode());
            const std::uint32_t plates = addSubtree(plate(side), 3);
            tree.nodes[chain.back()].leftChild = plates;
        }
        const std::uint32_t end = addSubtree(plate(side), 1);
        for (std::size_t i = 0; i < chain.size(); ++i)
            tree.nodes[chain[i]].rightChild = i + 1 < chain.size() ? chain[i + 1] : end;
        for (std::size_t i = chain.size(); i-- > 0;) {
            BvhBuildNode& n = tree.nodes[chain[i]];
            n.bounds = tree.nodes[n.leftChild].bounds;
            n.bounds.extend(tree.nodes[n.rightChild].bounds);
        }
    }

    BvhTree tree;

private:
    static Aabb plate(float side) { return {glm::vec3(0.0f), glm::vec3(side, side, 0.0f)}; }

    std::uint32_t addNode() {
        tree.nodes.emplace_back();
        return static_cast<std::uint32_t>(tree.nodes.size() - 1);
    }

    // A complete subtree of `levels` levels whose every node has the plate's box; its leaves
    // hold one primitive each. Parents come before their children, as the builder makes them.
    std::uint32_t addSubtree(const Aabb& box, std::uint32_t levels) {
        const std::uint32_t index = addNode();
        tree.nodes[index].bounds = box;
        if (levels == 0) {
            tree.nodes[index].firstPrimitive =
                static_cast<std::uint32_t>(tree.primitiveOrder.size());
            tree.nodes[index].primitiveCount = 1;
            tree.primitiveOrder.push_back(tree.nodes[index].firstPrimitive);
            return index;
        }
        const std::uint32_t left = addSubtree(box, levels - 1);
        const std::uint32_t right = addSubtree(box, levels - 1);
        tree.nodes[index].leftChild = left;
        tree.nodes[index].rightChild = right;
        return index;
    }
};

TEST(BvhWide, TreesTooDeepForTheBitStackCollapseTallestFirst) {
    ChainOfPlates chain(80);
    const std::uint32_t binaryDepth = computeBvhStats(chain.tree).maxDepth;
    ASSERT_GE(binaryDepth, 80u);
    const WideDraft draft = collapseBvh(chain.tree);
    EXPECT_LE(draft.depth, WIDE_BVH_MAX_DEPTH);
    EXPECT_EQ(draft.depth, collapseBvh(chain.tree, CollapseOrder::Tallest).depth)
        << "the largest-area collapse was kept although it is too deep";
    std::vector<gpu::WideBvhNode> nodes = flattenWideBvh(chain.tree);
    EXPECT_LE(computeWideBvhStats(nodes).depth, WIDE_BVH_MAX_DEPTH);
    EXPECT_EQ(std::size_t(computeWideBvhStats(nodes).leafCount), chain.tree.primitiveOrder.size());
}

bool sameNodes(const std::vector<gpu::WideBvhNode>& a, const std::vector<gpu::WideBvhNode>& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(gpu::WideBvhNode)) == 0;
}

TEST(BvhWide, SameNodesAndPrimitiveOrderForAnyThreadCount) {
    const std::vector<Aabb> bounds = triangleBounds(synthetic::displacedSphere(100, 200));
    const BvhTree built = buildBvh(bounds);
    BvhTree reference = built;
    const std::vector<gpu::WideBvhNode> nodes =
        flattenWideBvh(reference, CollapseOrder::LargestArea, 1);
    for (std::uint32_t threads : {2u, 3u, 8u}) {
        BvhTree tree = built;
        EXPECT_TRUE(sameNodes(flattenWideBvh(tree, CollapseOrder::LargestArea, threads), nodes))
            << threads << " threads";
        EXPECT_EQ(tree.primitiveOrder, reference.primitiveOrder) << threads << " threads";
    }
}

TEST(BvhWide, EmptyAndSingleTriangleTrees) {
    WideScene empty = buildWide({});
    ASSERT_EQ(empty.nodes.size(), 1u);
    EXPECT_EQ(empty.nodes[0].leafCounts, 0u);
    EXPECT_EQ(gpu::wideInternalSlots(uvec4Header(empty.nodes[0])), 0u);
    WideScene one = buildWide({{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
    ASSERT_EQ(one.nodes.size(), 1u);
    ASSERT_EQ(leafChildren(one.nodes).size(), 1u);
    EXPECT_EQ(leafChildren(one.nodes)[0].count, 1u);
}

TEST(WideWalkArithmetic, TheBitStackReturnsMasksInReverseOrder) {
    gpu::WideBitStack stack{uvec4(0u), uvec4(0u)};
    for (std::uint32_t level = 0; level < WIDE_BVH_MAX_DEPTH; ++level)
        gpu::pushMask(stack, (level * 37u + 11u) & 0xffu);
    for (std::uint32_t level = WIDE_BVH_MAX_DEPTH; level-- > 0;)
        EXPECT_EQ(gpu::popMask(stack), (level * 37u + 11u) & 0xffu) << "level " << level;
    EXPECT_EQ(stack.words, uvec4(0u));
    EXPECT_EQ(stack.overflow, uvec4(0u));
}

TEST(WideWalkArithmetic, SlotBitsMoveToSlotXorOctant) {
    for (std::uint32_t octant = 0; octant < 8; ++octant)
        for (std::uint32_t slot = 0; slot < 8; ++slot)
            EXPECT_EQ(gpu::orderSlotBits(1u << slot, octant), 1u << (slot ^ octant));
    for (std::uint32_t mask = 0; mask < 256; ++mask)
        for (std::uint32_t octant = 0; octant < 8; ++octant)
            EXPECT_EQ(gpu::orderSlotBits(gpu::orderSlotBits(mask, octant), octant), mask);
}

TEST(WideWalkArithmetic, LeafOffsetsSumTheLowerSlotsCounts) {
    synthetic::Rng rng(9);
    for (int trial = 0; trial < 1000; ++trial) {
        std::uint32_t counts = 0;
        std::uint32_t naive[8];
        std::uint32_t sum = 0;
        for (std::uint32_t slot = 0; slot < 8; ++slot) {
            const std::uint32_t count = rng.below(16);
            counts |= count << (4 * slot);
            naive[slot] = sum;
            sum += count;
        }
        for (std::uint32_t slot = 0; slot < 8; ++slot) {
            EXPECT_EQ(gpu::wideLeafOffset(counts, slot), naive[slot]);
            EXPECT_EQ(gpu::wideLeafCount(counts, slot), (counts >> (4 * slot)) & 15u);
        }
    }
}

} // namespace
} // namespace vkpt::bvh_wide_test
