// sampling.h — warps from uniform numbers to directions and points, their pdfs, and MIS.
// Pure functions shared by the CPU reference and the kernels.
#ifndef VKPT_SAMPLING_H
#define VKPT_SAMPLING_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

#define VKPT_PI 3.14159265358979323846f
#define VKPT_INV_PI 0.31830988618379067154f

struct Basis {
    vec3 tangent;
    vec3 bitangent;
    vec3 normal;
};

// Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017: branchless and
// free of the singularity of Frisvad's version at n.z = -1.
VKPT_FN Basis makeBasis(vec3 n) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float b = n.x * n.y * a;
    Basis basis;
    basis.tangent = vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
    basis.bitangent = vec3(b, s + n.y * n.y * a, -n.y);
    basis.normal = n;
    return basis;
}

VKPT_FN vec3 basisToWorld(Basis basis, vec3 v) {
    return v.x * basis.tangent + v.y * basis.bitangent + v.z * basis.normal;
}

// The inverse of basisToWorld: the basis is orthonormal, so its transpose undoes it.
VKPT_FN vec3 worldToBasis(Basis basis, vec3 v) {
    return vec3(dot(v, basis.tangent), dot(v, basis.bitangent), dot(v, basis.normal));
}

// Malley's method: a uniform disk point lifted to the hemisphere; pdf = cos θ / π.
VKPT_FN vec3 sampleCosineHemisphere(vec2 u) {
    float r = sqrt(u.x);
    float phi = 2.0f * VKPT_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0f, 1.0f - u.x)));
}

VKPT_FN float cosineHemispherePdf(float cosTheta) {
    return max(cosTheta, 0.0f) * VKPT_INV_PI;
}

// Uniform over the hemisphere z >= 0; pdf = 1 / (2π).
VKPT_FN vec3 sampleUniformHemisphere(vec2 u) {
    float z = u.x;
    float r = sqrt(max(0.0f, 1.0f - z * z));
    float phi = 2.0f * VKPT_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

VKPT_FN float uniformHemispherePdf() {
    return 0.5f * VKPT_INV_PI;
}

// Uniform over the whole sphere: z uniform in [-1, 1] (Archimedes' hat-box theorem);
// pdf = 1 / (4π).
VKPT_FN vec3 sampleUniformSphere(vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = sqrt(max(0.0f, 1.0f - z * z));
    float phi = 2.0f * VKPT_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

VKPT_FN float uniformSpherePdf() {
    return 0.25f * VKPT_INV_PI;
}

// Uniform point on a triangle as barycentrics (b0, b1, b2): pbrt-v3's square-root warp
// (Osada et al. 2002); the point is b0·v0 + b1·v1 + b2·v2.
VKPT_FN vec3 sampleTriangleBarycentrics(vec2 u) {
    float su = sqrt(u.x);
    return vec3(1.0f - su, su * (1.0f - u.y), su * u.y);
}

// Veach's power heuristic (β = 2) for nf samples from pdf f against ng samples from pdf g.
VKPT_FN float powerHeuristic(float nf, float fPdf, float ng, float gPdf) {
    float f = nf * fPdf;
    float g = ng * gPdf;
    float denominator = f * f + g * g;
    return denominator > 0.0f ? (f * f) / denominator : 0.0f;
}

// Rec. 709 / sRGB primaries.
VKPT_FN float luminance(vec3 c) {
    return dot(c, vec3(0.2126f, 0.7152f, 0.0722f));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_SAMPLING_H
