// wide_traverse.cpp — runs shared/wide_bvh.h's walk over host arrays, deciding alpha-masked
// crossings with the ray's filter where the kernels read the material.
#include "bvh/wide_traverse.h"

#include "shared/wide_bvh.h"

namespace vkpt {

namespace {

gpu::WideWalk walkWide(std::span<const gpu::WideBvhNode> nodes,
                       std::span<const gpu::Triangle> primitives,
                       std::span<const gpu::Instance> instances, const RayQuery& ray,
                       bool stopAtFirst, TraversalCounters* counters) {
    const gpu::WideBvhView bvh{nodes.data(), primitives.data(), true, ray.filter != nullptr,
                               instances.empty() ? nullptr : instances.data()};
    gpu::WideWalk walk =
        gpu::beginWideWalk(ray.origin, ray.direction, ray.tMin, ray.tMax, stopAtFirst, bvh);
    for (;;) {
        gpu::PendingCrossing pending = gpu::continueWideWalk(walk, bvh);
        if (pending.primitive == NO_PRIMITIVE) break;
        if (ray.filter->accepts(pending.primitive, WALK_INSTANCE(walk), ray, pending.hit))
            gpu::takeCrossing(walk, pending.hit, pending.primitive);
    }
    if (counters) {
        counters->nodesVisited += walk.nodesVisited;
        counters->triangleTests += walk.primitiveTests;
    }
    return walk;
}

} // namespace

ClosestHit closestHitWide(std::span<const gpu::WideBvhNode> nodes,
                          std::span<const gpu::Triangle> primitives,
                          std::span<const gpu::Instance> instances, const RayQuery& ray,
                          TraversalCounters* counters) {
    const gpu::WideWalk walk = walkWide(nodes, primitives, instances, ray, false, counters);
    if (walk.primitive == NO_PRIMITIVE) return {};
    return {walk.t, walk.u, walk.v, walk.primitive, true, walk.hitInstance};
}

bool anyHitWide(std::span<const gpu::WideBvhNode> nodes, std::span<const gpu::Triangle> primitives,
                std::span<const gpu::Instance> instances, const RayQuery& ray,
                TraversalCounters* counters) {
    return walkWide(nodes, primitives, instances, ray, true, counters).primitive != NO_PRIMITIVE;
}

ClosestHit closestHitWide(std::span<const gpu::WideBvhNode> nodes,
                          std::span<const gpu::Triangle> primitives, const RayQuery& ray,
                          TraversalCounters* counters) {
    return closestHitWide(nodes, primitives, {}, ray, counters);
}

bool anyHitWide(std::span<const gpu::WideBvhNode> nodes, std::span<const gpu::Triangle> primitives,
                const RayQuery& ray, TraversalCounters* counters) {
    return anyHitWide(nodes, primitives, {}, ray, counters);
}

} // namespace vkpt
