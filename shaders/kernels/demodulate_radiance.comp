// demodulate_radiance.comp — the denoiser's first stage, one invocation per pixel: the radiance
// divided by the albedo, with the variance of its mean luminance (shared/denoise.h), the iterate
// that filter_radiance then smooths.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/buffers.glsl"
#include "shared/denoise.h"

layout(local_size_x = WORKGROUP_SIZE) in;
layout(push_constant) uniform Params {
    DenoiseParams params;
};

VKPT_READONLY_BUFFER(0, DenoisePixel, denoisePixels)
VKPT_WRITEONLY_BUFFER(1, DenoiseValue, denoiseValuesOut)

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= params.width * params.height) return;
    denoiseValuesOut[index] = demodulatedPixel(denoisePixels[index]);
}
