// bsdf.h — the glTF 2.0 metallic-roughness BRDF (glTF 2.0 specification, Appendix B, with
// KHR_materials_specular, KHR_materials_sheen and KHR_materials_clearcoat), layered so that it
// never reflects more than it receives: evaluation, pdf and importance sampling in the local
// shading frame, where z is the shading normal and both directions point away from the surface.
//
//   base       = mix(dielectric, metal, metallic)
//   metal      = ggx · (baseColor + (1 − baseColor)(1 − V·H)^5)
//   dielectric = s · F · ggx + baseColor/π · (1 − Es(μo))(1 − Es(μi)) / (1 − Es_avg)
//   sheened    = sheenColor · charlie + (1 − max(sheenColor) · Esh(μo)) · base
//                (charlie normalised where its albedo exceeds 1, see evaluateSheen)
//   f          = clearcoat · Fc · ggx_c + (1 − clearcoat · Ec(μo)) · sheened
//
// ggx is D G2 / (4 μo μi) (ggx.h), F Schlick's with F0 = min(0.04 specularColor, 1), Fc the
// clearcoat's with F0 = 0.04 (IOR 1.5), charlie the sheen lobe (sheen.h), and each E the
// directional albedo of the layer above, from the tables of albedo_tables.h: the albedo
// scaling of Kulla and Conty 2017 ("Revisiting Physically Based Shading at Imageworks") that
// OpenPBR and Dassault's Enterprise PBR use for layers. It replaces the glTF sample code's
// coupling by 1 − F(V·H), which lets a white dielectric reflect up to 1.68 times what it
// receives at grazing views (docs/scene-model.md has the furnace figures).
//
// Two forms, chosen for what each is exact for:
//  - The diffuse base under its specular layer takes the reciprocal form
//    (1 − E(μo))(1 − E(μi)) / (1 − E_avg), E_avg = 2∫E(μ)μ dμ: for a Lambertian base its
//    albedo is exactly (1 − E(μo)) ρ, so a white dielectric reflects exactly 1, and f stays
//    reciprocal like the rest of the base.
//  - Sheen and clearcoat lie over a base that is glossy (metal, or the dielectric's own
//    highlight). The reciprocal form then gains: over a white mirror, clearcoat's
//    (1 − E(1))² / (1 − E_avg) is 1.015 at normal incidence. They take the one-sided form
//    (1 − E(μo)), whose albedo E_layer(μo) + (1 − E_layer(μo)) A_below is at most 1 for any
//    base with A_below ≤ 1. The price is reciprocity, which a path tracer that only traces
//    from the camera does not use: both renderers evaluate f(wo = towards the camera, wi).
//
// A material without MATERIAL_METALLIC_ROUGHNESS is Lambertian and keeps the exact arithmetic
// of the Lambertian path (docs/scene-model.md), so scenes made only of it render as before.
#ifndef VKPT_BSDF_H
#define VKPT_BSDF_H

#include "albedo_lookup.h"
#include "ggx.h"
#include "host_device.h"
#include "sampling.h"
#include "sheen.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// The smallest probability of a lobe that can contribute: a white dielectric at normal
// incidence estimates 0.04 for its highlight, and a highlight sampled 25 times less often than
// the diffuse lobe is noisy; the floor costs each other lobe at most 10 % of its samples.
#define VKPT_MIN_LOBE_PROBABILITY 0.1f

// KHR_materials_clearcoat's layer is a dielectric of IOR 1.5: F0 = ((1.5 − 1)/(1.5 + 1))².
#define VKPT_CLEARCOAT_F0 0.04f

struct ShadingMaterial {
    vec3 baseColor;
    float metallic;
    vec3 specularColor;     // KHR_materials_specular colour
    float specular;         // KHR_materials_specular factor s
    float alpha;            // GGX α = roughness², at least VKPT_MIN_GGX_ALPHA
    bool metallicRoughness; // false: the Lambertian material
    float clearcoat;        // KHR_materials_clearcoat factor × texture; 0: no clearcoat
    float clearcoatAlpha;   // GGX α of the clearcoat
    vec3 sheenColor;        // KHR_materials_sheen colour × texture; 0: no sheen
    float sheenAlpha;       // Charlie α = sheenRoughness², at least VKPT_MIN_SHEEN_ALPHA
};

