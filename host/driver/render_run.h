// render_run.h — what a render takes and gives, whichever executor runs it (vkpt's wavefront
// renderer, the CPU reference, the Embree baseline): the sample plan and where to resume, the
// AOVs, and how the driver runs the batches — signals, a time limit, an observer after each
// batch, checkpoints. Each executor's options and result extend these.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "common/render_stats.h"
#include "image/render_output.h"
#include "state/render_state.h"
#include "state/sample_plan.h"

namespace vkpt {

using CheckpointWrite =
    std::function<void(const std::vector<PixelRecord>&, const std::vector<FeatureRecord>&)>;

struct RenderRunOptions {
    // Which pixels and samples to render (--crop, --task); unset: every pixel, [0, spp).
    std::optional<SamplePlan> plan;
    // Records of plan.crop (row-major) to continue from (--resume): each pixel goes on from its
    // samplesTaken; converged pixels stay as they are. (vkpt resumes only a state whose
    // unfinished pixels all have the same count: its batches give every active pixel the same.)
    const std::vector<PixelRecord>* resume = nullptr;
    // Record the AOVs (shared/sample_features.h) from each camera sample's first hit, for an
    // output or a saved state that holds them; a render without them pays nothing for them.
    bool aovs = false;
    // With aovs and resume: the resumed pixels' features (plan.crop, row-major); null: none.
    const std::vector<FeatureRecord>* resumeFeatures = nullptr;
    // Set (e.g. by a SIGINT or SIGTERM handler) to stop after the current batch with the image
    // so far.
    const std::atomic<bool>* interrupt = nullptr;
    // Stop at the first batch end at or after this many seconds of rendering (0: no limit).
    // While a limit is set, a batch (after the first) takes no more samples per pixel than the
    // previous batch's rate says fit in the time left, and at least one.
    double timeLimitSeconds = 0.0;
    // Called after every batch; returning true stops the render there (RenderStop::TargetError:
    // --target-error). The figures' renderSeconds and cpuSeconds leave out the time of earlier
    // readbacks and calls (the process's CPU time, all threads: on a CPU device such as
    // lavapipe, the render's cost whatever else loads the machine). With readPixelsAfterPass
    // the output is the image and statistics so far and samplesTaken their Σ; otherwise the
    // output is null and samplesTaken 0.
    std::function<bool(const PassFigures&, const RenderOutput*)> afterPass;
    // Give afterPass the image so far, and grow batches geometrically so that it sees the
    // error at log-spaced sample counts (samplesForGeometricGrowth).
    bool readPixelsAfterPass = false;
    // Called with the records of plan.crop (and their features with aovs, else none) at the
    // first batch end after every checkpointSeconds; batches are cut short so that one ends in
    // time.
    double checkpointSeconds = 0.0;
    CheckpointWrite checkpoint;
};

struct RenderRunResult {
    RenderOutput output;                 // the whole frame; 0 outside the crop
    std::vector<PixelRecord> records;    // the plan's crop, row-major
    std::vector<FeatureRecord> features; // the same pixels' AOVs with options.aovs, else empty
    RenderStats stats;
    std::uint32_t passes = 0; // batches run
    bool interrupted = false;
    RenderStop stop = RenderStop::Budget;
};

} // namespace vkpt
