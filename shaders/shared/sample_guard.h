// sample_guard.h — what a camera sample's radiance must pass before a pixel accumulates it, the
// same in both renderers: a sample with a NaN or infinite component is discarded and counted
// (one NaN would poison the pixel for good), and with --clamp X a sample whose largest component
// exceeds X is scaled down to X. Clamping is biased (it removes energy from bright, rare paths)
// and off by default.
#ifndef VKPT_SAMPLE_GUARD_H
#define VKPT_SAMPLE_GUARD_H

#include "host_device.h"
#include "sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Tests the exponent bits, which no compiler may assume away (isnan and isinf can be, under
// fast-math or relaxed-precision shader compilation).
VKPT_FN bool isFiniteBits(float x) {
    return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;
}

VKPT_FN bool isFiniteRadiance(vec3 v) {
    return isFiniteBits(v.x) && isFiniteBits(v.y) && isFiniteBits(v.z);
}

// A sample the accumulators can take: finite components and a finite luminance (three
// components near the largest float can sum past it).
VKPT_FN bool isFiniteSample(vec3 radiance) {
    return isFiniteRadiance(radiance) && isFiniteBits(luminance(radiance));
}

// No clamp: the default of --clamp.
#define SAMPLE_CLAMP_OFF 0.0f

// The sample scaled so that no component exceeds `limit` (its colour is kept); unchanged when
// limit is SAMPLE_CLAMP_OFF.
VKPT_FN vec3 clampSample(vec3 radiance, float limit) {
    float largest = max(max(radiance.x, radiance.y), radiance.z);
    return (limit > 0.0f && largest > limit) ? radiance * (limit / largest) : radiance;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_SAMPLE_GUARD_H
