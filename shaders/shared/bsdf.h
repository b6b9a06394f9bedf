// bsdf.h — the glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification, Appendix B, with
// KHR_materials_specular): evaluation, pdf and importance sampling in the local shading frame,
// where z is the shading normal and both directions point away from the surface.
//
//   f          = mix(dielectric, metal, metallic)
//   metal      = specular · (baseColor + (1 − baseColor)(1 − V·H)^5)
//   dielectric = baseColor/π · (1 − s·max(F)) + specular · s·F,
//                F = F0 + (1 − F0)(1 − V·H)^5,  F0 = min(0.04·specularColor, 1)
//   specular   = D_GGX(H) · G2(V, L) / (4 (N·V)(N·L)), G2 height-correlated Smith.
//
// V·H = L·H, so f is reciprocal, the diffuse term's (1 − s·max F) factor included. The
// coupling of the two dielectric lobes is glTF's approximation: the diffuse term loses
// 1 − s·max F of its own half vector, not what the specular lobe reflects at wo, so a white
// dielectric reflects more than it receives at grazing views (tests/unit/bsdf_test.cpp
// measures it; KhronosGroup/glTF#1853 discusses the coupling).
// With KHR_materials_transmission the non-metal part is mix(dielectric, glass, transmission),
// the glass lobe of bsdf_dielectric.h; KHR_materials_ior sets F0 = ((ior − 1)/(ior + 1))².
// A material without MATERIAL_METALLIC_ROUGHNESS is Lambertian and keeps the exact arithmetic
// of the Lambertian path (docs/scene-model.md), so scenes made only of it render as before.
#ifndef VKPT_BSDF_H
#define VKPT_BSDF_H

#include "bsdf_dielectric.h"
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

// Bounds of the probability of sampling the specular lobe when both lobes contribute: a white
// dielectric at normal incidence estimates 0.04, and a highlight sampled 25 times less often
// than the diffuse lobe is noisy; the floor costs at most 10 % of the diffuse samples.
#define VKPT_MIN_LOBE_PROBABILITY 0.1f

struct ShadingMaterial {
    vec3 baseColor;
    float metallic;
    vec3 specularColor;     // KHR_materials_specular colour
    float specular;         // KHR_materials_specular factor s
    float alpha;            // GGX α = roughness², at least VKPT_MIN_GGX_ALPHA
    bool metallicRoughness; // false: the Lambertian material
    // KHR_materials_transmission, _ior and _volume (bsdf_dielectric.h).
    float transmission; // share of the non-metal part that is glass; 0: opaque
    float iorF0;        // ((ior − 1)/(ior + 1))², the dielectric's F0 before specularColor
    float eta;          // ior beyond the surface / ior on wo's side; thin-walled: the ior
    bool thinWalled;    // no volume behind the surface
};

// roughness is perceptual; it is clamped to [0, 1] (the glTF range) before squaring.
VKPT_FN ShadingMaterial makeShadingMaterial(vec3 baseColor, float metallic, float roughness,
                                            float specular, vec3 specularColor,
                                            bool metallicRoughness) {
    ShadingMaterial m;
    m.baseColor = baseColor;
    m.metallic = metallic;
    m.specularColor = specularColor;
    m.specular = specular;
    float r = clamp(roughness, 0.0f, 1.0f);
    m.alpha = max(r * r, VKPT_MIN_GGX_ALPHA);
    m.metallicRoughness = metallicRoughness;
    m.transmission = 0.0f;
    m.iorF0 = 0.04f; // ior 1.5
    m.eta = 1.5f;
    m.thinWalled = true;
    return m;
}

// The material's glass lobe: roughness as the opaque lobes', transmitted light tinted by the
// base colour (KHR_materials_transmission).
VKPT_FN DielectricLobe glassLobeOf(ShadingMaterial m) {
    DielectricLobe lobe;
    lobe.alpha = m.alpha;
    lobe.eta = m.eta;
    lobe.tint = m.baseColor;
    lobe.thinWalled = m.thinWalled;
    return lobe;
}

