// rng.h — counter-based random numbers: every number is a pure function of
// (seed, pixel, sample index, bounce, dimension), so images do not depend on scheduling and
// the CPU reference and the GPU kernels draw exactly the same numbers.
#ifndef VKPT_RNG_H
#define VKPT_RNG_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Dimensions: each names one hash evaluation, which yields four independent 32-bit words.
#define DIM_CAMERA 0u      // .xy: jitter inside the pixel
#define DIM_BSDF 1u        // .xy: scattered direction, .z: Russian roulette
#define DIM_LIGHT_FIRST 2u // DIM_LIGHT_FIRST + i for light sample i: .x emitter, .yz point
#define RNG_MAX_DIMENSION 255u
#define RNG_MAX_LIGHT_SAMPLES (RNG_MAX_DIMENSION - DIM_LIGHT_FIRST + 1u)

// pcg4d: Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020, section 3.
// Integer-only, so both sides agree bit for bit.
VKPT_FN uvec4 pcg4d(uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v ^= v >> 16u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

// Bounce and dimension share one input word: up to 2^24 bounces, 256 dimensions per bounce.
VKPT_FN uvec4 randomBits(uint seed, uint pixel, uint sampleIndex, uint bounce, uint dimension) {
    return pcg4d(uvec4(pixel, sampleIndex, (bounce << 8u) | (dimension & RNG_MAX_DIMENSION), seed));
}

// The top 24 bits give every float in [0, 1) with spacing 2^-24; never returns 1.
VKPT_FN float bitsToUnitFloat(uint bits) {
    return float(bits >> 8u) * (1.0f / 16777216.0f);
}

VKPT_FN vec4 randomFloats(uint seed, uint pixel, uint sampleIndex, uint bounce, uint dimension) {
    uvec4 bits = randomBits(seed, pixel, sampleIndex, bounce, dimension);
    return vec4(bitsToUnitFloat(bits.x), bitsToUnitFloat(bits.y), bitsToUnitFloat(bits.z),
                bitsToUnitFloat(bits.w));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_RNG_H
