// scene_tracer.h — the reference's ray queries: ordered stack traversal of the BVH tree,
// counting rays by kind and traversal work for the statistics. Alpha-masked surfaces let
// rays through where their alpha is below the cutoff, for every kind of ray.
#pragma once

#include "bvh/bvh_traverse.h"
#include "common/render_stats.h"
#include "prepare/prepared_scene.h"

namespace vkpt {

enum class RayKind { Camera, Extension, Shadow };

// The alpha MASK test of docs/scene-model.md for candidate hits of the prepared scene.
class AlphaMaskFilter final : public HitFilter {
public:
    explicit AlphaMaskFilter(const PreparedScene& scene) : scene_(scene) {}
    bool accepts(std::uint32_t primitive, const RayQuery& ray,
                 const gpu::TriangleHit& hit) const override;

private:
    const PreparedScene& scene_;
};

// One per thread: the counters are plain integers, merged after the render.
class SceneTracer {
public:
    explicit SceneTracer(const PreparedScene& scene)
        : scene_(scene), alphaMask_(scene),
          filter_(scene.features.alphaMask ? &alphaMask_ : nullptr) {}

    ClosestHit closest(const glm::vec3& origin, const glm::vec3& direction, RayKind kind);
    // True when something lies strictly between origin and origin + tMax·direction.
    bool occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax);

    const PreparedScene& scene() const { return scene_; }
    const RayCounts& rays() const { return rays_; }
    const TraversalCounters& traversal() const { return traversal_; }

private:
    const PreparedScene& scene_;
    AlphaMaskFilter alphaMask_;
    const HitFilter* filter_;
    RayCounts rays_;
    TraversalCounters traversal_;
};

} // namespace vkpt