// The probability of sampling the glass lobe: its share of the material.
VKPT_FN float glassLobeProbability(ShadingMaterial m) {
    return (1.0f - m.metallic) * m.transmission;
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

// The dielectric's normal-incidence reflectance: ((ior − 1)/(ior + 1))² (KHR_materials_ior; 0.04
// at the default 1.5) tinted by KHR_materials_specular.
VKPT_FN vec3 dielectricF0(ShadingMaterial m) {
    return min(m.iorF0 * m.specularColor, vec3(1.0f));
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

// Solid-angle pdf of the direction reflected about a visible normal:
// G1(wo) D(h) / (4 cos θo) with G1 = 2 cos θo / (cos θo + root(wo)), i.e. D / (2 (cos θo + root)).
VKPT_FN float ggxReflectionPdf(vec3 wo, vec3 h, float alpha) {
    return ggxDistribution(h, alpha) / (2.0f * (wo.z + smithRoot(wo, alpha)));
}

// A GGX normal visible from wo: Heitz, "Sampling the GGX Distribution of Visible Normals",
// JCGT 7(4), 2018. Stretching by 1/α turns the microsurface into the unit hemisphere; its
// visible normals are the projection of a uniform disk point onto it, the disk's half beyond
// the silhouette of wo squeezed so that the projected area is right; then unstretch.
VKPT_FN vec3 sampleGgxVisibleNormal(vec3 wo, float alpha, vec2 u) {
    vec3 v = normalize(vec3(alpha * wo.x, alpha * wo.y, wo.z));
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
    return normalize(vec3(alpha * n.x, alpha * n.y, max(0.0f, n.z)));
}

// f without the cosine. The Lambertian material ignores wo, as the Lambertian path always did
// (an interpolated shading normal may put wo slightly below it); the metallic-roughness BRDF is
// 0 unless both directions are above the shading normal's plane.
VKPT_FN vec3 evaluateBsdf(ShadingMaterial m, vec3 wo, vec3 wi) {
    if (!m.metallicRoughness) return wi.z > 0.0f ? m.baseColor * VKPT_INV_PI : vec3(0.0f);
    vec3 glass = vec3(0.0f); // for wi on either side; delta lobes excluded
    if (m.transmission > 0.0f) glass = evaluateDielectric(glassLobeOf(m), wo, wi);
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return glassLobeProbability(m) * glass;
    vec3 h = normalize(wo + wi);
    // V·H and L·H are equal in exact arithmetic; the rounding of h makes them differ by
    // (wo − wi)·δh, which near retro-reflection is ulps of 1, not of V·H. Their mean cancels
    // that error and is symmetric, so f(wo, wi) and f(wi, wo) agree to the last bit.
    float fresnelWeight = schlickWeight(0.5f * (dot(wo, h) + dot(wi, h)));
    float specular = ggxDistribution(h, m.alpha) * ggxVisibility(wo, wi, m.alpha);
    vec3 metal = specular * (m.baseColor + (vec3(1.0f) - m.baseColor) * fresnelWeight);
    vec3 f0 = dielectricF0(m);
    vec3 fresnel = f0 + (vec3(1.0f) - f0) * fresnelWeight;
    vec3 dielectric = m.baseColor * VKPT_INV_PI * (1.0f - m.specular * maxComponent(fresnel)) +
                      specular * m.specular * fresnel;
    if (m.transmission > 0.0f) dielectric = mix(dielectric, glass, m.transmission);
    return mix(dielectric, metal, m.metallic);
}

// Probability of sampling the GGX lobe rather than the cosine-weighted diffuse one: each lobe's
// weight estimated at wo by Schlick's Fresnel at cos θo (the specular albedo ignoring shadowing;
// the diffuse albedo times the dielectric's 1 − s·max F), by luminance. A lobe that cannot
// contribute (no diffuse: metallic 1 or a black base; no specular: metallic 0 and F0·s = 0)
// is never sampled; when both can, the probability stays in [0.1, 0.9].
VKPT_FN float specularLobeProbability(ShadingMaterial m, float cosThetaO) {
    float fresnelWeight = schlickWeight(cosThetaO);
    vec3 dielectricFresnel = schlickFresnel(dielectricF0(m), cosThetaO);
    vec3 metalFresnel = m.baseColor + (vec3(1.0f) - m.baseColor) * fresnelWeight;
    float specularWeight =
        mix(m.specular * luminance(dielectricFresnel), luminance(metalFresnel), m.metallic);
    float diffuseWeight = (1.0f - m.metallic) * luminance(m.baseColor) *
                          max(0.0f, 1.0f - m.specular * maxComponent(dielectricFresnel));
    bool hasSpecular = m.metallic > 0.0f || m.specular * maxComponent(dielectricF0(m)) > 0.0f;
    bool hasDiffuse = diffuseWeight > 0.0f;
    if (!hasDiffuse) return hasSpecular ? 1.0f : 0.0f;
    if (!hasSpecular) return 0.0f;
    float p = specularWeight / max(specularWeight + diffuseWeight, 1e-30f);
    return clamp(p, VKPT_MIN_LOBE_PROBABILITY, 1.0f - VKPT_MIN_LOBE_PROBABILITY);
}

// The one-sample mixture's pdf for wi: both lobes count, whichever drew it, so that MIS against
// light sampling weighs the direction by the density it really had.
VKPT_FN float mixtureBsdfPdf(ShadingMaterial m, vec3 wo, vec3 wi, float specularProbability) {
    float diffusePdf = wi.z * VKPT_INV_PI;
    float specularPdf = ggxReflectionPdf(wo, normalize(wo + wi), m.alpha);
    return mix(diffusePdf, specularPdf, specularProbability);
}

// With glass, the mixture is glass with probability glassLobeProbability, the opaque lobes
// otherwise (their pdf is 0 below the surface, and a smooth glass's is 0 everywhere).
VKPT_FN float bsdfPdf(ShadingMaterial m, vec3 wo, vec3 wi) {
    if (!m.metallicRoughness) return cosineHemispherePdf(wi.z);
    float glassProbability = glassLobeProbability(m);
    float glass = glassProbability > 0.0f ? dielectricPdf(glassLobeOf(m), wo, wi) : 0.0f;
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return glassProbability * glass;
    float opaque = mixtureBsdfPdf(m, wo, wi, specularLobeProbability(m, wo.z));
    return glassProbability > 0.0f ? mix(opaque, glass, glassProbability) : opaque;
}

struct BsdfSample {
    vec3 direction; // local frame
    float pdf;      // solid angle, bsdfPdf(m, wo, direction)
    vec3 weight;    // f · |cos θi| / pdf
    bool valid;
    bool delta; // a delta lobe (smooth glass): pdf is the discrete probability of the choice
};

VKPT_FN BsdfSample invalidBsdfSample() {
    BsdfSample s;
    s.direction = vec3(0.0f, 0.0f, 1.0f);
    s.pdf = 0.0f;
    s.weight = vec3(0.0f);
    s.valid = false;
    s.delta = false;
    return s;
}

// The glass lobe, chosen with probability glassProbability; uChoice picks reflection or
// refraction. A delta sample's weight is the lobe's own (its share of the material cancels
// against the probability of choosing it); a rough one is weighed by the whole mixture.
VKPT_FN BsdfSample sampleGlassLobe(ShadingMaterial m, vec3 wo, vec2 u, float uChoice,
                                   float glassProbability) {
    BsdfSample s = invalidBsdfSample();
    DielectricLobe lobe = glassLobeOf(m);
    DielectricSample d = sampleDielectric(lobe, wo, u, uChoice);
    if (!d.valid) return s;
    s.direction = d.direction;
    s.delta = dielectricIsDelta(lobe);
    s.pdf = s.delta ? glassProbability * d.pdf : bsdfPdf(m, wo, d.direction);
    if (!(s.pdf > 0.0f)) return s;
    s.weight = s.delta ? d.weight : evaluateBsdf(m, wo, d.direction) * (abs(d.direction.z) / s.pdf);
    s.valid = true;
    return s;
}

// uDirection places the direction within the lobe, uLobe picks the lobe (metallic-roughness
// only). A GGX sample reflected below the surface is invalid: the path ends there, which is the
// energy single-scattering microfacet models lose by design.
VKPT_FN BsdfSample sampleBsdf(ShadingMaterial m, vec3 wo, vec2 uDirection, float uLobe) {
    BsdfSample s = invalidBsdfSample();
    if (!m.metallicRoughness) {
        s.direction = sampleCosineHemisphere(uDirection);
        s.pdf = cosineHemispherePdf(s.direction.z);
        s.weight = m.baseColor; // (ρ/π)·cos θ / (cos θ/π), exactly
        s.valid = s.pdf > 0.0f;
        return s;
    }
    if (!(wo.z > 0.0f)) return s;
    float glassProbability = glassLobeProbability(m);
    if (glassProbability > 0.0f) {
        if (uLobe < glassProbability)
            return sampleGlassLobe(m, wo, uDirection, uLobe / glassProbability, glassProbability);
        uLobe = (uLobe - glassProbability) / (1.0f - glassProbability);
    }
    float specularProbability = specularLobeProbability(m, wo.z);
    vec3 wi;
    if (uLobe < specularProbability) {
        vec3 h = sampleGgxVisibleNormal(wo, m.alpha, uDirection);
        wi = normalize(2.0f * dot(wo, h) * h - wo);
    } else {
        wi = sampleCosineHemisphere(uDirection);
    }
    if (!(wi.z > 0.0f)) return s;
    float pdf = mixtureBsdfPdf(m, wo, wi, specularProbability);
    if (glassProbability > 0.0f)
        pdf = mix(pdf, dielectricPdf(glassLobeOf(m), wo, wi), glassProbability);
    if (!(pdf > 0.0f)) return s;
    s.direction = wi;
    s.pdf = pdf;
    s.weight = evaluateBsdf(m, wo, wi) * (wi.z / pdf);
    s.valid = true;
    return s;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_BSDF_H