// roughness is perceptual; it is clamped to [0, 1] (the glTF range) before squaring. No
// clearcoat, no sheen: withClearcoat and withSheen add them.
VKPT_FN ShadingMaterial makeShadingMaterial(vec3 baseColor, float metallic, float roughness,
                                            float specular, vec3 specularColor,
                                            bool metallicRoughness) {
    ShadingMaterial m;
    m.baseColor = baseColor;
    m.metallic = metallic;
    m.specularColor = specularColor;
    m.specular = specular;
    m.alpha = ggxAlphaOf(roughness);
    m.metallicRoughness = metallicRoughness;
    m.clearcoat = 0.0f;
    m.clearcoatAlpha = VKPT_MIN_GGX_ALPHA;
    m.sheenColor = vec3(0.0f);
    m.sheenAlpha = 1.0f;
    return m;
}

// factor in [0, 1] (KHR_materials_clearcoat), roughness perceptual.
VKPT_FN ShadingMaterial withClearcoat(ShadingMaterial m, float factor, float roughness) {
    m.clearcoat = clamp(factor, 0.0f, 1.0f);
    m.clearcoatAlpha = ggxAlphaOf(roughness);
    return m;
}

// color in [0, 1] per channel (KHR_materials_sheen), roughness perceptual.
VKPT_FN ShadingMaterial withSheen(ShadingMaterial m, vec3 color, float roughness) {
    m.sheenColor = clamp(color, vec3(0.0f), vec3(1.0f));
    m.sheenAlpha = sheenAlphaOf(roughness);
    return m;
}

VKPT_FN bool hasClearcoat(ShadingMaterial m) {
    return m.clearcoat > 0.0f;
}

VKPT_FN bool hasSheen(ShadingMaterial m) {
    return maxComponent(m.sheenColor) > 0.0f;
}

// ---------------------------------------------------------------------------------------------
// The opaque dielectric: KHR_materials_specular's GGX layer over a Lambertian base.

// The dielectric's normal-incidence reflectance: IOR 1.5 (0.04) tinted by KHR_materials_specular.
VKPT_FN vec3 dielectricF0(ShadingMaterial m) {
    return min(0.04f * m.specularColor, vec3(1.0f));
}

// What the specular layer reflects at cos θ, per channel: s (F0 E + (1 − F0) E_w), exact for
// Schlick's Fresnel, which is linear in F0 (albedo_tables.h).
VKPT_FN vec3 dielectricSpecularAlbedo(ShadingMaterial m, float cosTheta) {
    vec3 f0 = dielectricF0(m);
    return m.specular * (f0 * ggxAlbedo(cosTheta, m.alpha) +
                         (vec3(1.0f) - f0) * ggxFresnelAlbedo(cosTheta, m.alpha));
}

VKPT_FN vec3 dielectricSpecularAverageAlbedo(ShadingMaterial m) {
    vec3 f0 = dielectricF0(m);
    return m.specular *
           (f0 * ggxAverageAlbedo(m.alpha) + (vec3(1.0f) - f0) * ggxFresnelAverageAlbedo(m.alpha));
}

