// pass_recorder.cpp — the dispatch order of a pass and the barriers between stages.
#include "render/pass_recorder.h"

#include <algorithm>

#include "gpu/barriers.h"
#include "gpu/buffer.h"

namespace vkpt {

namespace {

// One invocation per item, as rows of at most 65,535 workgroups (flatInvocationIndex()).
WorkgroupCount workgroupsForItems(std::uint32_t items) {
    const std::uint32_t groups = workgroupsFor(items, WORKGROUP_SIZE);
    const std::uint32_t x = std::min(groups, 65535u);
    return {x, x == 0 ? 1u : workgroupsFor(groups, x), 1};
}

} // namespace

PassRecorder::PassRecorder(const WavefrontPipelines& pipelines, const WorkBuffers& buffers,
                           GpuTimer* timer, bool lightSamples)
    : pipelines_(pipelines), buffers_(buffers), timer_(timer), lightSamples_(lightSamples) {}

std::uint32_t PassRecorder::timerCapacity(std::uint32_t bounces) {
    return 2 + 5 * bounces;
}

void PassRecorder::begin(VkCommandBuffer commands) {
    commands_ = commands;
    if (timer_) timer_->recordReset(commands_);
    // Submissions follow one another after a fence wait; the barriers still order this one's
    // accesses after the last one's (the validation layer's synchronization checks ask it).
    recordComputeToComputeBarrier(commands_);
    recordComputeToTransferBarrier(commands_);
}

void PassRecorder::resetActiveList() {
    vkCmdFillBuffer(commands_, buffers_.queueCounters.handle(),
                    COUNTER_ACTIVE_NEXT * sizeof(std::uint32_t), sizeof(std::uint32_t), 0);
    recordTransferToComputeBarrier(commands_);
}

void PassRecorder::dispatch(WavefrontKernel kernel, const gpu::PassParams& params,
                            WorkgroupCount groups) {
    if (timer_) timer_->recordBegin(commands_, kernelName(kernel));
    recordDispatch(commands_, pipelines_.kernel(kernel), pipelines_.set(kernel), groups,
                   pushConstantBytes(params));
    if (timer_) timer_->recordEnd(commands_);
    recordComputeToComputeBarrier(commands_);
}

void PassRecorder::dispatchIndirect(WavefrontKernel kernel, const gpu::PassParams& params,
                                    std::uint32_t argumentWord) {
    if (timer_) timer_->recordBegin(commands_, kernelName(kernel));
    recordDispatchIndirect(commands_, pipelines_.kernel(kernel), pipelines_.set(kernel),
                           buffers_.dispatchArgs, argumentWord * sizeof(std::uint32_t),
                           pushConstantBytes(params));
    if (timer_) timer_->recordEnd(commands_);
    recordComputeToComputeBarrier(commands_);
}

void PassRecorder::generateCameraRays(const gpu::PassParams& params) {
    dispatch(WavefrontKernel::GenerateCameraRays, params,
             workgroupsForItems(params.chunkPixels * params.samplesPerPass));
}

void PassRecorder::traceBounce(const gpu::PassParams& params) {
    dispatch(WavefrontKernel::PrepareDispatches, params, {1, 1, 1});
    dispatchIndirect(WavefrontKernel::TraceClosest, params, DISPATCH_RAYS);
    dispatchIndirect(WavefrontKernel::ShadeHits, params, DISPATCH_RAYS);
    if (!lightSamples_) return;
    dispatchIndirect(WavefrontKernel::TraceShadow, params, DISPATCH_SHADOW);
    dispatchIndirect(WavefrontKernel::AddLightSamples, params, DISPATCH_RAYS);
}

void PassRecorder::accumulate(const gpu::PassParams& params) {
    dispatch(WavefrontKernel::Accumulate, params, workgroupsForItems(params.chunkPixels));
}

void PassRecorder::readBackCounters() {
    recordComputeToTransferBarrier(commands_);
    VkBufferCopy region{0, 0, buffers_.queueCounters.size()};
    vkCmdCopyBuffer(commands_, buffers_.queueCounters.handle(), buffers_.countersReadback.handle(),
                    1, &region);
    recordDeviceToHostBarrier(commands_);
}

} // namespace vkpt
