// wavefront.h — vkpt's executor: the wavefront path tracer on a Vulkan compute device. Passes
// of k samples for every active pixel (chunked to the path slots), each pass one command
// buffer of all its bounces, sized on the device by indirect dispatches; the host reads one
// counter block per pass to plan the next. Same integrators, random numbers and decisions as
// the CPU reference, so that at one seed the images agree pixel by pixel up to float rounding.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "common/device_stats.h"
#include "common/render_settings.h"
#include "common/render_stats.h"
#include "image/render_output.h"
#include "prepare/prepared_scene.h"
#include "render/wavefront_kernels.h"
#include "scene/scene_features.h"
#include "state/sample_plan.h"

namespace vkpt {

class GpuContext;

class EarlyPipelines;

struct WavefrontOptions {
    std::uint32_t slotCount = 0; // path slots; 0: chosen from the device (chooseSlotCount)
    bool timeKernels = false;    // per-kernel GPU times from timestamp queries (--stats)
    // Set (e.g. by a SIGINT handler) to stop after the current pass with the image so far.
    const std::atomic<bool>* interrupt = nullptr;
    // Stop at the first pass end at or after this many seconds of rendering (0: no limit).
    // While a limit is set, a pass (after the first) takes no more samples per pixel than the
    // previous pass's rate says fit in the time left, and at least one.
    double timeLimitSeconds = 0.0;
    // Called after every pass; returning true stops the render there (RenderStop::TargetError:
    // vkpt's --target-error). The figures' renderSeconds and cpuSeconds leave out the time of
    // earlier readbacks and calls (the process's CPU time, all threads: on a CPU device such as
    // lavapipe, the render's cost whatever else loads the machine). With readPixelsAfterPass
    // the output is the image and statistics so far (one readback of the pixel states) and
    // samplesTaken their Σ; otherwise the output is null and samplesTaken 0.
    std::function<bool(const PassFigures&, const RenderOutput*)> afterPass;
    // Give afterPass the image so far, and grow passes geometrically so that it sees the error
    // at log-spaced sample counts (samplesForGeometricGrowth).
    bool readPixelsAfterPass = false;
    // The features the kernels are specialised for; unset: the prepared scene's (`features`,
    // all of them after prepareScene(…, {.general = true})). Must include every feature the
    // scene uses (PreparedScene::usedFeatures), or renderWavefront throws InternalError.
    std::optional<SceneFeatures> features;
    // Which pixels and samples to render (--crop, --task); unset: every pixel, [0, spp).
    std::optional<SamplePlan> plan;
    // Records of plan.crop (row-major) to continue from (--resume). The pixels that go on must
    // all have taken the same number of samples (InputError otherwise), as every state a pass
    // or a reference round ends on has.
    const std::vector<PixelRecord>* resume = nullptr;
    // Which kernel builds the pipelines take (render/wavefront_kernels.h): the one for the
    // scene's feature set where there is one, or the full build (images equal bit for bit).
    KernelBuilds kernelBuilds = KernelBuilds::ForFeatureSet;
    // Pipelines already being created while the scene was prepared (early_pipelines.h); taken
    // when they were made for what this render needs, else the render creates its own.
    EarlyPipelines* earlyPipelines = nullptr;
    // Record the AOVs (shared/sample_features.h) from the camera samples' own hits, for an
    // output or a saved state that holds them; a render without them pays nothing for them.
    bool aovs = false;
    // With aovs and resume: the resumed pixels' features (plan.crop, row-major); null: none.
    const std::vector<FeatureRecord>* resumeFeatures = nullptr;
    // Called with the records of plan.crop (and their features with aovs, else none) at the
    // first pass end after every checkpointSeconds; passes are cut short so that one ends in
    // time.
    double checkpointSeconds = 0.0;
    std::function<void(const std::vector<PixelRecord>&, const std::vector<FeatureRecord>&)>
        checkpoint;
    // Called once the working buffers exist, before the scene is uploaded: the last moment to
    // read the host's copy of the scene that renderWavefrontReleasing frees.
    std::function<void()> beforeSceneUpload;
};

struct WavefrontResult {
    RenderOutput output;                 // the whole frame; 0 outside the crop
    std::vector<PixelRecord> records;    // the plan's crop, row-major
    std::vector<FeatureRecord> features; // the same pixels' AOVs with options.aovs, else empty
    RenderStats stats;
    std::vector<KernelTimeTotal> kernelTimes; // empty unless timeKernels
    std::uint64_t truncatedTraversals = 0;    // walks a driver loop limit cut short; must be 0
    std::uint32_t passes = 0;
    std::uint32_t slotCount = 0;
    bool interrupted = false;
    RenderStop stop = RenderStop::Budget;
    // Wall time of creating every kernel's pipeline (vkCreateShaderModule +
    // vkCreateComputePipelines, on several threads), before the first pass: what specialisation
    // costs or saves (lavapipe compiles its LLVM code at the first dispatch, so there it
    // measures the SPIR-V → NIR stage only); each kernel's own time is in pipelineCreations.
    double pipelineCreationSeconds = 0.0;
    std::vector<PipelineCreation> pipelineCreations; // per kernel
    bool pipelinesCreatedEarly = false;              // taken from options.earlyPipelines
    std::vector<SceneBufferBytes> sceneBuffers;      // the scene's buffers, as uploaded
    std::uint64_t sceneBufferBytes = 0;              // Σ sceneBuffers
};

// Deterministic: the image depends on the seed, not on scheduling, slot count or chunking.
// Throws VulkanError when the device cannot hold a buffer (the message names the limit).
WavefrontResult renderWavefront(GpuContext& context, const PreparedScene& scene,
                                const gpu::Camera& camera, const RenderSettings& settings,
                                const WavefrontOptions& options = {});

// The same, freeing each of the scene's device arrays on the host once it is uploaded (its
// features, tree, counts and everything else stay): for a caller that does not read them
// again, so that a large scene is not held twice (vkpt).
WavefrontResult renderWavefrontReleasing(GpuContext& context, PreparedScene& scene,
                                         const gpu::Camera& camera, const RenderSettings& settings,
                                         const WavefrontOptions& options = {});

} // namespace vkpt
