// wavefront.h — vkpt's executor: the wavefront path tracer on a Vulkan compute device. Passes
// of k samples for every active pixel (chunked to the path slots), each pass one command
// buffer of all its bounces, sized on the device by indirect dispatches; the host reads one
// counter block per pass to plan the next. Same integrators, random numbers and decisions as
// the CPU reference, so that at one seed the images agree pixel by pixel up to float rounding.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

#include "common/render_settings.h"
#include "common/render_stats.h"
#include "image/render_output.h"
#include "prepare/prepared_scene.h"
#include "render/kernel_times.h"

namespace vkpt {

class GpuContext;

struct WavefrontOptions {
    std::uint32_t slotCount = 0; // path slots; 0: chosen from the device (chooseSlotCount)
    bool timeKernels = false;    // per-kernel GPU times from timestamp queries (--stats)
    // Set (e.g. by a SIGINT handler) to stop after the current pass with the image so far.
    const std::atomic<bool>* interrupt = nullptr;
};

struct WavefrontResult {
    RenderOutput output;
    RenderStats stats;
    std::vector<KernelTimeTotal> kernelTimes; // empty unless timeKernels
    std::uint64_t truncatedTraversals = 0;    // walks a driver loop limit cut short; must be 0
    std::uint32_t passes = 0;
    std::uint32_t slotCount = 0;
    bool interrupted = false;
};

// Deterministic: the image depends on the seed, not on scheduling, slot count or chunking.
// Throws VulkanError when the device cannot hold a buffer (the message names the limit).
WavefrontResult renderWavefront(GpuContext& context, const PreparedScene& scene,
                                const gpu::Camera& camera, const RenderSettings& settings,
                                const WavefrontOptions& options = {});

} // namespace vkpt