// The share of light the specular layer leaves to the diffuse base, reciprocally:
// (1 − E(μo))(1 − E(μi)) / (1 − E_avg). Where the layer reflects (almost) everything on
// average, the base receives nothing.
VKPT_FN vec3 diffuseTransmittance(ShadingMaterial m, float cosThetaO, float cosThetaI) {
    vec3 outgoing = max(vec3(1.0f) - dielectricSpecularAlbedo(m, cosThetaO), vec3(0.0f));
    vec3 incoming = max(vec3(1.0f) - dielectricSpecularAlbedo(m, cosThetaI), vec3(0.0f));
    vec3 average = vec3(1.0f) - dielectricSpecularAverageAlbedo(m);
    vec3 result;
    result.x = average.x > 1e-6f ? outgoing.x * incoming.x / average.x : 0.0f;
    result.y = average.y > 1e-6f ? outgoing.y * incoming.y / average.y : 0.0f;
    result.z = average.z > 1e-6f ? outgoing.z * incoming.z / average.z : 0.0f;
    return result;
}

// ggx is D G2 / (4 μo μi) at the half vector, fresnelWeight Schlick's (1 − V·H)^5 there.
VKPT_FN vec3 evaluateOpaqueDielectric(ShadingMaterial m, vec3 wo, vec3 wi, float ggx,
                                      float fresnelWeight) {
    vec3 f0 = dielectricF0(m);
    vec3 fresnel = f0 + (vec3(1.0f) - f0) * fresnelWeight;
    return m.specular * ggx * fresnel +
           m.baseColor * VKPT_INV_PI * diffuseTransmittance(m, wo.z, wi.z);
}

// ---------------------------------------------------------------------------------------------
// The metal: the GGX lobe with Schlick's Fresnel of F0 = baseColor.

VKPT_FN vec3 evaluateMetal(ShadingMaterial m, float ggx, float fresnelWeight) {
    return ggx * (m.baseColor + (vec3(1.0f) - m.baseColor) * fresnelWeight);
}

VKPT_FN vec3 metalAlbedo(ShadingMaterial m, float cosTheta) {
    return m.baseColor * ggxAlbedo(cosTheta, m.alpha) +
           (vec3(1.0f) - m.baseColor) * ggxFresnelAlbedo(cosTheta, m.alpha);
}

// ---------------------------------------------------------------------------------------------
// The layers above the base.

// What the clearcoat reflects at cos θ: clearcoat × (0.04 E + 0.96 E_w) at its α.
VKPT_FN float clearcoatAlbedo(ShadingMaterial m, float cosTheta) {
    return m.clearcoat *
           (VKPT_CLEARCOAT_F0 * ggxAlbedo(cosTheta, m.clearcoatAlpha) +
            (1.0f - VKPT_CLEARCOAT_F0) * ggxFresnelAlbedo(cosTheta, m.clearcoatAlpha));
}

VKPT_FN float evaluateClearcoat(ShadingMaterial m, vec3 wo, vec3 wi) {
    vec3 h = normalize(wo + wi);
    float fresnel =
        VKPT_CLEARCOAT_F0 + (1.0f - VKPT_CLEARCOAT_F0) * halfVectorFresnelWeight(wo, wi, h);
    return m.clearcoat * fresnel * ggxReflection(wo, wi, h, m.clearcoatAlpha);
}

// Neubelt and Pettineo's visibility is no masking function: with Charlie's D the white lobe's
// albedo reaches 4.0 at grazing views for sheenRoughness 0.1, and exceeds 1 below about 0.45
// (albedo_tables.h). The lobe is divided by max(1, E(μo)), so that it never reflects more than
// it receives; where E ≤ 1 it is the specification's lobe unchanged.
VKPT_FN float sheenLobeAlbedo(ShadingMaterial m, float cosThetaO) {
    return sheenAlbedo(cosThetaO, m.sheenAlpha);
}

VKPT_FN vec3 evaluateSheen(ShadingMaterial m, vec3 wo, vec3 wi) {
    return m.sheenColor *
           (sheenReflection(wo, wi, m.sheenAlpha) / max(1.0f, sheenLobeAlbedo(m, wo.z)));
}

// What the layers below lose to the sheen: max(sheenColor) · min(E, 1), the largest channel's
// share (KHR_materials_sheen's albedo scaling), of the normalised lobe.
VKPT_FN float sheenAlbedoBound(ShadingMaterial m, float cosThetaO) {
    return maxComponent(m.sheenColor) * min(sheenLobeAlbedo(m, cosThetaO), 1.0f);
}

