// count_loop_iterations.comp — counts how many iterations loops really run. Mesa 22.3's
// lavapipe stops the loops of an invocation once a per-invocation iteration budget is spent
// (see docs/gpu.md); this kernel measures that budget on the device at hand.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "kernel_test_io.h"
#include "lib/buffers.glsl"
#include "shared/host_device.h"

layout(local_size_x = WORKGROUP_SIZE) in;
layout(push_constant) uniform Params {
    LoopParams loops;
}
params;

VKPT_WRITEONLY_BUFFER(0, LoopCounts, loopCounts)

void main() {
    // The bounds come from push constants so no compiler can fold a loop away.
    uint invocation = gl_GlobalInvocationID.x;
    uint firstLoop = params.loops.firstLoopInvocation == ALL_INVOCATIONS ||
                             params.loops.firstLoopInvocation == invocation
                         ? params.loops.firstLoop
                         : 0u;
    uint first = 0u;
    for (uint i = 0u; i < firstLoop; ++i)
        first += 1u;
    uint second = 0u;
    for (uint i = 0u; i < params.loops.secondLoop; ++i)
        second += 1u;
    uint nested = 0u;
    for (uint i = 0u; i < params.loops.outerLoop; ++i) {
        for (uint j = 0u; j < params.loops.innerLoop; ++j)
            nested += 1u;
    }
    loopCounts[invocation] = LoopCounts(first, second, nested, 0u);
}
