// scene_tracer.h — the reference's ray queries: ordered stack traversal of the BVH tree,
// counting rays by kind and traversal work for the statistics.
#pragma once

#include "bvh/bvh_traverse.h"
#include "common/render_stats.h"
#include "prepare/prepared_scene.h"

namespace vkpt {

enum class RayKind { Camera, Extension, Shadow };

// One per thread: the counters are plain integers, merged after the render.
class SceneTracer {
public:
    explicit SceneTracer(const PreparedScene& scene) : scene_(scene) {}

    ClosestHit closest(const glm::vec3& origin, const glm::vec3& direction, RayKind kind);
    // True when something lies strictly between origin and origin + toTarget.
    bool occluded(const glm::vec3& origin, const glm::vec3& toTarget);

    const PreparedScene& scene() const { return scene_; }
    const RayCounts& rays() const { return rays_; }
    const TraversalCounters& traversal() const { return traversal_; }

private:
    const PreparedScene& scene_;
    RayCounts rays_;
    TraversalCounters traversal_;
};

} // namespace vkpt
