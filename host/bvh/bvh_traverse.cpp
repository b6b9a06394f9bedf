// bvh_traverse.cpp — CPU ray queries: the reference's ordered stack walk of the tree, and brute
// force for the tests.
#include "bvh/bvh_traverse.h"

#include <array>
#include <utility>

#include "bvh/pair_box_test.h"
#include "bvh/ray_triangle_test.h"
#include "common/errors.h"
#include "shared/instance.h"
#include "shared/intersect.h"
#include "shared/sphere.h"

namespace vkpt {

namespace {

// What every walk carries: the ray with its inverse direction and triangle test data, the best hit
// so far (whose t is the walk's current tMax) and its work, counted in locals and added to the
// caller's counters once, at the end.
struct Walk {
    const RayQuery& ray;
    glm::vec3 invDirection;
    RayTriangleTest triangleTest;
    ClosestHit best;
    std::uint64_t boxTests = 0;
    std::uint64_t primitiveTests = 0;
    TraversalCounters* counters;
    // A bottom level of a two-level scene: the instance walked and where its primitives start in
    // the scene's array (hits and the filter take that numbering).
    std::uint32_t instance = NO_INSTANCE;
    std::uint32_t firstPrimitive = 0;

    Walk(const RayQuery& r, TraversalCounters* c)
        : ray(r), invDirection(gpu::safeInverseDirection(r.direction)),
          triangleTest(r.origin, r.direction), counters(c) {
        best.t = r.tMax;
    }
    ~Walk() {
        if (counters == nullptr) return;
        counters->nodesVisited += boxTests;
        counters->triangleTests += primitiveTests;
    }
    Walk(const Walk&) = delete;
    Walk& operator=(const Walk&) = delete;

    // Box entry distance, or VKPT_FAR when the box is missed or lies beyond the best hit.
    float enterBox(const glm::vec3& boxMin, const glm::vec3& boxMax) {
        ++boxTests;
        return gpu::intersectBox(ray.origin, invDirection, boxMin, boxMax, ray.tMin, best.t);
    }

