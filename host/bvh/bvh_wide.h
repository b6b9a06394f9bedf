// bvh_wide.h — the binned-SAH binary tree collapsed into the device's 8-wide compressed nodes
// (gpu::WideBvhNode, walked by shared/wide_bvh.h).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "bvh/bvh_build.h"
#include "shared/host_device.h"

namespace vkpt {

// A wide node before compression: its box and up to eight children in slot order.
struct WideDraftChild {
    enum class Kind : std::uint8_t { Empty, Internal, Leaf };
    Kind kind = Kind::Empty;
    std::uint32_t binaryNode = 0; // the tree node it stands for
    std::uint32_t wideNode = 0;   // internal children: the wide node made of it
};

struct WideDraftNode {
    std::uint32_t binaryNode = 0; // the tree node whose subtree it covers
    std::uint32_t parent = BVH_END;
    std::array<WideDraftChild, WIDE_BVH_WIDTH> slots{};
};

struct WideDraft {
    std::vector<WideDraftNode> nodes; // nodes[0] is the root; children of a node are contiguous
    std::uint32_t depth = 0;          // levels below the root
};

// How the collapse picks which child to open next while a node has fewer than eight.
enum class CollapseOrder {
    LargestArea, // the child a ray is likeliest to enter: the better tree for traversal
    Tallest,     // the child with the deepest subtree: each level of nodes spans at least three
                 // levels of the binary tree, so a tree of kBvhMaxDepth stays within
                 // WIDE_BVH_MAX_DEPTH
};

// Collapses the binary tree: each wide node opens binary nodes below its own until it has
// eight children or only leaves; the binary leaves become its leaf children, unchanged.
// Slots are chosen per node so that slot s holds the child nearest along the octant s's
// direction (host_device.h). With LargestArea a tree deeper than WIDE_BVH_MAX_DEPTH is
// collapsed again with Tallest, which never is. Subtrees below the top are collapsed on
// threadCount threads (0: one per hardware thread); the result does not depend on it.
WideDraft collapseBvh(const BvhTree& tree, CollapseOrder order = CollapseOrder::LargestArea,
                      std::uint32_t threadCount = 0);

// The device nodes of `tree`. Each wide node's leaf primitives must follow one another in slot
// order, so this renumbers the tree's leaves: tree.primitiveOrder becomes that order and each
// leaf's firstPrimitive its place in it (the tree's shape and boxes do not change, so its own
// walk finds the same crossings, now under the new indices). threadCount 0: one per hardware
// thread; the result does not depend on it.
std::vector<gpu::WideBvhNode> flattenWideBvh(BvhTree& tree,
                                             CollapseOrder order = CollapseOrder::LargestArea,
                                             std::uint32_t threadCount = 0);

// The eight child boxes of a device node as the walk decodes them (origin + q·2^e), empty
// boxes for empty slots; for tests.
std::array<Aabb, WIDE_BVH_WIDTH> decodeChildBoxes(const gpu::WideBvhNode& node);

// Node count, depth and the number of leaf children; for statistics and tests.
struct WideBvhStats {
    std::uint32_t nodeCount = 0;
    std::uint32_t leafCount = 0;
    std::uint32_t depth = 0;
    double childrenPerNode = 0.0; // occupied slots per node, on average
};
WideBvhStats computeWideBvhStats(const std::vector<gpu::WideBvhNode>& nodes);

} // namespace vkpt
