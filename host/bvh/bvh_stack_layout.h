// bvh_stack_layout.h — the BVH tree laid out for the CPU reference's ordered stack walk
// (bvh_traverse.h). Same tree, same boxes, same leaves as the BvhTree, arranged for the CPU,
// since at a million triangles the walk is bound by box tests and by waiting for node loads:
//   - an interior node's two children in one 64-byte cache line (a StackBvhPair), their boxes
//     stored slab by slab so that one 4-wide vector operation works on a slab of both boxes
//     (pair_box_test.h); the ordered walk tests both children at every interior node;
//   - pairs grouped in blocks of three levels (up to 7 pairs, 448 bytes, breadth first), so
//     that a walk entering a block can ask for all of its lines at once and wait for one
//     memory latency where descending three levels one load after the other waits for three;
//   - its own copy of the BVH-ordered primitives, and both arrays in huge pages
//     (HugePageAllocator), so that those loads rarely miss the TLB as well.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "bvh/bvh_build.h"
#include "common/huge_page_allocator.h"
#include "shared/host_device.h"

namespace vkpt {

// Where a node's content is. Leaf: `first` primitive and the count (1 .. 15) in the low 4 bits
// of `word`. Interior: `first` is the index of its children's StackBvhPair, the low 4 bits of
// `word` are 0, and above them is the number of pairs of the block that starts at `first` (0
// when `first` lies inside its parent's block).
struct StackBvhChild {
    std::uint32_t first = 0;
    std::uint32_t word = 0;

    bool isLeaf() const { return (word & kCountMask) != 0; }
    std::uint32_t primitiveCount() const { return word & kCountMask; }
    std::uint32_t blockPairs() const { return word >> kCountBits; }

    static constexpr std::uint32_t kCountBits = 4;
    static constexpr std::uint32_t kCountMask = (1u << kCountBits) - 1;
};

// The two children of an interior node: child 0 is the tree's left child. slabs[k] holds
// (min of child 0, min of child 1, max of child 0, max of child 1) along axis k.
struct alignas(64) StackBvhPair {
    float slabs[3][4];
    StackBvhChild child[2];
};
static_assert(sizeof(StackBvhPair) == 64);

// Levels of pairs per block: 3 levels hold up to 1 + 2 + 4 pairs.
inline constexpr std::uint32_t kStackBvhBlockLevels = 3;

struct StackBvh {
    Aabb rootBounds;
    StackBvhChild root;
    std::vector<StackBvhPair, HugePageAllocator<StackBvhPair>> pairs;
    // The primitives in BVH order, as given: leaf ranges and hit indices refer to them (empty for
    // a layout alone, makeStackBvhLayout).
    std::vector<gpu::Triangle, HugePageAllocator<gpu::Triangle>> primitives;
    bool empty = true; // no primitives: every walk finds nothing

    std::size_t nodeCount() const { return 1 + 2 * pairs.size(); }
};

// primitives: in BVH order (tree.primitiveOrder), as PreparedScene::triangles holds them; leaf
// ranges index them as in the tree. Throws InputError for leaves of more than 15 primitives
// (BvhBuildOptions::maxLeafSize allows 15).
StackBvh makeStackBvh(const BvhTree& tree, std::span<const gpu::Triangle> primitives);

// The nodes alone, for a tree whose leaves index something other than primitives (the top level
// of a two-level scene, whose leaves are instances): `primitives` stays empty.
StackBvh makeStackBvhLayout(const BvhTree& tree);

} // namespace vkpt
