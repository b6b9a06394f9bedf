// frame.glsl — what every wavefront kernel sees: the render's parameters (buffer frameParams),
// the per-dispatch push constants and its own flat invocation index.
#ifndef VKPT_FRAME_GLSL
#define VKPT_FRAME_GLSL

#include "lib/buffers.glsl"
#include "lib/wavefront.h"

layout(std430, set = 0, binding = BINDING_FRAME_PARAMS) readonly buffer frameParamsBuffer {
    FrameParams frame;
};

layout(push_constant) uniform PassParamsBlock {
    PassParams passParams;
};

// Large dispatches are two-dimensional (at most 65,535 workgroups per axis), rows of
// gl_NumWorkGroups.x workgroups; every kernel bounds-checks the index it gets.
uint flatInvocationIndex() {
    return gl_GlobalInvocationID.x +
           gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x);
}

#endif // VKPT_FRAME_GLSL
