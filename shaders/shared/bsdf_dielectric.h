// bsdf_dielectric.h — the glass lobe of KHR_materials_transmission, KHR_materials_ior and
// KHR_materials_volume: reflection and refraction at a dielectric interface, rough (GGX) or
// smooth, solid (the mesh bounds a volume: directions bend) or thin-walled (they do not).
// Local shading frame as in bsdf.h: z is the shading normal turned towards wo, both directions
// point away from the surface, so wi.z < 0 is a transmitted direction.
//
// eta is the index of refraction on wi's far side over the index on wo's side: the material's
// ior when the path enters the volume through its front face, 1/ior when it leaves through the
// back face. The reflectance is the exact dielectric Fresnel term of that ratio, not Schlick's.
//
// Rough: Walter, Marschner, Li and Torrance, "Microfacet Models for Refraction through Rough
// Surfaces" (EGSR 2007), with GGX, height-correlated Smith masking (Heitz 2014) and visible
// normal sampling (Heitz 2018, ggx.h's sampleGgxVisibleNormal). Reflection is eq. 20,
// transmission eq. 21 with o = wo (the camera side) and i = wi: in that form the BTDF is the
// radiance BTDF and carries the factor (η_o/η_i)² = 1/η² by which radiance is compressed on
// entering a denser medium (Veach 1997, thesis §5.2). Its adjoint (importance) differs by η²;
// the two factors of a path that enters and leaves a volume cancel.
//
// Smooth (α at its floor, or ior 1): a delta lobe, reflection with probability F, refraction
// by Snell's law with 1 − F, each sampled with exactly its Fresnel weight, so that a sample's
// weight is 1 for reflection and tint/η² for refraction. Evaluation and pdf are 0: no other
// strategy can find a delta direction, and light sampling does not try (docs/integrator.md).
//
// Thin-walled (thicknessFactor 0, KHR_materials_volume): a sheet with two parallel faces and
// nothing inside. A ray passes through without bending; what it reflects and transmits are
// the sums over the rays bouncing between the two faces, R' = R + T²R/(1 − R²) = 2R/(1 + R)
// and T' = 1 − R' (Stokes' relations for a non-absorbing slab; pbrt-v4 §9.5 does the same).
// Rough thin-walled transmission is the reflection lobe mirrored through the surface plane:
// the sheet roughens both faces alike, and a ray through it keeps its direction on average.
#ifndef VKPT_BSDF_DIELECTRIC_H
#define VKPT_BSDF_DIELECTRIC_H

#include "ggx.h"
#include "host_device.h"
#include "sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// The dielectric lobe's parameters at a point.
struct DielectricLobe {
    float alpha;     // GGX α; at VKPT_SMOOTH_DIELECTRIC_ALPHA or below, the lobe is a delta
    float eta;       // ior beyond the surface / ior on wo's side (solid only)
    vec3 tint;       // transmitted light's colour: KHR_materials_transmission's baseColor
    bool thinWalled; // no volume behind the surface: transmission does not bend
};

// α at or below this is a smooth interface. It is ggx.h's VKPT_MIN_GGX_ALPHA, the floor of
// every GGX α (roughness ≤ 0.0316), so "roughness 0 glass" is the mirror-and-window that glTF
// means rather than a lobe 2·10⁻³ rad wide that no light sample could find.
#define VKPT_SMOOTH_DIELECTRIC_ALPHA 1e-3f

VKPT_FN bool dielectricIsDelta(DielectricLobe lobe) {
    return lobe.alpha <= VKPT_SMOOTH_DIELECTRIC_ALPHA || lobe.eta == 1.0f;
}

// Exact Fresnel reflectance of unpolarised light at a dielectric interface (Walter et al. 2007,
// eq. 22): c = |cos θ| on the incident side, η = η_t/η_i, g² = η² − 1 + c²; g² ≤ 0 is total
// internal reflection.
VKPT_FN float dielectricFresnel(float cosTheta, float eta) {
    float c = min(abs(cosTheta), 1.0f);
    float g2 = eta * eta - 1.0f + c * c;
    if (!(g2 > 0.0f)) return 1.0f;
    float g = sqrt(g2);
    float a = (g - c) / (g + c);
    float b = (c * (g + c) - 1.0f) / (c * (g - c) + 1.0f);
    return min(0.5f * a * a * (1.0f + b * b), 1.0f);
}

