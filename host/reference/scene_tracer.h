// scene_tracer.h — what the integrators trace through: one thread's SceneIntersector, with
// the rays counted by kind for the statistics. Alpha-masked surfaces let rays through where
// their alpha is below the cutoff, for every kind of ray (the intersector's alpha test); camera
// rays pass the back faces of single-sided opaque materials (shared/camera_culling.h), as the
// device's trace_closest does.
#pragma once

#include <memory>

#include "common/render_stats.h"
#include "prepare/prepared_scene_view.h"
#include "reference/scene_intersector.h"
#include "shared/camera_culling.h"
#include "shared/surface.h"

namespace vkpt {

enum class RayKind { Camera, Extension, Shadow };

// One per thread: the counters are plain integers, merged after the render.
class SceneTracer {
public:
    SceneTracer(const PreparedScene& scene, const IntersectorFactory& intersectors)
        : scene_(scene), view_(makeSceneView(scene)), intersector_(intersectors.makeIntersector()) {
    }

    ClosestHit closest(const glm::vec3& origin, const glm::vec3& direction, RayKind kind) {
        (kind == RayKind::Camera ? rays_.camera : rays_.extension) += 1;
        ClosestHit hit = intersector_->closestHit(origin, direction, 0.0f);
        if (kind != RayKind::Camera) return hit;
        // A culled back face: the same ray again, beyond it (t > its t).
        for (std::uint32_t culled = 0;
             culled < CAMERA_CULLED_FACES_MAX && hit.hit &&
             gpu::hiddenFromCamera(hit.triangle, hit.instance, {hit.t, hit.u, hit.v, true}, origin,
                                   direction, view_);
             ++culled)
            hit = intersector_->closestHit(origin, direction, hit.t);
        return hit;
    }
    // True when something lies strictly between origin and origin + tMax·direction.
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) {
        rays_.shadow += 1;
        return intersector_->occluded(origin, direction, tMax);
    }

    // The surface point of `hit`, found by a ray from `origin` along `direction`.
    gpu::SurfacePoint surfaceAt(const ClosestHit& hit, const glm::vec3& origin,
                                const glm::vec3& direction) const {
        return gpu::makeSurfacePoint(hit.triangle, hit.instance,
                                     gpu::TriangleHit{hit.t, hit.u, hit.v, true}, origin, direction,
                                     view_);
    }

    const PreparedScene& scene() const { return scene_; }
    // The scene as the shared surface, material and light code reads it.
    const gpu::SceneView& view() const { return view_; }
    SceneIntersector& intersector() { return *intersector_; }
    const RayCounts& rays() const { return rays_; }
    TraversalCounters traversal() const { return intersector_->traversal(); }

private:
    const PreparedScene& scene_;
    gpu::SceneView view_;
    std::unique_ptr<SceneIntersector> intersector_;
    RayCounts rays_;
};

} // namespace vkpt
