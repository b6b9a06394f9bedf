// reference_renderer.h — vkpt-ref's executor: the integrators over the pixels of a crop, in
// tiles on all cores, with per-pixel adaptive sampling; in rounds of samples, so that a render
// can stop between two rounds (Ctrl-C, SIGTERM) and hand its state to a checkpoint.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "common/render_settings.h"
#include "common/render_stats.h"
#include "image/render_output.h"
#include "prepare/prepared_scene.h"
#include "reference/scene_intersector.h"
#include "state/sample_plan.h"

namespace vkpt {

struct ReferenceOptions {
    // The ray queries (each thread makes its own); null: vkpt-ref's ordered stack walk
    // (StackIntersectors).
    const IntersectorFactory* intersectors = nullptr;
    std::optional<SamplePlan> plan; // unset: every pixel, samples [0, spp)
    // Records of plan.crop (row-major) to continue from (--resume): each pixel goes on from
    // its samplesTaken; converged pixels stay as they are.
    const std::vector<PixelRecord>* resume = nullptr;
    // Record the AOVs (shared/sample_features.h) from each camera sample's first hit, in the
    // integrators' own loop, for an output or a saved state that holds them.
    bool aovs = false;
    // With aovs and resume: the resumed pixels' features (plan.crop, row-major); null: none.
    const std::vector<FeatureRecord>* resumeFeatures = nullptr;
    // Set (e.g. by a SIGINT or SIGTERM handler) to stop at the end of the current round.
    const std::atomic<bool>* interrupt = nullptr;
    // Called with the records of plan.crop (and their features with aovs, else none) at the
    // first round end after every checkpointSeconds; rounds are cut short so that one ends in
    // time.
    double checkpointSeconds = 0.0;
    std::function<void(const std::vector<PixelRecord>&, const std::vector<FeatureRecord>&)>
        checkpoint;
};

struct ReferenceResult {
    RenderOutput output;                 // the whole frame; 0 outside the crop
    std::vector<PixelRecord> records;    // plan.crop, row-major
    std::vector<FeatureRecord> features; // the same pixels' AOVs with options.aovs, else empty
    bool interrupted = false;
};

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
