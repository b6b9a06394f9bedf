// wide_traverse.h — the device's walk of the 8-wide compressed BVH (shared/wide_bvh.h, the
// very code the kernels run) on the CPU: for the traversal tests and the benchmarks.
#pragma once

#include <span>

#include "bvh/bvh_traverse.h"
#include "shared/host_device.h"

namespace vkpt {

// The nodes of flattenWideBvh and the primitives in the order it left the tree's leaves.
// A crossing of an alpha-masked primitive (PRIMITIVE_ALPHA_MASKED) counts only if the ray's
// filter accepts it, as the kernels decide with the material.
ClosestHit closestHitWide(std::span<const gpu::WideBvhNode> nodes,
                          std::span<const gpu::Triangle> primitives, const RayQuery& ray,
                          TraversalCounters* counters = nullptr);
bool anyHitWide(std::span<const gpu::WideBvhNode> nodes, std::span<const gpu::Triangle> primitives,
                const RayQuery& ray, TraversalCounters* counters = nullptr);

// A two-level scene (PreparedScene::nodes, ::triangles and ::instances): node 0 is the top level,
// whose leaves index `instances`. ClosestHit::instance names the instance hit.
ClosestHit closestHitWide(std::span<const gpu::WideBvhNode> nodes,
                          std::span<const gpu::Triangle> primitives,
                          std::span<const gpu::Instance> instances, const RayQuery& ray,
                          TraversalCounters* counters = nullptr);
bool anyHitWide(std::span<const gpu::WideBvhNode> nodes, std::span<const gpu::Triangle> primitives,
                std::span<const gpu::Instance> instances, const RayQuery& ray,
                TraversalCounters* counters = nullptr);

} // namespace vkpt