// The reflectance of the lobe at cos θ to the (micro)normal: one interface, or the thin sheet's
// two (2R/(1 + R), see above).
VKPT_FN float dielectricReflectance(DielectricLobe lobe, float cosTheta) {
    float r = dielectricFresnel(cosTheta, lobe.eta);
    return lobe.thinWalled ? 2.0f * r / (1.0f + r) : r;
}

// Height-correlated G2 = 1/(1 + Λ(wo) + Λ(wi)) (Heitz 2014, eq. 99, which holds for
// transmission with |cos|) divided by |cos θo cos θi|: 2 / (|zi|·root(wo) + |zo|·root(wi)).
VKPT_FN float dielectricG2OverCosines(vec3 wo, vec3 wi, float alpha) {
    float d = abs(wi.z) * smithRoot(wo, alpha) + abs(wo.z) * smithRoot(wi, alpha);
    return d > 0.0f ? 2.0f / d : 0.0f;
}

// The density of visible normals h seen from wo (Heitz 2018, eq. 2): G1(wo)·max(0, wo·h)·D/wo.z
// with G1 = 2 wo.z/(wo.z + root(wo)).
VKPT_FN float dielectricVisibleNormalPdf(vec3 wo, vec3 h, float alpha) {
    float woh = dot(wo, h);
    if (!(woh > 0.0f)) return 0.0f;
    return 2.0f * ggxDistribution(h, alpha) * woh / (wo.z + smithRoot(wo, alpha));
}

// wi mirrored through the surface plane: the thin sheet's transmitted twin of a reflection.
VKPT_FN vec3 mirroredThroughSurface(vec3 w) {
    return vec3(w.x, w.y, -w.z);
}

// The microfacet normal that turns wo into wi, turned to +z; (0, 0, 0) when there is none.
// Reflection (and the thin sheet's mirrored transmission): the half vector. Refraction: the
// generalised half vector −(wo + η wi) (Walter et al. 2007, eq. 16).
VKPT_FN vec3 dielectricHalfVector(DielectricLobe lobe, vec3 wo, vec3 wi) {
    vec3 h;
    if (wi.z > 0.0f) {
        h = wo + wi;
    } else if (lobe.thinWalled) {
        h = wo + mirroredThroughSurface(wi);
    } else {
        h = -(wo + lobe.eta * wi);
    }
    float l = length(h);
    if (!(l > 0.0f)) return vec3(0.0f);
    h = h / l;
    return h.z < 0.0f ? -h : h;
}

// f (no cosine) of the rough lobe; 0 for the delta lobe, for wo below the surface, and for
// microfacets that face away from either direction.
VKPT_FN vec3 evaluateDielectric(DielectricLobe lobe, vec3 wo, vec3 wi) {
    if (dielectricIsDelta(lobe) || !(wo.z > 0.0f) || wi.z == 0.0f) return vec3(0.0f);
    vec3 h = dielectricHalfVector(lobe, wo, wi);
    float woh = dot(wo, h);
    if (h.z == 0.0f || !(woh > 0.0f)) return vec3(0.0f);
    float r = dielectricReflectance(lobe, woh);
    float d = ggxDistribution(h, lobe.alpha);
    float g = dielectricG2OverCosines(wo, wi, lobe.alpha);
    // Reflection, eq. 20: F·D·G2/(4 |cos θo cos θi|).
    if (wi.z > 0.0f) return vec3(0.25f * r * d * g);
    if (lobe.thinWalled) return lobe.tint * (0.25f * (1.0f - r) * d * g);
    // Refraction, eq. 21: |wo·h||wi·h| (1 − F) D G2 / (|cos θo cos θi| (wo·h + η wi·h)²).
    float wih = dot(wi, h);
    if (!(wih < 0.0f)) return vec3(0.0f);
    float denominator = woh + lobe.eta * wih;
    if (denominator == 0.0f) return vec3(0.0f);
    return lobe.tint * (woh * -wih * (1.0f - r) * d * g / (denominator * denominator));
}