    // Tests one primitive against (tMin, best t], before the first hit (tMin, tMax); a hit
    // becomes the best if it precedes it (intersect.h, crossingPrecedes) and unless the
    // primitive is alpha-masked and the filter rejects it.
    bool testTriangle(std::span<const gpu::Triangle> triangles, std::uint32_t index) {
        ++primitiveTests;
        const gpu::Triangle& tri = triangles[index];
        const float tMax = best.hit ? gpu::nextFloatUp(best.t) : best.t;
        gpu::TriangleHit h =
            gpu::isSpherePrimitive(tri)
                ? gpu::intersectSphere(ray.origin, ray.direction, tri.v0, tri.v1.x, ray.tMin, tMax)
                : triangleTest.intersect(tri.v0, tri.v1, tri.v2, ray.tMin, tMax);
        if (!h.hit) return false;
        const std::uint32_t primitive = firstPrimitive + index;
        if (!gpu::instancedCrossingPrecedes(h.t, instance, primitive, best.t, best.instance,
                                            best.hit ? best.triangle : NO_PRIMITIVE))
            return false;
        if (ray.filter != nullptr && gpu::isAlphaMaskedPrimitive(tri) &&
            !ray.filter->accepts(primitive, instance, ray, h))
            return false;
        best = {h.t, h.u, h.v, primitive, true, instance};
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

// Whether a box entered at `entry` may still hold the best crossing: it may tie with the best
// t and precede it by primitive index (crossingPrecedes).
bool mayHoldBest(float entry, const Walk& walk) {
    return entry != VKPT_FAR && !(entry > walk.best.t * kBoxExitMargin);
}

// A far child waiting on the stack, with its box entry distance when it was pushed.
struct StackEntry {
    StackBvhChild node;
    float entry;
};

// A stack as deep as the deepest tree the builder makes (kBvhMaxDepth): a walk holds at most
// one pending sibling per level.
struct NodeStack {
    std::array<StackEntry, kBvhMaxDepth + 1> entries;
    std::uint32_t size = 0;

    void push(const StackEntry& entry) {
        VKPT_ASSERT(size < entries.size(), "tree deeper than kBvhMaxDepth");
        entries[size++] = entry;
    }
    // The next entry whose box may still hold the best crossing; false when none is left (an
    // entry whose box now lies behind a nearer hit found since the push is dropped).
    bool popUseful(const Walk& walk, StackEntry& next) {
        while (size > 0) {
            next = entries[--size];
            if (mayHoldBest(next.entry, walk)) return true;
        }
        return false;
    }
};

// Memory-level parallelism for the walk (see bvh_stack_layout.h): a node that starts a block
// asks for all of the block's lines before its first pair is read, and a leaf put on the stack
// asks for its primitives before the walk comes back to it.
void prefetchBlock(const StackBvh& bvh, StackBvhChild node) {
    const StackBvhPair* first = &bvh.pairs[node.first];
    for (std::uint32_t i = 0; i < node.blockPairs(); ++i)
        __builtin_prefetch(first + i);
}

void prefetchLeaf(const StackBvh& bvh, StackBvhChild leaf) {
    if (bvh.primitives.empty()) return; // a top level: its leaves are instances
    const char* begin = reinterpret_cast<const char*>(&bvh.primitives[leaf.first]);
    const char* end = begin + leaf.primitiveCount() * sizeof(gpu::Triangle);
    for (const char* line = begin; line < end; line += 64)
        __builtin_prefetch(line);
}

// The ordered walk; with stopAtFirst it becomes the any-hit query. At an interior node both
// children's boxes are tested (one cache line, one vector test); the walk goes on into the
// nearer and pushes the farther with its entry distance, which is checked against the best hit
// again when it is popped (mayHoldBest). The nearer is the one with the smaller entry, the left
// one on a tie.
// This is pbrt-v4's front-to-back BVHAggregate::Intersect, ordered by entry distance where pbrt
// uses the ray's direction sign on the split axis.
// testLeaf(first, count) tests a leaf's primitives and says whether it found a hit.
template <typename TestLeaf>
bool walkStack(const StackBvh& bvh, Walk& walk, bool stopAtFirst, TestLeaf testLeaf) {
    if (bvh.empty) return false;
    if (!mayHoldBest(walk.enterBox(bvh.rootBounds.min, bvh.rootBounds.max), walk)) return false;
    const PairBoxTest pairTest(walk.ray.origin, walk.ray.direction);
    NodeStack stack;
    StackBvhChild node = bvh.root;
    bool any = false;
    for (;;) {
        if (node.isLeaf()) {
            any = testLeaf(node.first, node.primitiveCount()) || any;
            if (any && stopAtFirst) return true;
        } else {
            prefetchBlock(bvh, node);
            const StackBvhPair& pair = bvh.pairs[node.first];
            walk.boxTests += 2;
            PairBoxTest::Entries e = pairTest.enter(pair, walk.ray.tMin, walk.best.t);
            StackEntry near{pair.child[0], e.child[0]};
            StackEntry far{pair.child[1], e.child[1]};
            if (far.entry < near.entry) std::swap(near, far);
            if (far.entry != VKPT_FAR) {
                if (far.node.isLeaf()) prefetchLeaf(bvh, far.node);
                stack.push(far);
            }
            if (mayHoldBest(near.entry, walk)) {
                node = near.node;
                continue;
            }
        }
        StackEntry next;
        if (!stack.popUseful(walk, next)) return any;
        node = next.node;
    }
}

bool walkStack(const StackBvh& bvh, Walk& walk, bool stopAtFirst) {
    const std::span<const gpu::Triangle> triangles(bvh.primitives);
    return walkStack(bvh, walk, stopAtFirst, [&](std::uint32_t first, std::uint32_t count) {
        return walk.testTriangles(triangles, first, count, stopAtFirst);
    });
}

// The instances of a top-level leaf: each one's bottom level walked with the ray in its space,
// from the best hit so far.
bool walkInstances(const TwoLevelStackBvh& bvh, Walk& top, std::uint32_t first, std::uint32_t count,
                   bool stopAtFirst) {
    bool any = false;
    for (std::uint32_t i = first; i < first + count; ++i) {
        const gpu::Instance& x = bvh.instances[i];
        const RayQuery local{gpu::instanceRayOrigin(x, top.ray.origin),
                             gpu::instanceRayDirection(x, top.ray.direction), top.ray.tMin,
                             top.ray.tMax, top.ray.filter};
        Walk inner(local, top.counters);
        inner.best = top.best;
        inner.instance = i;
        inner.firstPrimitive = bvh.firstPrimitives[x.mesh];
        any = walkStack(bvh.bottoms[x.mesh], inner, stopAtFirst) || any;
        top.best = inner.best;
        if (any && stopAtFirst) return true;
    }
    return any;
}

bool walkTwoLevel(const TwoLevelStackBvh& bvh, Walk& walk, bool stopAtFirst) {
    return walkStack(bvh.top, walk, stopAtFirst, [&](std::uint32_t first, std::uint32_t count) {
        return walkInstances(bvh, walk, first, count, stopAtFirst);
    });
}

} // namespace

ClosestHit closestHitStack(const StackBvh& bvh, const RayQuery& ray, TraversalCounters* counters) {
    Walk walk(ray, counters);
    walkStack(bvh, walk, false);
    return finish(walk);
}

bool anyHitStack(const StackBvh& bvh, const RayQuery& ray, TraversalCounters* counters) {
    Walk walk(ray, counters);
    return walkStack(bvh, walk, true);
}

ClosestHit closestHitTwoLevel(const TwoLevelStackBvh& bvh, const RayQuery& ray,
                              TraversalCounters* counters) {
    Walk walk(ray, counters);
    walkTwoLevel(bvh, walk, false);
    return finish(walk);
}

bool anyHitTwoLevel(const TwoLevelStackBvh& bvh, const RayQuery& ray, TraversalCounters* counters) {
    Walk walk(ray, counters);
    return walkTwoLevel(bvh, walk, true);
}

// With intersect.h's own tests rather than the walk's per-ray versions (pair_box_test.h,
// ray_triangle_test.h), so that comparing the walk with brute force also checks those against
// the shared functions. In index order, with t exclusive, the first crossing found at a t is
// the one of lowest index, as crossingPrecedes asks.
ClosestHit closestHitBruteForce(std::span<const gpu::Triangle> triangles, const RayQuery& ray) {
    ClosestHit best;
    best.t = ray.tMax;
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
        const gpu::Triangle& tri = triangles[i];
        gpu::TriangleHit h = gpu::isSpherePrimitive(tri)
                                 ? gpu::intersectSphere(ray.origin, ray.direction, tri.v0, tri.v1.x,
                                                        ray.tMin, best.t)
                                 : gpu::intersectTriangle(ray.origin, ray.direction, tri.v0, tri.v1,
                                                          tri.v2, ray.tMin, best.t);
        if (!h.hit) continue;
        if (ray.filter != nullptr && gpu::isAlphaMaskedPrimitive(tri) &&
            !ray.filter->accepts(i, NO_INSTANCE, ray, h))
            continue;
        best = {h.t, h.u, h.v, i, true};
    }
    return best.hit ? best : ClosestHit{};
}

} // namespace vkpt
