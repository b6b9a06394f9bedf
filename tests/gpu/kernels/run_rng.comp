// run_rng.comp — shared/rng.h and shared/sampler.h on the device, one record per invocation,
// for comparison with C++.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "kernel_test_io.h"
#include "lib/buffers.glsl"
#include "shared/sampler.h"

layout(local_size_x = WORKGROUP_SIZE) in;
layout(push_constant) uniform Params {
    uint count;
}
params;

VKPT_READONLY_BUFFER(0, RngInput, rngInputs)
VKPT_WRITEONLY_BUFFER(1, RngOutput, rngOutputs)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count) return;
    RngInput key = rngInputs[i];
    rngOutputs[i].bits =
        randomBits(key.seed, key.pixel, key.sampleIndex, key.bounce, key.dimension);
    rngOutputs[i].floats =
        randomFloats(key.seed, key.pixel, key.sampleIndex, key.bounce, key.dimension);
    rngOutputs[i].sampled = sampleFloats(key.samplerSetup, key.width, key.seed, key.pixel,
                                         key.sampleIndex, key.bounce, key.dimension);
}
