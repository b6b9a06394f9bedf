// ggx.h — the GGX (Trowbridge–Reitz) microfacet lobe every specular layer of bsdf.h uses (the
// base's dielectric and metal reflection, the clearcoat): Schlick's Fresnel, the distribution,
// height-correlated Smith visibility, the pdf of reflected visible normals and their sampler,
// all in the local shading frame (z the normal, both directions away from the surface).
#ifndef VKPT_GGX_H
#define VKPT_GGX_H

#include "host_device.h"
#include "sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// The smallest GGX α. glTF's roughness 0 is a perfect mirror, which a renderer without delta
// lobes cannot represent; α = 1e-3 is the bound below which pbrt-v4 treats the distribution as
// smooth. At it, D peaks at 1/(π α²) ≈ 3.2e5, far inside float range, and the lobe (about
// 2α = 2e-3 rad wide in the reflected direction) is still four orders of magnitude wider than
// the angular resolution of a float unit vector, so sampling and evaluation agree.
#define VKPT_MIN_GGX_ALPHA 1e-3f

// Perceptual roughness → GGX α = roughness², clamped to [0, 1] (the glTF range) first.
VKPT_FN float ggxAlphaOf(float roughness) {
    float r = clamp(roughness, 0.0f, 1.0f);
    return max(r * r, VKPT_MIN_GGX_ALPHA);
}

VKPT_FN float maxComponent(vec3 v) {
    return max(max(v.x, v.y), v.z);
}

// Schlick's (1 − cos θ)^5, the Fresnel weight of F90 = 1.
VKPT_FN float schlickWeight(float cosTheta) {
    float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return m2 * m2 * m;
}

VKPT_FN vec3 schlickFresnel(vec3 f0, float cosTheta) {
    return f0 + (vec3(1.0f) - f0) * schlickWeight(cosTheta);
}

// GGX (Trowbridge–Reitz) normal distribution for a unit half vector h in the local frame,
// written as 1 / (π α² ((x² + y²)/α² + z²)²) rather than with 1 − cos²θ: the sine part is then
// exact near the peak, where a narrow lobe (α near its floor) lives.
VKPT_FN float ggxDistribution(vec3 h, float alpha) {
    float a2 = alpha * alpha;
    float t = (h.x * h.x + h.y * h.y) / a2 + h.z * h.z;
    return 1.0f / (VKPT_PI * a2 * t * t);
}

// √(z² + α²(x² + y²)) for a unit direction w: GGX's Smith Λ(w) = (√(1 + α² tan²θ) − 1)/2
// (Heitz 2014, "Understanding the Masking-Shadowing Function in Microfacet-Based BRDFs",
// JCGT 3(2), eq. 72) is (this/z − 1)/2, which needs no division by a grazing z.
VKPT_FN float smithRoot(vec3 w, float alpha) {
    return sqrt(w.z * w.z + alpha * alpha * (w.x * w.x + w.y * w.y));
}

// Height-correlated G2 = 1/(1 + Λ(wo) + Λ(wi)) (Heitz 2014, eq. 99) divided by the BRDF's
// 4 cos θo cos θi: with the form of smithRoot the cosines cancel, leaving
// 1 / (2 (cos θi · root(wo) + cos θo · root(wi))), finite at grazing angles.
VKPT_FN float ggxVisibility(vec3 wo, vec3 wi, float alpha) {
    float denominator = wi.z * smithRoot(wo, alpha) + wo.z * smithRoot(wi, alpha);
    return denominator > 0.0f ? 0.5f / denominator : 0.0f;
}

// The GGX lobe with F = 1 for directions above the surface: D · G2 / (4 cos θo cos θi).
VKPT_FN float ggxReflection(vec3 wo, vec3 wi, vec3 h, float alpha) {
    return ggxDistribution(h, alpha) * ggxVisibility(wo, wi, alpha);
}

// Schlick's weight at V·H for the half vector h of wo and wi. V·H and L·H are equal in exact
// arithmetic; the rounding of h makes them differ by (wo − wi)·δh, which near retro-reflection
// is ulps of 1, not of V·H. Their mean cancels that error and is symmetric, so a BRDF built on
// it gives f(wo, wi) and f(wi, wo) to the last bit.
VKPT_FN float halfVectorFresnelWeight(vec3 wo, vec3 wi, vec3 h) {
    return schlickWeight(0.5f * (dot(wo, h) + dot(wi, h)));
}

// Solid-angle pdf of the direction reflected about a visible normal:
// G1(wo) D(h) / (4 cos θo) with G1 = 2 cos θo / (cos θo + root(wo)), i.e. D / (2 (cos θo + root)).
VKPT_FN float ggxReflectionPdf(vec3 wo, vec3 h, float alpha) {
    return ggxDistribution(h, alpha) / (2.0f * (wo.z + smithRoot(wo, alpha)));
}

// A GGX normal visible from wo: Heitz, "Sampling the GGX Distribution of Visible Normals",
// JCGT 7(4), 2018. Stretching by 1/α turns the microsurface into the unit hemisphere; its
// visible normals are the projection of a uniform disk point onto it, the disk's half beyond
// the silhouette of wo squeezed so that the projected area is right; then unstretch.
// With alpha = (αx, αy) the same construction samples the anisotropic distribution
// (ggx_anisotropic.h); the isotropic sampler is its αx = αy case.
VKPT_FN vec3 sampleGgxVisibleNormalStretched(vec3 wo, vec2 alpha, vec2 u) {
    vec3 v = normalize(vec3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
    float lengthSquared = v.x * v.x + v.y * v.y;
    vec3 t1 =
        lengthSquared > 0.0f ? vec3(-v.y, v.x, 0.0f) / sqrt(lengthSquared) : vec3(1.0f, 0.0f, 0.0f);
    vec3 t2 = cross(v, t1);
    float r = sqrt(u.x);
    float phi = 2.0f * VKPT_PI * u.y;
    float p1 = r * cos(phi);
    float p2 = r * sin(phi);
    float squeeze = 0.5f * (1.0f + v.z);
    p2 = mix(sqrt(max(0.0f, 1.0f - p1 * p1)), p2, squeeze);
    vec3 n = p1 * t1 + p2 * t2 + sqrt(max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * v;
    return normalize(vec3(alpha.x * n.x, alpha.y * n.y, max(0.0f, n.z)));
}

VKPT_FN vec3 sampleGgxVisibleNormal(vec3 wo, float alpha, vec2 u) {
    return sampleGgxVisibleNormalStretched(wo, vec2(alpha, alpha), u);
}

// wo reflected about a sampled visible normal; below the surface when the normal is steep.
VKPT_FN vec3 sampleGgxReflection(vec3 wo, float alpha, vec2 u) {
    vec3 h = sampleGgxVisibleNormal(wo, alpha, u);
    return normalize(2.0f * dot(wo, h) * h - wo);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_GGX_H
