// bvh_traverse.h — closest-hit and any-hit queries on the CPU: the reference's ordered stack
// walk of the binary tree, and brute force (the device's walk of the wide nodes on the CPU is
// in wide_traverse.h).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "bvh/bvh_build.h"
#include "bvh/bvh_stack_layout.h"
#include "shared/host_device.h"
#include "shared/intersect.h"

namespace vkpt {

struct RayQuery;

// Decides whether a primitive the ray crosses counts as a hit: alpha-masked surfaces let rays
// through where their alpha is below the cutoff. Without a filter every crossing counts; the
// walks ask it only about primitives marked PRIMITIVE_ALPHA_MASKED (as the device walk does).
class HitFilter {
public:
    virtual ~HitFilter() = default;
    // `instance` places the primitive (NO_INSTANCE: the world's own geometry, or one level).
    virtual bool accepts(std::uint32_t primitive, std::uint32_t instance, const RayQuery& ray,
                         const gpu::TriangleHit& hit) const = 0;
};

// The primitives are triangles and spheres (gpu::isSpherePrimitive); the walks test each with
// its own intersection routine.
struct RayQuery {
    glm::vec3 origin;
    glm::vec3 direction; // need not be unit; t is in units of |direction|
    float tMin = 0.0f;
    float tMax = VKPT_FAR;
    const HitFilter* filter = nullptr;
};

struct ClosestHit {
    float t = 0.0f;
    float u = 0.0f;             // barycentric weight of v1
    float v = 0.0f;             // barycentric weight of v2
    std::uint32_t triangle = 0; // index into the BVH-ordered triangle array
    bool hit = false;
    std::uint32_t instance = NO_INSTANCE; // two-level scenes: the instance whose mesh was hit
};

// Work counters, for the reference's statistics and the traversal tests.
struct TraversalCounters {
    std::uint64_t nodesVisited = 0;
    std::uint64_t triangleTests = 0;
};

// The reference's walk, on the tree and primitives laid out by makeStackBvh.
ClosestHit closestHitStack(const StackBvh& bvh, const RayQuery& ray,
                           TraversalCounters* counters = nullptr);
bool anyHitStack(const StackBvh& bvh, const RayQuery& ray, TraversalCounters* counters = nullptr);

// A two-level scene laid out for the stack walk: the top level, whose leaves index `instances`
// (in the top-level tree's leaf order, as PreparedScene holds them), and each bottom level with
// its primitives; gpu::Instance::mesh names an instance's bottom level. Hits number primitives
// in the scene's one primitive array: a bottom level's own index plus its firstPrimitive.
struct TwoLevelStackBvh {
    StackBvh top;
    std::vector<StackBvh> bottoms;
    std::vector<std::uint32_t> firstPrimitives; // per bottom level
    std::vector<gpu::Instance> instances;
};

// The reference's two-level walk: the ordered stack walk of the top level; at each instance it
// meets, the ray moves into the mesh's space (shared/instance.h, as the device walk does) and the
// bottom level's walk goes on with the same best hit. Ties between instances go to the lower
// instance (instancedCrossingPrecedes).
ClosestHit closestHitTwoLevel(const TwoLevelStackBvh& bvh, const RayQuery& ray,
                              TraversalCounters* counters = nullptr);
bool anyHitTwoLevel(const TwoLevelStackBvh& bvh, const RayQuery& ray,
                    TraversalCounters* counters = nullptr);

// Below, triangles are in BVH order (gpu::Triangle built from primitiveOrder).

ClosestHit closestHitBruteForce(std::span<const gpu::Triangle> triangles, const RayQuery& ray);

} // namespace vkpt
