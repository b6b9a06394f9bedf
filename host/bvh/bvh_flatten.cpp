// bvh_flatten.cpp — lays the built tree out depth first with skip links, the node array the
// GPU walks without a stack.
#include "bvh/bvh_flatten.h"

#include "common/errors.h"

namespace vkpt {

namespace {

struct ChildPair {
    std::uint32_t first;
    std::uint32_t second;
};

// Left first, unless a direction is given and the right child's centre lies nearer along it.
// Centres stand in for the split plane, which the tree does not keep: for the two sides of a
// split they say which side a ray travelling along the direction reaches first.
ChildPair orderChildren(const BvhTree& tree, const BvhBuildNode& n, const FlattenOptions& options) {
    if (!options.nearFirstDirection) return {n.leftChild, n.rightChild};
    glm::vec3 gap =
        tree.nodes[n.rightChild].bounds.centre() - tree.nodes[n.leftChild].bounds.centre();
    bool rightNearer = glm::dot(gap, *options.nearFirstDirection) < 0.0f;
    return rightNearer ? ChildPair{n.rightChild, n.leftChild}
                       : ChildPair{n.leftChild, n.rightChild};
}

// The tree's nodes in depth-first preorder (first child's subtree before the second's),
// whatever order the tree stores them in.
std::vector<std::uint32_t> preorder(const BvhTree& tree, const FlattenOptions& options) {
    std::vector<std::uint32_t> order;
    order.reserve(tree.nodes.size());
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        std::uint32_t node = stack.back();
        stack.pop_back();
        order.push_back(node);
        const BvhBuildNode& n = tree.nodes[node];
        if (n.isLeaf()) continue;
        ChildPair children = orderChildren(tree, n, options);
        stack.push_back(children.second);
        stack.push_back(children.first);
    }
    return order;
}

// Node count of each subtree, indexed by tree node; children follow parents in preorder, so
// the reverse order sees every child before its parent.
std::vector<std::uint32_t> subtreeSizes(const BvhTree& tree,
                                        const std::vector<std::uint32_t>& order) {
    std::vector<std::uint32_t> sizes(tree.nodes.size(), 1);
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
        const BvhBuildNode& n = tree.nodes[*it];
        if (!n.isLeaf()) sizes[*it] = 1 + sizes[n.leftChild] + sizes[n.rightChild];
    }
    return sizes;
}

std::uint32_t packLeaf(const BvhBuildNode& n) {
    if (n.primitiveCount == 0) return kEmptyLeafTriangles;
    VKPT_ASSERT(n.primitiveCount <= BVH_MAX_LEAF_TRIANGLES, "leaf fits the packed count");
    VKPT_ASSERT(n.firstPrimitive < BVH_MAX_TRIANGLES, "leaf start fits the packed word");
    return gpu::packLeafTriangles(n.firstPrimitive, n.primitiveCount);
}

// An empty tree's only box stays finite on the GPU: a point at the origin.
gpu::BvhNode makeFlatNode(const BvhBuildNode& n, std::uint32_t missIndex) {
    gpu::BvhNode flat{};
    flat.boundsMin = n.bounds.empty() ? glm::vec3(0.0f) : n.bounds.min;
    flat.boundsMax = n.bounds.empty() ? glm::vec3(0.0f) : n.bounds.max;
    flat.missIndex = missIndex;
    flat.leafTriangles = n.isLeaf() ? packLeaf(n) : 0u;
    return flat;
}

} // namespace

// In preorder, a subtree occupies [index, index + size): its first child is index + 1, the
// second follows the first's subtree, and the node after the subtree is where a miss (or a
// finished leaf) continues.
std::vector<gpu::BvhNode> flattenBvh(const BvhTree& tree, const FlattenOptions& options) {
    VKPT_ASSERT(!tree.nodes.empty(), "a built tree has a root");
    std::vector<std::uint32_t> order = preorder(tree, options);
    std::vector<std::uint32_t> sizes = subtreeSizes(tree, order);
    auto total = static_cast<std::uint32_t>(order.size());
    std::vector<gpu::BvhNode> nodes;
    nodes.reserve(total);
    for (std::uint32_t index = 0; index < total; ++index) {
        std::uint32_t next = index + sizes[order[index]];
        nodes.push_back(makeFlatNode(tree.nodes[order[index]], next == total ? BVH_END : next));
    }
    return nodes;
}

} // namespace vkpt
