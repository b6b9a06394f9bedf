// alpha_mask_filter.h — the alpha MASK test of docs/scene-model.md for candidate hits of the
// prepared scene. Every intersector asks it, so that cut-outs are the same whatever walks the
// scene; the test itself is the kernels' (shaders/shared/materials.h, isCutOut).
#pragma once

#include "bvh/bvh_traverse.h"
#include "prepare/prepared_scene_view.h"

namespace vkpt {

class AlphaMaskFilter final : public HitFilter {
public:
    explicit AlphaMaskFilter(const PreparedScene& scene) : view_(makeSceneView(scene)) {}
    bool accepts(std::uint32_t primitive, std::uint32_t instance, const RayQuery& ray,
                 const gpu::TriangleHit& hit) const override;

private:
    gpu::SceneView view_;
};

} // namespace vkpt
