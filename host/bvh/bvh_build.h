// bvh_build.h — binned SAH construction of the BVH over triangle bounds, on the CPU.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    void extend(const glm::vec3& p);
    void extend(const Aabb& b);
    bool empty() const;
    float surfaceArea() const;
    glm::vec3 centre() const;
};

// Inline: the build calls these a few hundred million times for a million triangles.
inline void Aabb::extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
}

inline void Aabb::extend(const Aabb& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
}

inline bool Aabb::empty() const {
    return min.x > max.x || min.y > max.y || min.z > max.z;
}

inline float Aabb::surfaceArea() const {
    if (empty()) return 0.0f;
    glm::vec3 d = max - min;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
}

// Halves first, so that boxes near ±FLT_MAX do not overflow.
inline glm::vec3 Aabb::centre() const {
    return 0.5f * min + 0.5f * max;
}

struct BvhBuildOptions {
    std::uint32_t binCount = 16;   // SAH bins per axis
    std::uint32_t maxLeafSize = 4; // a node with more triangles is always split (<= 15)
    float traversalCost = 1.0f;    // SAH cost of visiting a node, relative to one triangle test
    float intersectionCost = 1.0f;
    std::uint32_t threadCount = 0; // 0: one per hardware thread; the tree does not depend on it
};

// SAH splits stop at this depth and object-median splits take over, so that no input (however
// skewed) makes a tree deeper than kBvhMaxDepth: 2^28 triangles need at most 28 median levels.
// Stack traversals size their stacks with kBvhMaxDepth.
inline constexpr std::uint32_t kBvhMaxSahDepth = 64;
inline constexpr std::uint32_t kBvhMaxDepth = kBvhMaxSahDepth + 28;

// A node of the unflattened tree. Interior nodes have two children; leaves own the
// triangles primitiveOrder[firstPrimitive .. firstPrimitive + primitiveCount). Children
// always come after their parent, so leftChild == 0 marks the one empty leaf of an empty tree.
struct BvhBuildNode {
    Aabb bounds;
    std::uint32_t leftChild = 0;
    std::uint32_t rightChild = 0;
    std::uint32_t firstPrimitive = 0;
    std::uint32_t primitiveCount = 0; // 0 for interior nodes

    bool isLeaf() const { return primitiveCount > 0 || leftChild == 0; }
};

struct BvhTree {
    std::vector<BvhBuildNode> nodes;           // nodes[0] is the root
    std::vector<std::uint32_t> primitiveOrder; // leaf order → index of the input primitive
};

struct BvhStats {
    std::uint32_t nodeCount = 0;
    std::uint32_t leafCount = 0;
    std::uint32_t maxDepth = 0; // in edges: a tree that is a single leaf has depth 0
    std::uint32_t maxLeafSize = 0;
    float sahCost = 0.0f; // expected cost per ray, relative to the root's surface area
    double buildSeconds = 0.0;
};

// Builds over the given primitive bounds; an empty input gives a tree with one empty leaf.
// Nodes come in depth-first order (leftChild == index + 1). Throws InputError for more than
// BVH_MAX_TRIANGLES - 1 primitives (the device walk's limit, host_device.h).
BvhTree buildBvh(std::span<const Aabb> primitiveBounds, const BvhBuildOptions& options = {});

// Triangle bounds for buildBvh: positions holds three vertices per triangle.
std::vector<Aabb> triangleBounds(std::span<const glm::vec3> positions);

// Node count, depth, leaf sizes and SAH cost of a built tree (buildSeconds left at 0).
BvhStats computeBvhStats(const BvhTree& tree, const BvhBuildOptions& options = {});

struct TimedBvh {
    BvhTree tree;
    BvhStats stats; // with buildSeconds: the wall time of buildBvh alone
};

TimedBvh buildBvhTimed(std::span<const Aabb> primitiveBounds, const BvhBuildOptions& options = {});

} // namespace vkpt
