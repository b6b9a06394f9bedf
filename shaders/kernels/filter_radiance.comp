// filter_radiance.comp — one à-trous iteration of the denoiser, one invocation per pixel
// (shared/denoise_filter.h): reads the iterate, writes the next; the last pass only chooses,
// multiplies the albedo back and writes the denoised radiance (DenoiseValue.chosen).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/buffers.glsl"
#include "shared/denoise.h"

layout(local_size_x = WORKGROUP_SIZE) in;
layout(push_constant) uniform Params {
    DenoiseParams params;
};

VKPT_READONLY_BUFFER(0, DenoisePixel, denoisePixels)
VKPT_READONLY_BUFFER(1, DenoiseValue, denoiseValuesIn)
VKPT_WRITEONLY_BUFFER(2, DenoiseValue, denoiseValuesOut)

#include "shared/denoise_filter.h"

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= params.width * params.height) return;
    uint x = index % params.width;
    uint y = index / params.width;
    DenoiseValue filtered = filterPixel(x, y, params);
    if (params.modulate != 0u)
        filtered.chosen = vec4(modulatedRadiance(denoisePixels[index], filtered), filtered.chosen.w);
    denoiseValuesOut[index] = filtered;
}
