// frame.glsl — what every wavefront kernel sees: the render's parameters (buffer frameParams),
// the per-dispatch push constants and its own flat invocation index.
#ifndef VKPT_FRAME_GLSL
#define VKPT_FRAME_GLSL

// Subgroup operations (Vulkan 1.1 basic, ballot and arithmetic; device_list.cpp requires them
// of a device) let a subgroup add to a counter with one atomic instead of one per invocation
// (lib/counters.glsl).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "lib/buffers.glsl"
#include "lib/wavefront.h"

// A uniform block: every invocation reads the same words, which lavapipe then loads once per
// 8 invocations instead of once per invocation. FrameParams has the same offsets under std140
// as under std430 (no arrays, every struct a multiple of 16 bytes).
layout(std140, set = 0, binding = BINDING_FRAME_PARAMS) uniform frameParamsBlock {
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
