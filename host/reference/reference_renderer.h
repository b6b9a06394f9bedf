// reference_renderer.h — vkpt-ref's executor: the integrators over the pixels of a crop, in
// tiles on all cores, with per-pixel adaptive sampling; in rounds of samples, run by the render
// driver (driver/render_driver.h), so that a render stops between two rounds (Ctrl-C,
// SIGTERM, a time limit, a target error) and hands its state to a checkpoint.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "common/render_settings.h"
#include "common/render_stats.h"
#include "driver/render_run.h"
#include "image/render_output.h"
#include "prepare/prepared_scene.h"
#include "reference/scene_intersector.h"
#include "state/sample_plan.h"

namespace vkpt {

// The run's options every executor takes (driver/render_run.h) and the reference's own.
struct ReferenceOptions : RenderRunOptions {
    // The ray queries (each thread makes its own); null: vkpt-ref's ordered stack walk
    // (StackIntersectors).
    const IntersectorFactory* intersectors = nullptr;
};

using ReferenceResult = RenderRunResult;

// Deterministic: the image depends on the seed, not on the thread count, tile order or rounds.
ReferenceResult renderReferenceParts(const PreparedScene& scene, const gpu::Camera& camera,
                                     const RenderSettings& settings, RenderStats& stats,
                                     const ReferenceOptions& options);

// The whole image, samples [0, spp), rays through vkpt-ref's ordered stack walk.
RenderOutput renderReference(const PreparedScene& scene, const gpu::Camera& camera,
                             const RenderSettings& settings, RenderStats& stats);

// The same render with the rays traced by `intersectors` (each thread makes its own).
RenderOutput renderReference(const PreparedScene& scene, const gpu::Camera& camera,
                             const RenderSettings& settings, RenderStats& stats,
                             const IntersectorFactory& intersectors);

// The luminance below which adaptive sampling asks for an absolute error (see adaptive.h).
float adaptiveDarkFloor(float exposure);

} // namespace vkpt
