// write_indices.comp — values[i] = i * SCALE + params.offset: exercises push constants,
// specialisation constants and indirect dispatch in the host layer's own tests.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/buffers.glsl"
#include "shared/host_device.h"

layout(local_size_x = WORKGROUP_SIZE) in;
layout(constant_id = 0) const uint SCALE = 1u;
layout(push_constant) uniform Params {
    uint offset;
}
params;

VKPT_BUFFER(0, uint, values)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(values.length())) return;
    values[i] = i * SCALE + params.offset;
}
