// reference_renderer.h — vkpt-ref's executor: the integrators over all pixels, in tiles on
// all cores, with per-pixel adaptive sampling.
#pragma once

#include "common/render_settings.h"
#include "common/render_stats.h"
#include "image/render_output.h"
#include "prepare/prepared_scene.h"
#include "reference/scene_intersector.h"

namespace vkpt {

// Deterministic: the image depends on the seed, not on the thread count or tile order.
// Rays go through vkpt-ref's ordered stack walk (StackIntersectors).
RenderOutput renderReference(const PreparedScene& scene, const gpu::Camera& camera,
                             const RenderSettings& settings, RenderStats& stats);

// The same render with the rays traced by `intersectors` (each thread makes its own).
RenderOutput renderReference(const PreparedScene& scene, const gpu::Camera& camera,
                             const RenderSettings& settings, RenderStats& stats,
                             const IntersectorFactory& intersectors);

// The luminance below which adaptive sampling asks for an absolute error (see adaptive.h).
float adaptiveDarkFloor(float exposure);

} // namespace vkpt
