// alpha_mask_filter.h — the alpha MASK test of docs/scene-model.md for candidate hits of the
// prepared scene. Every intersector asks it, so that cut-outs are the same whatever walks the
// scene.
#pragma once

#include "bvh/bvh_traverse.h"
#include "prepare/prepared_scene.h"

namespace vkpt {

class AlphaMaskFilter final : public HitFilter {
public:
    explicit AlphaMaskFilter(const PreparedScene& scene) : scene_(scene) {}
    bool accepts(std::uint32_t primitive, const RayQuery& ray,
                 const gpu::TriangleHit& hit) const override;

private:
    const PreparedScene& scene_;
};

} // namespace vkpt
