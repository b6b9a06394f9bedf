// denoise_filter.h — the denoiser's à-trous iteration (shared/denoise.h), which reads the
// pixels around the one it writes: in a kernel from the buffers denoisePixels and
// denoiseValuesIn, which the kernel declares before it includes this file; in C++ from the
// arrays of a DenoiseSource.
#ifndef VKPT_DENOISE_FILTER_H
#define VKPT_DENOISE_FILTER_H

#include "denoise.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Where a kernel and the C++ loop read the pixels and the current iterate: buffers on the
// device (declared by the kernel before it includes this file), arrays on the host.
#ifdef __cplusplus
struct DenoiseSource {
    const DenoisePixel* pixels;
    const vec4* values;
};
#define DENOISE_SOURCE_PARAM const DenoiseSource &source,
#define DENOISE_PIXEL(i) source.pixels[i]
#define DENOISE_VALUE(i) source.values[i]
#else
#define DENOISE_SOURCE_PARAM
#define DENOISE_PIXEL(i) denoisePixels[i]
#define DENOISE_VALUE(i) denoiseValuesIn[i]
#endif

// The variance the centre's test uses: its own, or, where larger, its own blended with the mean
// over its 3×3 neighbourhood leaving out the largest, the neighbourhood counting as
// DENOISE_PRIOR_SAMPLES samples against the pixel's n. A pixel whose few samples happened to
// agree (variance 0 at 4 spp) thus still sees its surroundings' noise, while 64 samples of
// exactly 0 (a black emitter's back among lit floor) are believed; and one firefly beside the
// pixel (a variance far above the rest) does not lift its bound and so is not spread into it.
VKPT_FN float centreTestVariance(DENOISE_SOURCE_PARAM uint x, uint y, DenoiseParams params) {
    float total = 0.0f;
    float largest = 0.0f;
    float count = 0.0f;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            int qx = int(x) + dx;
            int qy = int(y) + dy;
            if (qx < 0 || qy < 0 || qx >= int(params.width) || qy >= int(params.height)) continue;
            float variance = DENOISE_VALUE(uint(qy) * params.width + uint(qx)).w;
            total += variance;
            largest = max(largest, variance);
            count += 1.0f;
        }
    }
    float own = DENOISE_VALUE(y * params.width + x).w;
    float around = count > 1.0f ? (total - largest) / (count - 1.0f) : own;
    float samples = float(DENOISE_PIXEL(y * params.width + x).sampleCount);
    return max(own, (samples * own + DENOISE_PRIOR_SAMPLES * around) /
                        (samples + DENOISE_PRIOR_SAMPLES));
}

// One à-trous iteration at pixel (x, y): the weighted mean of the 5×5 taps `step` apart (rgb)
// and the variance of its luminance (w). A tap's variance enters the test capped at the
// centre's, so that a firefly (a mean far above its neighbours, with a variance to match) cannot
// pass its neighbours' tests on the strength of its own noise.
VKPT_FN vec4 filterPixel(DENOISE_SOURCE_PARAM uint x, uint y, DenoiseParams params) {
    uint centreIndex = y * params.width + x;
    DenoisePixel centre = DENOISE_PIXEL(centreIndex);
    vec4 centreValue = DENOISE_VALUE(centreIndex);
#ifdef __cplusplus
    float centreVariance = centreTestVariance(source, x, y, params);
#else
    float centreVariance = centreTestVariance(x, y, params);
#endif
    // The centre plus the weighted differences, so that with every tap rejected the output is
    // the centre's value bit for bit (Σ w·x / Σ w need not round back to x).
    vec3 centreRgb = vec3(centreValue.x, centreValue.y, centreValue.z);
    vec3 differenceSum = vec3(0.0f);
    float weightSum = 0.0f;
    float varianceSum = 0.0f;
    for (int j = -2; j <= 2; ++j) {
        for (int i = -2; i <= 2; ++i) {
            int qx = int(x) + i * int(params.step);
            int qy = int(y) + j * int(params.step);
            if (qx < 0 || qy < 0 || qx >= int(params.width) || qy >= int(params.height)) continue;
            uint index = uint(qy) * params.width + uint(qx);
            vec4 value = DENOISE_VALUE(index);
            float weight = atrousTap(i) * atrousTap(j);
            if (index != centreIndex) {
                float distance = float(params.step) * sqrt(float(i * i + j * j));
                float variance = centreVariance + min(value.w, centreVariance);
                weight *=
                    guideWeight(centre, DENOISE_PIXEL(index), distance, params) *
                    gateWeight(centreRgb, vec3(value.x, value.y, value.z), variance, params.gateT);
            }
            differenceSum += weight * (vec3(value.x, value.y, value.z) - centreRgb);
            weightSum += weight;
            varianceSum += weight * weight * value.w;
        }
    }
    return vec4(centreRgb + differenceSum / weightSum, varianceSum / (weightSum * weightSum));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_DENOISE_FILTER_H
