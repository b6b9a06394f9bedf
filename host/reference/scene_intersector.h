// scene_intersector.h — the reference's ray queries behind an interface, so that the same
// integrators, sampling and options can run on another traversal: vkpt-ref's own ordered stack
// walk (stack_intersector.h), or Embree in the benchmarks (tests/bench/embree/). One virtual
// call per ray; everything below it (nodes, triangles) is the implementation's, and each asks
// the same AlphaMaskFilter (alpha_mask_filter.h) about cut-outs.
#pragma once

#include <memory>

#include "bvh/bvh_traverse.h"
#include "prepare/prepared_scene.h"

namespace vkpt {

// One thread's queries. Primitives are the prepared scene's, in BVH order (ClosestHit::triangle
// indexes PreparedScene::triangles); t is in units of |direction|, as in RayQuery.
class SceneIntersector {
public:
    virtual ~SceneIntersector() = default;
    // The nearest hit at t in (tMin, VKPT_FAR) that the alpha test accepts.
    virtual ClosestHit closestHit(const glm::vec3& origin, const glm::vec3& direction,
                                  float tMin) = 0;
    // True when something lies at t in (0, tMax) (alpha test included).
    virtual bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) = 0;
    // Traversal work so far; zero where the implementation does not count it (Embree).
    virtual TraversalCounters traversal() const { return {}; }
};

// Shared by the render threads, built once per scene: each thread asks for its own intersector
// (so that counters stay plain integers). makeIntersector is called concurrently.
class IntersectorFactory {
public:
    virtual ~IntersectorFactory() = default;
    virtual std::unique_ptr<SceneIntersector> makeIntersector() const = 0;
};

} // namespace vkpt
