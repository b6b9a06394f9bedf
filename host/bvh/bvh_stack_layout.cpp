// bvh_stack_layout.cpp — copies the tree into sibling pairs, grouped into blocks of
// kStackBvhBlockLevels levels, breadth first inside a block; blocks follow each other depth
// first, so that a subtree's blocks lie together.
#include "bvh/bvh_stack_layout.h"

#include <string>

#include "common/errors.h"

namespace vkpt {

namespace {

// An interior tree node whose StackBvhChild (in its parent's pair, or the root) still needs
// its `first` and `word`.
struct PendingSubtree {
    std::uint32_t treeNode;
    StackBvhChild* child;
};

StackBvhChild leafOrInterior(const BvhBuildNode& n) {
    if (!n.isLeaf()) return {}; // filled in when its pair is placed
    if (n.primitiveCount > StackBvhChild::kCountMask)
        throw InputError("BVH leaf of " + std::to_string(n.primitiveCount) +
                         " primitives; at most 15 are supported");
    return {n.firstPrimitive, n.primitiveCount};
}

StackBvhPair makePair(const BvhBuildNode& left, const BvhBuildNode& right) {
    StackBvhPair pair{};
    for (int k = 0; k < 3; ++k) {
        pair.slabs[k][0] = left.bounds.min[k];
        pair.slabs[k][1] = right.bounds.min[k];
        pair.slabs[k][2] = left.bounds.max[k];
        pair.slabs[k][3] = right.bounds.max[k];
    }
    pair.child[0] = leafOrInterior(left);
    pair.child[1] = leafOrInterior(right);
    return pair;
}

class Layout {
public:
    Layout(const BvhTree& tree, StackBvh& bvh) : tree_(tree), bvh_(bvh) {}

    // Lays out the block whose first pair holds the children of `top`, and queues the blocks
    // below it.
    void block(PendingSubtree top, std::vector<PendingSubtree>& nextBlocks) {
        const auto start = static_cast<std::uint32_t>(bvh_.pairs.size());
        std::vector<PendingSubtree> level{top};
        for (std::uint32_t depth = 0; depth < kStackBvhBlockLevels && !level.empty(); ++depth) {
            std::vector<PendingSubtree> below;
            for (const PendingSubtree& p : level)
                addPair(p, below);
            level = std::move(below);
        }
        top.child->word = (static_cast<std::uint32_t>(bvh_.pairs.size()) - start)
                          << StackBvhChild::kCountBits;
        // Deepest first onto the stack, so that the block holding the left-most subtree
        // comes next in memory.
        nextBlocks.insert(nextBlocks.end(), level.rbegin(), level.rend());
    }

private:
    // The pair of p's children; their interior ones go to `below`.
    void addPair(const PendingSubtree& p, std::vector<PendingSubtree>& below) {
        const BvhBuildNode& n = tree_.nodes[p.treeNode];
        VKPT_ASSERT(bvh_.pairs.size() < bvh_.pairs.capacity(), "pairs must not move");
        p.child->first = static_cast<std::uint32_t>(bvh_.pairs.size());
        bvh_.pairs.push_back(makePair(tree_.nodes[n.leftChild], tree_.nodes[n.rightChild]));
        StackBvhPair& pair = bvh_.pairs.back();
        if (!tree_.nodes[n.leftChild].isLeaf()) below.push_back({n.leftChild, &pair.child[0]});
        if (!tree_.nodes[n.rightChild].isLeaf()) below.push_back({n.rightChild, &pair.child[1]});
    }

    const BvhTree& tree_;
    StackBvh& bvh_;
};

} // namespace

StackBvh makeStackBvh(const BvhTree& tree, std::span<const gpu::Triangle> primitives) {
    VKPT_ASSERT(primitives.size() == tree.primitiveOrder.size(), "one record per primitive");
    StackBvh bvh = makeStackBvhLayout(tree);
    bvh.primitives.assign(primitives.begin(), primitives.end());
    return bvh;
}

StackBvh makeStackBvhLayout(const BvhTree& tree) {
    StackBvh bvh;
    if (tree.nodes.empty() || tree.primitiveOrder.empty()) return bvh;
    bvh.empty = false;
    bvh.rootBounds = tree.nodes[0].bounds;
    bvh.root = leafOrInterior(tree.nodes[0]);
    if (bvh.root.isLeaf()) return bvh;
    bvh.pairs.reserve(tree.nodes.size() / 2); // one pair per interior node: (nodes − 1) / 2
    Layout layout(tree, bvh);
    std::vector<PendingSubtree> blocks{{0, &bvh.root}};
    while (!blocks.empty()) {
        PendingSubtree top = blocks.back();
        blocks.pop_back();
        layout.block(top, blocks);
    }
    return bvh;
}

} // namespace vkpt