// ---------------------------------------------------------------------------------------------
// The whole BRDF.

VKPT_FN vec3 evaluateBase(ShadingMaterial m, vec3 wo, vec3 wi) {
    vec3 h = normalize(wo + wi);
    float fresnelWeight = halfVectorFresnelWeight(wo, wi, h);
    float ggx = ggxReflection(wo, wi, h, m.alpha);
    vec3 dielectric = evaluateOpaqueDielectric(m, wo, wi, ggx, fresnelWeight);
    vec3 metal = evaluateMetal(m, ggx, fresnelWeight);
    return mix(dielectric, metal, m.metallic);
}

// f without the cosine. The Lambertian material ignores wo, as the Lambertian path always did
// (an interpolated shading normal may put wo slightly below it); the metallic-roughness BRDF is
// 0 unless both directions are above the shading normal's plane.
VKPT_FN vec3 evaluateBsdf(ShadingMaterial m, vec3 wo, vec3 wi) {
    if (!m.metallicRoughness) return wi.z > 0.0f ? m.baseColor * VKPT_INV_PI : vec3(0.0f);
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return vec3(0.0f);
    vec3 f = evaluateBase(m, wo, wi);
    if (hasSheen(m)) {
        f = evaluateSheen(m, wo, wi) + (1.0f - sheenAlbedoBound(m, wo.z)) * f;
    }
    if (hasClearcoat(m)) {
        f = vec3(evaluateClearcoat(m, wo, wi)) + (1.0f - clearcoatAlbedo(m, wo.z)) * f;
    }
    return f;
}

// ---------------------------------------------------------------------------------------------
// Sampling: one lobe drawn with probability by its estimated albedo at wo, the direction from
// that lobe's sampler, the pdf the mixture's.

// The probability of each lobe's sampler: the diffuse lobe's cosine hemisphere, the base's GGX
// visible normals (dielectric highlight and metal share α), the clearcoat's, and the sheen's
// uniform hemisphere. They sum to 1.
struct LobeProbabilities {
    float diffuse;
    float specular;
    float clearcoat;
    float sheen;
};

// Each lobe's weight is its albedo at wo from the tables, by luminance, times what the layers
// above leave it. A lobe that cannot contribute (no diffuse: metallic 1 or a black base; no
// specular: metallic 0 and F0·s = 0; no clearcoat or sheen) is never sampled; each of the k
// lobes that can gets VKPT_MIN_LOBE_PROBABILITY plus its share of the rest. A material that
// reflects nothing samples the diffuse lobe, with weight 0.
VKPT_FN LobeProbabilities lobeProbabilities(ShadingMaterial m, float cosThetaO) {
    float clearcoatWeight = 0.0f;
    float sheenWeight = 0.0f;
    float below = 1.0f; // what the layers above leave the base, at wo
    if (hasClearcoat(m)) {
        clearcoatWeight = clearcoatAlbedo(m, cosThetaO);
        below = 1.0f - clearcoatWeight;
    }
    if (hasSheen(m)) {
        sheenWeight = below * luminance(m.sheenColor) * min(sheenLobeAlbedo(m, cosThetaO), 1.0f);
        below *= 1.0f - sheenAlbedoBound(m, cosThetaO);
    }
    vec3 dielectricSpecular = dielectricSpecularAlbedo(m, cosThetaO);
    float specularWeight = below * mix(luminance(dielectricSpecular),
                                       luminance(metalAlbedo(m, cosThetaO)), m.metallic);
    if (!(m.metallic > 0.0f || m.specular * maxComponent(dielectricF0(m)) > 0.0f))
        specularWeight = 0.0f;
    float diffuseWeight = below * (1.0f - m.metallic) *
                          luminance(m.baseColor * max(vec3(1.0f) - dielectricSpecular, vec3(0.0f)));
    float lobes = (diffuseWeight > 0.0f ? 1.0f : 0.0f) + (specularWeight > 0.0f ? 1.0f : 0.0f) +
                  (clearcoatWeight > 0.0f ? 1.0f : 0.0f) + (sheenWeight > 0.0f ? 1.0f : 0.0f);
    LobeProbabilities p;
    p.diffuse = 0.0f;
    p.specular = 0.0f;
    p.clearcoat = 0.0f;
    p.sheen = 0.0f;
    if (lobes == 0.0f) {
        p.diffuse = 1.0f;
        return p;
    }
    // With one lobe its probability is 1 exactly, not 0.1 + 0.9 w/w rounded.
    float minimum = lobes > 1.0f ? VKPT_MIN_LOBE_PROBABILITY : 0.0f;
    float share =
        (1.0f - lobes * minimum) / (diffuseWeight + specularWeight + clearcoatWeight + sheenWeight);
    if (diffuseWeight > 0.0f) p.diffuse = lobes > 1.0f ? minimum + share * diffuseWeight : 1.0f;
    if (specularWeight > 0.0f) p.specular = lobes > 1.0f ? minimum + share * specularWeight : 1.0f;
    if (clearcoatWeight > 0.0f)
        p.clearcoat = lobes > 1.0f ? minimum + share * clearcoatWeight : 1.0f;
    if (sheenWeight > 0.0f) p.sheen = lobes > 1.0f ? minimum + share * sheenWeight : 1.0f;
    return p;
}

