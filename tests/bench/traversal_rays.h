// traversal_rays.h — the ray sets traversal_bench traces with every variant: the rays one
// sample per pixel of vkpt-ref's path tracer really traces in the scene, recorded once and
// sorted into closest-hit and any-hit, coherent and incoherent.
#pragma once

#include <string>
#include <vector>

#include "bvh/bvh_traverse.h"
#include "common/render_settings.h"
#include "prepare/prepared_scene.h"

namespace vkpt::bench {

struct RaySet {
    std::string name;
    bool anyHit = false;        // shadow rays: is anything in (tMin, tMax)?
    std::vector<RayQuery> rays; // tMin 0; tMax VKPT_FAR for closest hits, finite for shadow rays
};

// Renders one sample per pixel of `camera` (settings: depth, seed, light samples) with the
// reference's integrator and records each ray it traces:
//   closest, coherent:   camera rays (the jittered pixel sample, from the camera);
//   closest, incoherent: extension rays after each scattering event (BSDF-sampled, bounces
//                        1 .. max depth, Russian roulette from the 3rd);
//   any-hit, coherent:   shadow rays from the camera rays' hits to points on the lights;
//   any-hit, incoherent: shadow rays from the later path vertices.
// Alpha tests are off in the returned sets (RayQuery::filter is null); the bench sets them.
std::vector<RaySet> recordRenderRays(const PreparedScene& scene, const gpu::Camera& camera,
                                     const RenderSettings& settings);

} // namespace vkpt::bench
