// wavefront.h — vkpt's executor: the wavefront path tracer on a Vulkan compute device, run by
// the render driver (driver/render_driver.h). Passes of k samples for every active pixel (chunked
// to the path slots), each pass one command buffer of all its bounces, sized on the device by
// indirect dispatches; the host reads one counter block per pass to plan the next. Same
// integrators, random numbers and decisions as the CPU reference, so that at one seed the images
// agree pixel by pixel up to float rounding.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "common/device_stats.h"
#include "common/render_settings.h"
#include "common/render_stats.h"
#include "driver/render_run.h"
#include "image/render_output.h"
#include "prepare/prepared_scene.h"
#include "render/kept_scene.h"
#include "render/wavefront_kernels.h"
#include "scene/scene_features.h"
#include "state/sample_plan.h"

namespace vkpt {

class GpuContext;

class EarlyPipelines;

// The run's options every executor takes (driver/render_run.h) and the device's own.
struct WavefrontOptions : RenderRunOptions {
    std::uint32_t slotCount = 0; // path slots; 0: chosen from the device (chooseSlotCount)
    bool timeKernels = false;    // per-kernel GPU times from timestamp queries (--stats)
    // The features the kernels are specialised for; unset: the prepared scene's (`features`,
    // all of them after prepareScene(…, {.general = true})). Must include every feature the
    // scene uses (PreparedScene::usedFeatures), or renderWavefront throws InternalError.
    std::optional<SceneFeatures> features;
    // Which kernel builds the pipelines take (render/wavefront_kernels.h): the one for the
    // scene's feature set where there is one, folded on the host, or the full build specialised
    // by the driver (images equal bit for bit).
    KernelBuilds kernelBuilds = KernelBuilds::ForFeatureSet;
    // Pipelines already being created while the scene was prepared (early_pipelines.h); taken
    // when they were made for what this render needs, else the render creates its own.
    EarlyPipelines* earlyPipelines = nullptr;
};

// What every executor's run gives and the device's own figures.
struct WavefrontResult : RenderRunResult, DeviceRunFigures {};

// Deterministic: the image depends on the seed, not on scheduling, slot count or chunking.
// Throws VulkanError when the device cannot hold a buffer (the message names the limit).
WavefrontResult renderWavefront(GpuContext& context, const PreparedScene& scene,
                                const gpu::Camera& camera, const RenderSettings& settings,
                                const WavefrontOptions& options = {});

// The same, freeing on the host the scene's binary tree and meshes before the upload and each
// of its device arrays once it is uploaded (its features, counts and everything else stay): for
// a caller that does not read them again, so that a large scene is not held twice (vkpt).
WavefrontResult renderWavefrontReleasing(GpuContext& context, PreparedScene& scene,
                                         const gpu::Camera& camera, const RenderSettings& settings,
                                         const WavefrontOptions& options = {});

// renderWavefrontReleasing for one frame of an animation (docs/scene-model.md, "Frames"): the
// arrays go to the device through `kept`, which holds the frame before's and uploads only what
// changed, and gets this frame's back once it has rendered.
WavefrontResult renderWavefrontKeeping(GpuContext& context, PreparedScene& scene,
                                       const gpu::Camera& camera, const RenderSettings& settings,
                                       const WavefrontOptions& options, KeptDeviceScene& kept);

} // namespace vkpt