// The solid-angle pdf with which sampleDielectric draws wi (0 for the delta lobe): the visible
// normal's density, times the reflect/refract choice (F or 1 − F), times the Jacobian of the
// map from h to wi: 1/(4 wo·h) for reflection (Walter eq. 14), η²|wi·h|/(wo·h + η wi·h)² for
// refraction (eq. 17).
VKPT_FN float dielectricPdf(DielectricLobe lobe, vec3 wo, vec3 wi) {
    if (dielectricIsDelta(lobe) || !(wo.z > 0.0f) || wi.z == 0.0f) return 0.0f;
    vec3 h = dielectricHalfVector(lobe, wo, wi);
    float woh = dot(wo, h);
    if (h.z == 0.0f || !(woh > 0.0f)) return 0.0f;
    float r = dielectricReflectance(lobe, woh);
    float visible = dielectricVisibleNormalPdf(wo, h, lobe.alpha);
    if (wi.z > 0.0f) return r * visible / (4.0f * woh);
    if (lobe.thinWalled) return (1.0f - r) * visible / (4.0f * woh);
    float wih = dot(wi, h);
    if (!(wih < 0.0f)) return 0.0f;
    float denominator = woh + lobe.eta * wih;
    if (denominator == 0.0f) return 0.0f;
    return (1.0f - r) * visible * lobe.eta * lobe.eta * -wih / (denominator * denominator);
}

// Snell's law about the unit normal n (on wo's side): the refracted direction for η = η_t/η_i,
// or (0, 0, 0) under total internal reflection.
VKPT_FN vec3 refractDirection(vec3 wo, vec3 n, float eta) {
    float cosI = dot(wo, n);
    float sin2T = max(0.0f, 1.0f - cosI * cosI) / (eta * eta);
    if (sin2T >= 1.0f) return vec3(0.0f);
    float cosT = sqrt(1.0f - sin2T);
    return normalize(-wo / eta + (cosI / eta - cosT) * n);
}

// A direction drawn from the lobe. For the delta lobe, weight = f·|cos θi|/pdf exactly (1 for
// reflection, tint/η² or the thin sheet's tint for transmission) and pdf is the discrete
// probability of the choice; the rough lobe's weight is left to the caller, which divides by
// the pdf of its whole mixture.
struct DielectricSample {
    vec3 direction;
    float pdf; // delta: F or 1 − F; rough: unused (0)
    vec3 weight;
    bool valid;
};

VKPT_FN DielectricSample sampleDielectric(DielectricLobe lobe, vec3 wo, vec2 u, float uChoice) {
    DielectricSample s;
    s.direction = vec3(0.0f, 0.0f, 1.0f);
    s.pdf = 0.0f;
    s.weight = vec3(0.0f);
    s.valid = false;
    if (!(wo.z > 0.0f)) return s;
    bool delta = dielectricIsDelta(lobe);
    vec3 h = delta ? vec3(0.0f, 0.0f, 1.0f) : sampleGgxVisibleNormal(wo, lobe.alpha, u);
    float woh = dot(wo, h);
    if (!(woh > 0.0f)) return s;
    float r = dielectricReflectance(lobe, woh);
    vec3 reflected = normalize(2.0f * woh * h - wo);
    bool reflect = uChoice < r;
    if (reflect) {
        s.direction = reflected;
        s.weight = vec3(1.0f);
    } else if (lobe.thinWalled) {
        s.direction = mirroredThroughSurface(reflected);
        s.weight = lobe.tint;
    } else {
        s.direction = refractDirection(wo, h, lobe.eta);
        s.weight = lobe.tint / (lobe.eta * lobe.eta);
    }
    // A reflection must stay above the surface and a transmission go below it (a GGX normal
    // can send either across; total internal reflection returns no direction).
    s.valid = reflect ? s.direction.z > 0.0f : s.direction.z < 0.0f;
    s.pdf = delta ? (reflect ? r : 1.0f - r) : 0.0f;
    return s;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_BSDF_DIELECTRIC_H
