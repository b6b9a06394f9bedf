// sample_features.h — the layers a denoiser and a compositor read beside the colour (AOVs):
// albedo, shading normal and depth at the first surface a camera sample sees, and their
// per-pixel accumulation over the samples. One definition for both renderers: vkpt's kernels
// write a sample's features where they shade its camera ray (shade_hits, bounce 0) and add them
// in accumulate; vkpt-ref's integrators fill them at their own first hit and add them with the
// same function, in the same sample order, so that at one seed the two agree as their colours do.
#ifndef VKPT_SAMPLE_FEATURES_H
#define VKPT_SAMPLE_FEATURES_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// +inf as a float's bits: the depth of a sample that sees no surface.
#define FEATURE_DEPTH_NONE 0x7f800000u

// One camera sample's features (a miss: albedo and normal 0, depth +inf).
struct SampleFeatures {
    vec3 albedo; // the base colour at the hit, textures applied
    float depth; // camera-space z of the hit: t · (direction · forward)
    vec3 normal; // world-space shading normal, turned towards the camera
    uint unused0;
};

// One pixel's features over `count` camera samples: albedo and normal as running means, a miss
// counting as 0, so that edges are filtered like the colour (Open Image Denoise asks for that);
// depth the nearest hit (+inf when every sample missed).
struct PixelFeatures {
    vec3 albedoMean;
    float depth;
    vec3 normalMean;
    uint count;
};

VKPT_FN SampleFeatures missFeatures() {
    SampleFeatures miss;
    miss.albedo = vec3(0.0f);
    miss.depth = uintBitsToFloat(FEATURE_DEPTH_NONE);
    miss.normal = vec3(0.0f);
    miss.unused0 = 0u;
    return miss;
}

VKPT_FN PixelFeatures noPixelFeatures() {
    PixelFeatures none;
    none.albedoMean = vec3(0.0f);
    none.depth = uintBitsToFloat(FEATURE_DEPTH_NONE);
    none.normalMean = vec3(0.0f);
    none.count = 0u;
    return none;
}

// `direction` is the camera ray's, as the camera made it; t the hit's distance along it.
VKPT_FN SampleFeatures surfaceFeatures(vec3 baseColor, vec3 shadingNormal, float t, vec3 direction,
                                       vec3 forward) {
    SampleFeatures hit;
    hit.albedo = baseColor;
    hit.depth = t * dot(direction, forward);
    hit.normal = shadingNormal;
    hit.unused0 = 0u;
    return hit;
}

// The running mean m += (x − m) / n stays within float rounding of the true mean at any count,
// where a float sum of 2^20 albedos would lose about 6 % (Welford's update, as the luminance's).
// (`sample` is a GLSL keyword, hence `one`.)
VKPT_FN void addSampleFeatures(VKPT_INOUT(PixelFeatures) pixel, SampleFeatures one) {
    pixel.count += 1u;
    float weight = 1.0f / float(pixel.count);
    pixel.albedoMean += (one.albedo - pixel.albedoMean) * weight;
    pixel.normalMean += (one.normal - pixel.normalMean) * weight;
    pixel.depth = min(pixel.depth, one.depth);
}

#ifdef __cplusplus
static_assert(sizeof(SampleFeatures) == 32 && offsetof(SampleFeatures, normal) == 16);
static_assert(sizeof(PixelFeatures) == 32 && offsetof(PixelFeatures, count) == 28);
} // namespace vkpt::gpu
#endif

#endif // VKPT_SAMPLE_FEATURES_H
