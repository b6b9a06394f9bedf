// prepare_dispatches.comp — one invocation between stages: turns the current queue's ray count
// into the VkDispatchIndirectCommands of this bounce's kernels, empties the queue the bounce
// appends to, and counts the rays by kind. This is what lets a whole pass, every bounce,
// sit in one command buffer with no CPU round trip.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = 1) in;

#include "lib/kernel_bindings.h"

VKPT_DECLARE_BUFFERS(PREPARE_DISPATCHES_BINDINGS)

#include "lib/counters.glsl"

// Workgroups for `invocations`, as rows of at most 65,535 (the smallest
// maxComputeWorkGroupCount Vulkan allows); kernels bounds-check flatInvocationIndex().
void writeWorkgroups(uint offset, uint invocations) {
    uint groups = invocations / WORKGROUP_SIZE + (invocations % WORKGROUP_SIZE != 0u ? 1u : 0u);
    uint x = min(groups, 65535u);
    uint y = x == 0u ? 1u : groups / x + (groups % x != 0u ? 1u : 0u);
    dispatchArgs[offset] = x;
    dispatchArgs[offset + 1u] = y;
    dispatchArgs[offset + 2u] = 1u;
}

void main() {
    uint queueHalf = passParams.bounce & 1u;
    uint rayCount = queueCounters[COUNTER_RAYS + queueHalf];
    writeWorkgroups(DISPATCH_RAYS, rayCount);
    writeWorkgroups(DISPATCH_SHADOW, rayCount * frame.lightSamples);
    queueCounters[COUNTER_RAYS + (queueHalf ^ 1u)] = 0u;
    addToCounter64(passParams.bounce == 0u ? COUNTER_CAMERA_RAYS : COUNTER_EXTENSION_RAYS,
                   rayCount);
}
