// pass_recorder.h — records the dispatches of a pass into a command buffer: generate, then per
// bounce prepare_dispatches → trace_closest → shade_hits → trace_shadow → add_light_samples
// (all but the first indirect, sized on the device), then accumulate; each followed by the
// barrier that makes its writes and counts visible to the next, and timed when asked.
#pragma once

#include <volk.h>

#include <cstdint>

#include "gpu/dispatch.h"
#include "gpu/timestamps.h"
#include "lib/wavefront.h"
#include "render/wavefront_kernels.h"
#include "render/work_buffers.h"

namespace vkpt {

class PassRecorder {
public:
    // timer may be null (no --stats); lightSamples: whether bounces trace light samples.
    PassRecorder(const WavefrontPipelines& pipelines, const WorkBuffers& buffers, GpuTimer* timer,
                 bool lightSamples);

    // Opens a command buffer's recording: orders it after the previous submission's work.
    void begin(VkCommandBuffer commands);
    // Once per pass, before its first chunk: empties the next active list.
    void resetActiveList();
    void generateCameraRays(const gpu::PassParams& params);
    void traceBounce(const gpu::PassParams& params); // params.bounce set
    void accumulate(const gpu::PassParams& params);
    // Copies queueCounters to the host-visible readback buffer (read after the fence).
    void readBackCounters();

    // Intervals the timer may need per submission for `bounces` bounces.
    static std::uint32_t timerCapacity(std::uint32_t bounces);

private:
    void dispatch(WavefrontKernel kernel, const gpu::PassParams& params, WorkgroupCount groups);
    void dispatchIndirect(WavefrontKernel kernel, const gpu::PassParams& params,
                          std::uint32_t argumentWord);

    const WavefrontPipelines& pipelines_;
    const WorkBuffers& buffers_;
    GpuTimer* timer_;
    bool lightSamples_;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
};

} // namespace vkpt