// The one-sample mixture's pdf for wi: every lobe counts, whichever drew it, so that MIS against
// light sampling weighs the direction by the density it really had.
VKPT_FN float mixtureBsdfPdf(ShadingMaterial m, vec3 wo, vec3 wi, LobeProbabilities p) {
    vec3 h = normalize(wo + wi);
    float pdf = p.diffuse * wi.z * VKPT_INV_PI;
    if (p.specular > 0.0f) pdf += p.specular * ggxReflectionPdf(wo, h, m.alpha);
    if (p.clearcoat > 0.0f) pdf += p.clearcoat * ggxReflectionPdf(wo, h, m.clearcoatAlpha);
    if (p.sheen > 0.0f) pdf += p.sheen * uniformHemispherePdf();
    return pdf;
}

VKPT_FN float bsdfPdf(ShadingMaterial m, vec3 wo, vec3 wi) {
    if (!m.metallicRoughness) return cosineHemispherePdf(wi.z);
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    return mixtureBsdfPdf(m, wo, wi, lobeProbabilities(m, wo.z));
}

struct BsdfSample {
    vec3 direction; // local frame
    float pdf;      // solid angle, bsdfPdf(m, wo, direction)
    vec3 weight;    // f · cos θi / pdf
    bool valid;
};

VKPT_FN BsdfSample invalidBsdfSample() {
    BsdfSample s;
    s.direction = vec3(0.0f, 0.0f, 1.0f);
    s.pdf = 0.0f;
    s.weight = vec3(0.0f);
    s.valid = false;
    return s;
}

// uDirection places the direction within the lobe, uLobe picks the lobe (metallic-roughness
// only; in the order specular, clearcoat, sheen, diffuse). A GGX sample reflected below the
// surface is invalid: the path ends there, which is the energy single-scattering microfacet
// models lose by design.
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
    LobeProbabilities p = lobeProbabilities(m, wo.z);
    vec3 wi;
    if (uLobe < p.specular) {
        wi = sampleGgxReflection(wo, m.alpha, uDirection);
    } else if (uLobe < p.specular + p.clearcoat) {
        wi = sampleGgxReflection(wo, m.clearcoatAlpha, uDirection);
    } else if (uLobe < p.specular + p.clearcoat + p.sheen) {
        wi = sampleUniformHemisphere(uDirection);
    } else {
        wi = sampleCosineHemisphere(uDirection);
    }
    if (!(wi.z > 0.0f)) return s;
    float pdf = mixtureBsdfPdf(m, wo, wi, p);
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
