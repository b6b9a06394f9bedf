// sheen.h — the Charlie sheen lobe of KHR_materials_sheen: Estevez and Kulla 2017, "Production
// Friendly Microfacet Sheen BRDF" (the distribution, their eq. 2), with the visibility term of
// Neubelt and Pettineo 2013, "Crafting a Next-Gen Material Pipeline for The Order: 1886",
// which the KHR_materials_sheen specification allows in place of Charlie's fitted Λ: it is
// closed-form, symmetric in wo and wi, and needs no per-roughness fit. Local shading frame.
#ifndef VKPT_SHEEN_H
#define VKPT_SHEEN_H

#include "host_device.h"
#include "sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// The smallest sheen α (= sheenRoughness²). Charlie's D is sin^(1/α) θh: below α = 0.01 the
// lobe is a rim a few degrees from the horizon that uniform sampling rarely finds, so a
// smoother sheen renders as sheenRoughness 0.1.
#define VKPT_MIN_SHEEN_ALPHA 0.01f

VKPT_FN float sheenAlphaOf(float roughness) {
    float r = clamp(roughness, 0.0f, 1.0f);
    return max(r * r, VKPT_MIN_SHEEN_ALPHA);
}

// D(h) = (2 + 1/α) sin^(1/α) θh / (2π), normalised so that ∫ D cos θh dω = 1. sin θh is
// √(x² + y²), exact near the horizon where the lobe lives.
VKPT_FN float charlieDistribution(vec3 h, float alpha) {
    float sinTheta = sqrt(h.x * h.x + h.y * h.y);
    float inverseAlpha = 1.0f / alpha;
    return (2.0f + inverseAlpha) * pow(sinTheta, inverseAlpha) * (0.5f * VKPT_INV_PI);
}

// Neubelt and Pettineo's V = 1 / (4 (cos θi + cos θo − cos θi cos θo)), which replaces
// G / (4 cos θi cos θo).
VKPT_FN float sheenVisibility(float cosThetaO, float cosThetaI) {
    return 0.25f / (cosThetaI + cosThetaO - cosThetaI * cosThetaO);
}

// The white sheen lobe D · V for directions above the surface; KHR_materials_sheen multiplies it
// by sheenColor.
VKPT_FN float sheenReflection(vec3 wo, vec3 wi, float alpha) {
    vec3 h = normalize(wo + wi);
    return charlieDistribution(h, alpha) * sheenVisibility(wo.z, wi.z);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_SHEEN_H
