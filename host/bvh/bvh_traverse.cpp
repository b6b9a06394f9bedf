// bvh_traverse.cpp — CPU ray queries: the reference's ordered stack walk of the tree, and brute
// force for the tests.
#include "bvh/bvh_traverse.h"

#include <array>
#include <utility>

#include "common/errors.h"
#include "shared/intersect.h"
#include "shared/sphere.h"

namespace vkpt {

namespace {

// What every walk carries: the ray with its precomputed inverse direction, the best hit so
// far (whose t is the walk's current tMax) and the optional counters.
struct Walk {
    const RayQuery& ray;
    glm::vec3 invDirection;
    gpu::ShearedRay sheared; // the watertight test's per-ray shear, computed once per walk
    ClosestHit best;
    TraversalCounters* counters;

    Walk(const RayQuery& r, TraversalCounters* c)
        : ray(r), invDirection(gpu::safeInverseDirection(r.direction)),
          sheared(gpu::shearRay(r.direction)), counters(c) {
        best.t = r.tMax;
    }

    // Box entry distance, or VKPT_FAR when the box is missed or lies beyond the best hit.
    float enterBox(const glm::vec3& boxMin, const glm::vec3& boxMax) {
        if (counters) ++counters->nodesVisited;
        return gpu::intersectBox(ray.origin, invDirection, boxMin, boxMax, ray.tMin, best.t);
    }

    // Tests one primitive against (tMin, best t], before the first hit (tMin, tMax); a hit the
    // filter accepts becomes the best if it precedes it (intersect.h, crossingPrecedes).
    bool testTriangle(std::span<const gpu::Triangle> triangles, std::uint32_t index) {
        if (counters) ++counters->triangleTests;
        const gpu::Triangle& tri = triangles[index];
        const float tMax = best.hit ? gpu::nextFloatUp(best.t) : best.t;
        gpu::TriangleHit h =
            gpu::isSpherePrimitive(tri)
                ? gpu::intersectSphere(ray.origin, ray.direction, tri.v0, tri.v1.x, ray.tMin, tMax)
                : gpu::intersectTriangleWatertight(ray.origin, sheared, tri.v0, tri.v1, tri.v2,
                                                   ray.tMin, tMax);
        if (!h.hit) return false;
        if (!gpu::crossingPrecedes(h.t, index, best.t, best.hit ? best.triangle : NO_PRIMITIVE))
            return false;
        if (ray.filter != nullptr && !ray.filter->accepts(index, ray, h)) return false;
        best = {h.t, h.u, h.v, index, true};
        return true;
    }

    // Tests count triangles from first; with stopAtFirst, returns at the first hit.
    bool testTriangles(std::span<const gpu::Triangle> triangles, std::uint32_t first,
                       std::uint32_t count, bool stopAtFirst) {
        bool any = false;
        for (std::uint32_t i = first; i < first + count; ++i) {
            any = testTriangle(triangles, i) || any;
            if (any && stopAtFirst) return true;
        }
        return any;
    }
};

ClosestHit finish(const Walk& walk) {
    return walk.best.hit ? walk.best : ClosestHit{};
}

// intersectBox widens a box's exit by this factor (Ize 2013); a box entered up to the best t
// times it may hold a crossing at that t.
constexpr float kBoxExitMargin = 1.0000004f;

struct StackEntry {
    std::uint32_t node;
    float entry; // box entry distance when pushed
};

// A stack as deep as the deepest tree the builder makes (kBvhMaxDepth): a walk holds at most
// one pending sibling per level.
struct NodeStack {
    std::array<StackEntry, kBvhMaxDepth + 1> entries;
    std::uint32_t size = 0;

    void push(std::uint32_t node, float entry) {
        VKPT_ASSERT(size < entries.size(), "tree deeper than kBvhMaxDepth");
        entries[size++] = {node, entry};
    }
    StackEntry pop() { return entries[--size]; }
    bool empty() const { return size == 0; }
};

// Pushes the children of an interior node whose boxes the ray enters, the nearer last so that
// it is popped first (front-to-back order, as in pbrt-v4's BVHAggregate::Intersect, which
// uses the ray's direction sign instead of the entry distances).
void pushChildren(const BvhTree& tree, const BvhBuildNode& n, Walk& walk, NodeStack& stack) {
    const BvhBuildNode& left = tree.nodes[n.leftChild];
    const BvhBuildNode& right = tree.nodes[n.rightChild];
    StackEntry near{n.leftChild, walk.enterBox(left.bounds.min, left.bounds.max)};
    StackEntry far{n.rightChild, walk.enterBox(right.bounds.min, right.bounds.max)};
    if (far.entry < near.entry) std::swap(near, far);
    if (far.entry != VKPT_FAR) stack.push(far.node, far.entry);
    if (near.entry != VKPT_FAR) stack.push(near.node, near.entry);
}

// The ordered walk; with stopAtFirst it becomes the any-hit query.
bool walkStack(const BvhTree& tree, std::span<const gpu::Triangle> triangles, Walk& walk,
               bool stopAtFirst) {
    if (tree.nodes.empty()) return false;
    const BvhBuildNode& root = tree.nodes[0];
    float rootEntry = walk.enterBox(root.bounds.min, root.bounds.max);
    NodeStack stack;
    if (rootEntry != VKPT_FAR) stack.push(0, rootEntry);
    bool any = false;
    while (!stack.empty()) {
        StackEntry e = stack.pop();
        // A nearer hit was found since the push. Boxes entered up to the best t (with intersectBox's
        // margin) may still hold a crossing that ties with it and precedes it.
        if (e.entry > walk.best.t * kBoxExitMargin) continue;
        const BvhBuildNode& n = tree.nodes[e.node];
        if (!n.isLeaf()) {
            pushChildren(tree, n, walk, stack);
            continue;
        }
        any = walk.testTriangles(triangles, n.firstPrimitive, n.primitiveCount, stopAtFirst) || any;
        if (any && stopAtFirst) return true;
    }
    return any;
}

} // namespace

ClosestHit closestHitStack(const BvhTree& tree, std::span<const gpu::Triangle> triangles,
                           const RayQuery& ray, TraversalCounters* counters) {
    Walk walk(ray, counters);
    walkStack(tree, triangles, walk, false);
    return finish(walk);
}

bool anyHitStack(const BvhTree& tree, std::span<const gpu::Triangle> triangles, const RayQuery& ray,
                 TraversalCounters* counters) {
    Walk walk(ray, counters);
    return walkStack(tree, triangles, walk, true);
}

ClosestHit closestHitBruteForce(std::span<const gpu::Triangle> triangles, const RayQuery& ray) {
    Walk walk(ray, nullptr);
    walk.testTriangles(triangles, 0, static_cast<std::uint32_t>(triangles.size()), false);
    return finish(walk);
}

} // namespace vkpt
