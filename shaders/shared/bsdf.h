// bsdf.h — the glTF 2.0 metallic-roughness BSDF (glTF 2.0 specification, Appendix B, with
// KHR_materials_specular, _ior, _transmission, _sheen and _clearcoat), layered so that it never
// reflects more than it receives: evaluation, pdf and importance sampling in the local shading
// frame, where z is the shading normal and wo points away from the surface.
//
//   base       = mix(mix(dielectric, glass, transmission), metal, metallic)
//   metal      = ggx · (baseColor + (1 − baseColor)(1 − V·H)^5)
//   dielectric = s · F · ggx + baseColor/π · (1 − Es(μo))(1 − Es(μi)) / (1 − Es_avg)
//   sheened    = sheenColor · charlie + (1 − max(sheenColor) · Esh(μo)) · base
//                (charlie normalised where its albedo exceeds 1, see evaluateSheen)
//   f          = clearcoat · Fc · ggx_c + (1 − clearcoat · Ec(μo)) · sheened
//
// ggx is D G2 / (4 μo μi) (ggx.h), F Schlick's with F0 = min(F0_ior · specularColor, 1) where
// F0_ior = ((ior − 1)/(ior + 1))² (KHR_materials_ior; 0.04 at the default 1.5), Fc the
// clearcoat's with F0 = 0.04 (IOR 1.5), charlie the sheen lobe (sheen.h), glass the dielectric
// lobe of bsdf_dielectric.h (reflection and refraction, exact Fresnel), and each E the
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
//    reciprocal like the rest of the base. Schlick's albedo is linear in F0, so the tables
//    serve every ior.
//  - Sheen and clearcoat lie over a base that is glossy (metal, glass, or the dielectric's own
//    highlight). The reciprocal form then gains: over a white mirror, clearcoat's
//    (1 − E(1))² / (1 − E_avg) is 1.015 at normal incidence. They take the one-sided form
//    (1 − E(μo)), whose albedo E_layer(μo) + (1 − E_layer(μo)) A_below is at most 1 for any
//    base with A_below ≤ 1. The price is reciprocity, which a path tracer that only traces
//    from the camera does not use: both renderers evaluate f(wo = towards the camera, wi).
//    Light the glass transmits below the surface passes the layers once, on wo's side.
//
// KHR_materials_iridescence mixes a thin film's Fresnel term (iridescence.h) into the dielectric
// highlight's and the metal's. The film's term is taken at VKPT_FILM_NODES cosines and
// interpolated between them, so that the highlight's albedo is exactly Σ F_k E_k (tables of the
// lobe weighted by each node's hat function): the diffuse base under the film then receives what
// the film's highlight really leaves, and its normalisation 1 − E_avg is the average of that
// same albedo, so the white dielectric under a film is lossless like the bare one.
//
// KHR_materials_diffuse_transmission splits the diffuse base between reflection and a Lambertian
// transmission to the other side (the extension's mix(diffuse_brdf(baseColor),
// diffuse_btdf(diffuseTransmissionColor), diffuseTransmission)), both under the specular layer:
//   diffuse(wi above) = (1 − dt) · baseColor/π · (1 − Es(μo))(1 − Es(μi)) / (1 − Es_avg)
//   diffuse(wi below) = dt · dtColor/π · (1 − Es(μo))(1 − Es(|μi|)) / (1 − Es_avg)
// so the split keeps the reciprocal form's albedo (1 − Es(μo))·ρ, now shared by the two sides,
// and the transmitted lobe is the reflected one mirrored through the surface (reciprocal under
// swapping wo and wi, both sides' layers alike). Its sampler is the mirrored cosine hemisphere.
//
// KHR_materials_anisotropy stretches the base's GGX lobe (ggx_anisotropic.h; baseGgxReflection
// and its pdf and sampler); the albedo tables then stand in at baseAlbedoAlpha's α per direction.
//
// The clearcoat may have its own normal (KHR_materials_clearcoat's clearcoatNormalTexture): its
// lobe and its albedo are then taken in that normal's frame. A material without
// MATERIAL_METALLIC_ROUGHNESS is Lambertian and keeps the exact arithmetic of the Lambertian
// path (docs/scene-model.md), so scenes made only of it render as before.
#ifndef VKPT_BSDF_H
#define VKPT_BSDF_H

#include "albedo_lookup.h"
#include "bsdf_dielectric.h"
#include "dispersion.h"
#include "ggx.h"
#include "ggx_anisotropic.h"
#include "host_device.h"
#include "iridescence.h"
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
    vec3 clearcoatNormal;   // the clearcoat's normal in this frame; (0, 0, 1): the base's
    vec3 sheenColor;        // KHR_materials_sheen colour × texture; 0: no sheen
    float sheenAlpha;       // Charlie α = sheenRoughness², at least VKPT_MIN_SHEEN_ALPHA
    // KHR_materials_transmission, _ior and _volume (bsdf_dielectric.h).
    float transmission; // share of the non-metal part that is glass; 0: opaque
    float iorF0;        // ((ior − 1)/(ior + 1))², the dielectric's F0 before specularColor
    float eta;          // ior beyond the surface / ior on wo's side; thin-walled: the ior
    bool thinWalled;    // no volume behind the surface
    // KHR_materials_anisotropy: the base's GGX lobe (dielectric highlight and metal) is
    // stretched to αt = mix(α, 1, strength²) along anisotropyDirection (unit, in this frame's
    // tangent plane) and keeps α across it (the extension's formula). 0: isotropic.
    float anisotropy;
    float alphaT;
    vec2 anisotropyDirection;
    // KHR_materials_iridescence: a thin film over the base's specular layers (dielectric
    // highlight and metal) whose Fresnel term (iridescence.h) is mixed in by `iridescence`.
    // 0: no film.
    float iridescence;
    float iridescenceIor;       // the film's index of refraction
    float iridescenceThickness; // the film's thickness in nanometres
    // KHR_materials_diffuse_transmission: the share of the diffuse base transmitted to the other
    // side, and its colour. 0: the diffuse base only reflects.
    float diffuseTransmission;
    vec3 diffuseTransmissionColor;
    // KHR_materials_dispersion: 20/V_d of the glass (dispersion.h); 0: none.
    float dispersion;
};

// roughness is perceptual; it is clamped to [0, 1] (the glTF range) before squaring. Opaque,
// ior 1.5, no clearcoat, no sheen: withClearcoat and withSheen add the layers, surface.h the
// dielectric extensions.
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
    m.clearcoatNormal = vec3(0.0f, 0.0f, 1.0f);
    m.sheenColor = vec3(0.0f);
    m.sheenAlpha = 1.0f;
    m.transmission = 0.0f;
    m.iorF0 = 0.04f; // ior 1.5
    m.eta = 1.5f;
    m.thinWalled = true;
    m.anisotropy = 0.0f;
    m.alphaT = m.alpha;
    m.anisotropyDirection = vec2(1.0f, 0.0f);
    m.iridescence = 0.0f;
    m.iridescenceIor = 1.3f;
    m.iridescenceThickness = 400.0f;
    m.diffuseTransmission = 0.0f;
    m.diffuseTransmissionColor = vec3(1.0f);
    m.dispersion = 0.0f;
    return m;
}

// factor in [0, 1] and colour (KHR_materials_diffuse_transmission).
VKPT_FN ShadingMaterial withDiffuseTransmission(ShadingMaterial m, float factor, vec3 color) {
    m.diffuseTransmission = clamp(factor, 0.0f, 1.0f);
    m.diffuseTransmissionColor = clamp(color, vec3(0.0f), vec3(1.0f));
    return m;
}

// A macro in a kernel, for the reason hasAnisotropy's note gives.
#ifdef VKPT_FEATURES_GLSL
#define hasDiffuseTransmission(m) (featureDiffuseTransmission && (m).diffuseTransmission > 0.0f)
#define hasDispersion(m)                                                                           \
    (featureDispersion && (m).dispersion > 0.0f && (m).transmission > 0.0f && !(m).thinWalled)
#else
VKPT_FN bool hasDiffuseTransmission(ShadingMaterial m) {
    return m.diffuseTransmission > 0.0f;
}
// Dispersion shows where light refracts into a volume: thin walls do not bend it.
VKPT_FN bool hasDispersion(ShadingMaterial m) {
    return m.dispersion > 0.0f && m.transmission > 0.0f && !m.thinWalled;
}
#endif

// The glass at `wavelength` (nm): the ratio of indices a refraction crosses, from the index at
// that wavelength (dispersion.h). eta ≥ 1 enters the volume (eta = ior), eta < 1 leaves it
// (1/ior). The specular layer's F0 keeps the d line's index (the extension disperses
// refraction).
VKPT_FN ShadingMaterial atWavelength(ShadingMaterial m, float wavelength) {
    bool entering = m.eta >= 1.0f;
    float iorD = entering ? m.eta : 1.0f / m.eta;
    float ior = dispersiveIor(iorD, m.dispersion, wavelength);
    m.eta = entering ? ior : 1.0f / ior;
    return m;
}

// factor in [0, 1], the film's ior and thickness in nm (KHR_materials_iridescence).
VKPT_FN ShadingMaterial withIridescence(ShadingMaterial m, float factor, float ior,
                                        float thickness) {
    m.iridescence = clamp(factor, 0.0f, 1.0f);
    m.iridescenceIor = ior;
    m.iridescenceThickness = max(thickness, 0.0f);
    return m;
}

// A macro in a kernel, for the reason hasAnisotropy's note gives.
#ifdef VKPT_FEATURES_GLSL
#define hasIridescence(m) (featureIridescence && (m).iridescence > 0.0f)
#else
VKPT_FN bool hasIridescence(ShadingMaterial m) {
    return m.iridescence > 0.0f;
}
#endif

// The base's Fresnel term for normal-incidence reflectance f0 at cosTheta = V·H, whose
// Schlick weight is schlickWeight: Schlick's, mixed with the film's by the iridescence factor
// (the extension's mix(F, F_iridescence, factor)), the film's term between its nodes.
VKPT_FN vec3 baseFresnel(ShadingMaterial m, vec3 f0, float cosTheta, float schlickWeight) {
    vec3 fresnel = f0 + (vec3(1.0f) - f0) * schlickWeight;
    if (!hasIridescence(m)) return fresnel;
    vec3 film =
        interpolatedIridescenceFresnel(m.iridescenceIor, m.iridescenceThickness, cosTheta, f0);
    return mix(fresnel, film, m.iridescence);
}

// strength in [0, 1] (KHR_materials_anisotropy), direction a unit vector in the shading frame's
// tangent plane.
VKPT_FN ShadingMaterial withAnisotropy(ShadingMaterial m, float strength, vec2 direction) {
    m.anisotropy = clamp(strength, 0.0f, 1.0f);
    m.alphaT = mix(m.alpha, 1.0f, m.anisotropy * m.anisotropy);
    m.anisotropyDirection = direction;
    return m;
}

// In a kernel, whether the scene has anisotropy is a specialisation constant
// (lib/features.glsl). It guards the anisotropic code where it is called, not inside a function,
// so that a kernel specialised without the feature drops those calls as it translates the
// SPIR-V, before inlining copies the lobe into every caller (the Cornell box's pipelines would
// otherwise take longer to create): a macro for that reason. C++ compiles every feature in.
#ifdef VKPT_FEATURES_GLSL
#define hasAnisotropy(m) (featureAnisotropy && (m).anisotropy > 0.0f)
#else
VKPT_FN bool hasAnisotropy(ShadingMaterial m) {
    return m.anisotropy > 0.0f;
}
#endif

// The base's GGX lobe, its sampler's pdf and its sampler, isotropic or anisotropic; directions
// in the shading frame.
VKPT_FN float baseGgxReflection(ShadingMaterial m, vec3 wo, vec3 wi, vec3 h) {
    if (!hasAnisotropy(m)) return ggxReflection(wo, wi, h, m.alpha);
    vec2 d = m.anisotropyDirection;
    return ggxReflectionAnisotropic(toAnisotropyFrame(d, wo), toAnisotropyFrame(d, wi),
                                    toAnisotropyFrame(d, h), vec2(m.alphaT, m.alpha));
}

VKPT_FN float baseGgxReflectionPdf(ShadingMaterial m, vec3 wo, vec3 h) {
    if (!hasAnisotropy(m)) return ggxReflectionPdf(wo, h, m.alpha);
    vec2 d = m.anisotropyDirection;
    return ggxReflectionPdfAnisotropic(toAnisotropyFrame(d, wo), toAnisotropyFrame(d, h),
                                       vec2(m.alphaT, m.alpha));
}

VKPT_FN vec3 sampleBaseGgxReflection(ShadingMaterial m, vec3 wo, vec2 u) {
    if (!hasAnisotropy(m)) return sampleGgxReflection(wo, m.alpha, u);
    vec2 d = m.anisotropyDirection;
    return fromAnisotropyFrame(
        d, sampleGgxReflectionAnisotropic(toAnisotropyFrame(d, wo), vec2(m.alphaT, m.alpha), u));
}

// The α at which the (isotropic) albedo tables stand in for the base's lobe seen from w: α
// itself, or for an anisotropic lobe the roughness projected on w's azimuth,
// √(αt² cos²φ + αb² sin²φ) with φ measured from the anisotropy direction: the α of Smith's Λ(w)
// for the stretched distribution (Heitz 2014, eq. 86), so the masking of w, which decides most
// of the albedo, is exact. At normal incidence, where φ is undefined, the geometric mean.
// tests/unit/bsdf_test.cpp measures what remains (AnisotropicFurnace...).
VKPT_FN float baseAlbedoAlpha(ShadingMaterial m, vec3 w) {
    if (!hasAnisotropy(m)) return m.alpha;
    vec3 a = toAnisotropyFrame(m.anisotropyDirection, w);
    float planar = a.x * a.x + a.y * a.y;
    float mean = sqrt(m.alphaT * m.alpha);
    if (!(planar > 0.0f)) return mean;
    return min(mean,
               sqrt((m.alphaT * m.alphaT * a.x * a.x + m.alpha * m.alpha * a.y * a.y) / planar));
}

// baseAlbedoAlpha at the k-th of 8 azimuths of the quarter circle (k + 1/2 eighths of it), for
// the azimuthal means below (α(φ) is even about both axes).
VKPT_FN float azimuthAlbedoAlpha(ShadingMaterial m, int k) {
    float phi = (float(k) + 0.5f) * (0.5f * VKPT_PI / 8.0f);
    float c = cos(phi);
    float s = sin(phi);
    return min(sqrt(m.alphaT * m.alpha),
               sqrt(m.alphaT * m.alphaT * c * c + m.alpha * m.alpha * s * s));
}

// The azimuthal mean over a hemisphere of directions of the table's cosine-weighted average
// albedo, E_avg(α(φ)), by the midpoint rule on 8 azimuths of the quarter circle: what the
// reciprocal form's normalisation 1 − E_avg needs so that the diffuse base under an anisotropic
// highlight still integrates to (1 − E(wo))·ρ. xy: F = 1 and Schlick weight tables
// (ggxAverageAlbedo, ggxFresnelAverageAlbedo).
VKPT_FN vec2 anisotropicAverageAlbedos(ShadingMaterial m) {
    vec2 sum = vec2(0.0f);
    for (int k = 0; k < 8; ++k) {
        float alpha = azimuthAlbedoAlpha(m, k);
        sum += vec2(ggxAverageAlbedo(alpha), ggxFresnelAverageAlbedo(alpha));
    }
    return sum * 0.125f;
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
// The glass: KHR_materials_transmission's share of the non-metal part.

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

// The glass lobe's share of the base.
VKPT_FN float glassShare(ShadingMaterial m) {
    return (1.0f - m.metallic) * m.transmission;
}

// ---------------------------------------------------------------------------------------------
// The opaque dielectric: KHR_materials_specular's GGX layer over a Lambertian base.

// The dielectric's normal-incidence reflectance: ((ior − 1)/(ior + 1))² (KHR_materials_ior; 0.04
// at the default 1.5) tinted by KHR_materials_specular.
VKPT_FN vec3 dielectricF0(ShadingMaterial m) {
    return min(m.iorF0 * m.specularColor, vec3(1.0f));
}

// The film's term over reflectance f0 at node k (iridescence.h).
VKPT_FN vec3 filmNodeFresnel(ShadingMaterial m, vec3 f0, int k) {
    return iridescenceFresnel(m.iridescenceIor, m.iridescenceThickness, filmNodeCosine(k), f0);
}

// The cosine-weighted average of node k's albedo over a hemisphere of directions: the table's
// for α, or for an anisotropic lobe its azimuthal mean as anisotropicAverageAlbedos takes it.
VKPT_FN float filmNodeAverage(ShadingMaterial m, int k) {
    if (!hasAnisotropy(m)) return filmNodeAverageAlbedo(k, m.alpha);
    float sum = 0.0f;
    for (int j = 0; j < 8; ++j)
        sum += filmNodeAverageAlbedo(k, azimuthAlbedoAlpha(m, j));
    return sum * 0.125f;
}

// The albedo towards w of the base's GGX lobe with the film's term over f0: Σ F_k E_k(w), exact
// for the interpolated term the lobe uses (iridescence.h, albedo_tables.h).
VKPT_FN vec3 iridescentAlbedo(ShadingMaterial m, vec3 f0, vec3 w) {
    AlbedoCell cell = albedoCell(w.z, sqrt(baseAlbedoAlpha(m, w)));
    vec3 sum = vec3(0.0f);
    for (int k = 0; k < VKPT_FILM_NODES; ++k)
        sum += filmNodeFresnel(m, f0, k) * filmNodeAlbedo(k, cell);
    return sum;
}

// The Schlick part of the specular layer's albedo (without s): F0 E + (1 − F0) E_w, exact for
// Schlick's Fresnel, which is linear in F0 (albedo_tables.h).
VKPT_FN vec3 schlickSpecularAlbedo(ShadingMaterial m, vec3 f0, vec3 w) {
    float alpha = baseAlbedoAlpha(m, w);
    return f0 * ggxAlbedo(w.z, alpha) + (vec3(1.0f) - f0) * ggxFresnelAlbedo(w.z, alpha);
}

VKPT_FN vec3 schlickSpecularAverageAlbedo(ShadingMaterial m, vec3 f0) {
    if (hasAnisotropy(m)) {
        vec2 albedos = anisotropicAverageAlbedos(m);
        return f0 * albedos.x + (vec3(1.0f) - f0) * albedos.y;
    }
    return f0 * ggxAverageAlbedo(m.alpha) + (vec3(1.0f) - f0) * ggxFresnelAverageAlbedo(m.alpha);
}

// What the specular layer reflects at cos θ, per channel: s times the Schlick albedo, mixed with
// the film's by the iridescence factor.
VKPT_FN vec3 dielectricSpecularAlbedo(ShadingMaterial m, vec3 w) {
    vec3 f0 = dielectricF0(m);
    vec3 albedo = schlickSpecularAlbedo(m, f0, w);
    if (hasIridescence(m)) albedo = mix(albedo, iridescentAlbedo(m, f0, w), m.iridescence);
    return m.specular * albedo;
}

// The specular layer's albedo towards wo and wi and its cosine-weighted average, which the
// diffuse base's reciprocal form needs together. Under a film the three share the film's node
// values, computed once.
struct SpecularAlbedos {
    vec3 outgoing;
    vec3 incoming;
    vec3 average;
};

VKPT_FN SpecularAlbedos dielectricSpecularAlbedos(ShadingMaterial m, vec3 wo, vec3 wi) {
    vec3 f0 = dielectricF0(m);
    SpecularAlbedos a;
    a.outgoing = schlickSpecularAlbedo(m, f0, wo);
    a.incoming = schlickSpecularAlbedo(m, f0, wi);
    a.average = schlickSpecularAverageAlbedo(m, f0);
    if (hasIridescence(m)) {
        AlbedoCell cellO = albedoCell(wo.z, sqrt(baseAlbedoAlpha(m, wo)));
        AlbedoCell cellI = albedoCell(wi.z, sqrt(baseAlbedoAlpha(m, wi)));
        SpecularAlbedos film;
        film.outgoing = vec3(0.0f);
        film.incoming = vec3(0.0f);
        film.average = vec3(0.0f);
        for (int k = 0; k < VKPT_FILM_NODES; ++k) {
            vec3 fresnel = filmNodeFresnel(m, f0, k);
            film.outgoing += fresnel * filmNodeAlbedo(k, cellO);
            film.incoming += fresnel * filmNodeAlbedo(k, cellI);
            film.average += fresnel * filmNodeAverage(m, k);
        }
        a.outgoing = mix(a.outgoing, film.outgoing, m.iridescence);
        a.incoming = mix(a.incoming, film.incoming, m.iridescence);
        a.average = mix(a.average, film.average, m.iridescence);
    }
    a.outgoing *= m.specular;
    a.incoming *= m.specular;
    a.average *= m.specular;
    return a;
}

// The share of light the specular layer leaves to the diffuse base, reciprocally:
// (1 − E(μo))(1 − E(μi)) / (1 − E_avg). Where the layer reflects (almost) everything on
// average, the base receives nothing.
VKPT_FN vec3 diffuseTransmittance(ShadingMaterial m, vec3 wo, vec3 wi) {
    SpecularAlbedos albedos = dielectricSpecularAlbedos(m, wo, wi);
    vec3 outgoing = max(vec3(1.0f) - albedos.outgoing, vec3(0.0f));
    vec3 incoming = max(vec3(1.0f) - albedos.incoming, vec3(0.0f));
    vec3 average = vec3(1.0f) - albedos.average;
    vec3 result;
    result.x = average.x > 1e-6f ? outgoing.x * incoming.x / average.x : 0.0f;
    result.y = average.y > 1e-6f ? outgoing.y * incoming.y / average.y : 0.0f;
    result.z = average.z > 1e-6f ? outgoing.z * incoming.z / average.z : 0.0f;
    return result;
}

// The diffuse base's reflectance: baseColor, less the share KHR_materials_diffuse_transmission
// sends to the other side.
VKPT_FN vec3 diffuseReflectance(ShadingMaterial m) {
    if (!hasDiffuseTransmission(m)) return m.baseColor;
    return (1.0f - m.diffuseTransmission) * m.baseColor;
}

// ggx is D G2 / (4 μo μi) at the half vector, cosVH its V·H and fresnelWeight Schlick's
// (1 − V·H)^5 there.
VKPT_FN vec3 evaluateOpaqueDielectric(ShadingMaterial m, vec3 wo, vec3 wi, float ggx, float cosVH,
                                      float fresnelWeight) {
    vec3 fresnel = baseFresnel(m, dielectricF0(m), cosVH, fresnelWeight);
    return m.specular * ggx * fresnel +
           diffuseReflectance(m) * VKPT_INV_PI * diffuseTransmittance(m, wo, wi);
}

// The base's diffuse lobes, wi below the surface: the Lambertian transmission, the reflected
// lobe's mirror image, in the opaque dielectric's share (what metal and glass leave it).
VKPT_FN vec3 evaluateDiffuseTransmission(ShadingMaterial m, vec3 wo, vec3 wi) {
    vec3 mirrored = mirroredThroughSurface(wi);
    float share = (1.0f - m.metallic) * (1.0f - m.transmission) * m.diffuseTransmission;
    return (share * VKPT_INV_PI) * m.diffuseTransmissionColor *
           diffuseTransmittance(m, wo, mirrored);
}

// ---------------------------------------------------------------------------------------------
// The metal: the GGX lobe with Schlick's Fresnel of F0 = baseColor.

VKPT_FN vec3 evaluateMetal(ShadingMaterial m, float ggx, float cosVH, float fresnelWeight) {
    return ggx * baseFresnel(m, m.baseColor, cosVH, fresnelWeight);
}

// What the base's GGX lobe with its Fresnel term over f0 reflects towards w, as the lobe
// sampler weighs it (lobeProbabilities): exact for Schlick's term; under a film, the film's term
// at the view on the Schlick albedo, one evaluation of the film where iridescentAlbedo takes 16.
// The sampler needs weights, not albedos: any positive estimate keeps the mixture unbiased.
VKPT_FN vec3 specularAlbedoEstimate(ShadingMaterial m, vec3 f0, vec3 w) {
    vec3 albedo = schlickSpecularAlbedo(m, f0, w);
    if (!hasIridescence(m)) return albedo;
    vec3 film = iridescenceFresnel(m.iridescenceIor, m.iridescenceThickness, w.z, f0);
    return mix(albedo, schlickSpecularAlbedo(m, film, w), m.iridescence);
}

// ---------------------------------------------------------------------------------------------
// The layers above the base.

// A direction of the shading frame in the clearcoat normal's frame. With the clearcoat on the
// shading normal (no clearcoatNormalTexture), the basis is the identity and w is returned
// unchanged, so an unmapped clearcoat costs no rounding.
VKPT_FN vec3 toClearcoatFrame(ShadingMaterial m, vec3 w) {
    if (m.clearcoatNormal.z == 1.0f) return w;
    return worldToBasis(makeBasis(m.clearcoatNormal), w);
}

VKPT_FN vec3 fromClearcoatFrame(ShadingMaterial m, vec3 w) {
    if (m.clearcoatNormal.z == 1.0f) return w;
    return basisToWorld(makeBasis(m.clearcoatNormal), w);
}

// What the clearcoat reflects at cos θ to its normal: clearcoat × (0.04 E + 0.96 E_w) at its α.
VKPT_FN float clearcoatAlbedo(ShadingMaterial m, float cosTheta) {
    return m.clearcoat *
           (VKPT_CLEARCOAT_F0 * ggxAlbedo(cosTheta, m.clearcoatAlpha) +
            (1.0f - VKPT_CLEARCOAT_F0) * ggxFresnelAlbedo(cosTheta, m.clearcoatAlpha));
}

// What the clearcoat reflects towards wo (shading frame), which is what it takes from the
// layers below.
VKPT_FN float clearcoatAlbedoAt(ShadingMaterial m, vec3 wo) {
    return clearcoatAlbedo(m, dot(wo, m.clearcoatNormal));
}

// wo and wi in the clearcoat's frame; 0 unless both are above its normal.
VKPT_FN float evaluateClearcoat(ShadingMaterial m, vec3 wo, vec3 wi) {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    vec3 h = normalize(wo + wi);
    float fresnel =
        VKPT_CLEARCOAT_F0 + (1.0f - VKPT_CLEARCOAT_F0) * halfVectorFresnelWeight(wo, wi, h);
    return m.clearcoat * fresnel * ggxReflection(wo, wi, h, m.clearcoatAlpha);
}

// The clearcoat's f in the shading frame. A tilted coat (clearcoatNormalTexture) reflects like a
// facet of that tilt: its f·cos is f_c·(wi·n_c), the cosine to its own normal, so f here is
// f_c·(wi·n_c)/(wi·n). Then the coat reflects at most E_c(wo·n_c), what it takes from the layers
// below; with the shading frame's cosine a coat tilted 30° over a white dielectric returned up to
// 6 % more than it received (tests/unit/layered_bsdf_test.cpp). wi above the shading normal.
VKPT_FN float clearcoatInShadingFrame(ShadingMaterial m, vec3 wo, vec3 wi) {
    vec3 wiC = toClearcoatFrame(m, wi);
    float f = evaluateClearcoat(m, toClearcoatFrame(m, wo), wiC);
    if (m.clearcoatNormal.z == 1.0f) return f;
    return f * (max(wiC.z, 0.0f) / wi.z);
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

// The share of light at wo that the clearcoat and the sheen leave to the base.
VKPT_FN float layersTransmittance(ShadingMaterial m, vec3 wo) {
    float t = 1.0f;
    if (hasSheen(m)) t *= 1.0f - sheenAlbedoBound(m, wo.z);
    if (hasClearcoat(m)) t *= 1.0f - clearcoatAlbedoAt(m, wo);
    return t;
}

// ---------------------------------------------------------------------------------------------
// The whole BSDF.

// The base for wo and wi above the surface; glass is the glass lobe's value there.
VKPT_FN vec3 evaluateBase(ShadingMaterial m, vec3 wo, vec3 wi, vec3 glass) {
    vec3 h = normalize(wo + wi);
    float fresnelWeight = halfVectorFresnelWeight(wo, wi, h);
    float cosVH = 0.5f * (dot(wo, h) + dot(wi, h)); // as halfVectorFresnelWeight takes it
    float ggx = baseGgxReflection(m, wo, wi, h);
    vec3 dielectric = evaluateOpaqueDielectric(m, wo, wi, ggx, cosVH, fresnelWeight);
    if (m.transmission > 0.0f) dielectric = mix(dielectric, glass, m.transmission);
    vec3 metal = evaluateMetal(m, ggx, cosVH, fresnelWeight);
    return mix(dielectric, metal, m.metallic);
}

// f without the cosine. The Lambertian material ignores wo, as the Lambertian path always did
// (an interpolated shading normal may put wo slightly below it). The metallic-roughness BSDF
// reflects only with both directions above the shading normal's plane; below it, only its glass
// transmits (delta lobes excluded: they have no value to evaluate).
VKPT_FN vec3 evaluateBsdf(ShadingMaterial m, vec3 wo, vec3 wi) {
    if (!m.metallicRoughness) return wi.z > 0.0f ? m.baseColor * VKPT_INV_PI : vec3(0.0f);
    vec3 glass = vec3(0.0f); // for wi on either side
    if (m.transmission > 0.0f) glass = evaluateDielectric(glassLobeOf(m), wo, wi);
    if (!(wo.z > 0.0f)) return glassShare(m) * glass;
    if (!(wi.z > 0.0f)) {
        vec3 transmitted = glassShare(m) * glass;
        if (hasDiffuseTransmission(m)) transmitted += evaluateDiffuseTransmission(m, wo, wi);
        return layersTransmittance(m, wo) * transmitted;
    }
    vec3 f = evaluateBase(m, wo, wi, glass);
    if (hasSheen(m)) {
        f = evaluateSheen(m, wo, wi) + (1.0f - sheenAlbedoBound(m, wo.z)) * f;
    }
    if (hasClearcoat(m)) {
        f = vec3(clearcoatInShadingFrame(m, wo, wi)) + (1.0f - clearcoatAlbedoAt(m, wo)) * f;
    }
    return f;
}

// ---------------------------------------------------------------------------------------------
// Sampling: one lobe drawn with probability by its estimated albedo at wo, the direction from
// that lobe's sampler, the pdf the mixture's.

// The probability of each lobe's sampler: the diffuse lobe's cosine hemisphere, the base's GGX
// visible normals (dielectric highlight and metal share α), the clearcoat's, the sheen's
// uniform hemisphere and the glass lobe's own sampler. They sum to 1.
struct LobeProbabilities {
    float diffuse;
    float specular;
    float clearcoat;
    float sheen;
    float glass;
    float diffuseTransmission; // KHR_materials_diffuse_transmission's mirrored cosine hemisphere
};

// Each lobe's weight is its albedo at wo from the tables (a film's estimated,
// specularAlbedoEstimate), by luminance, times what the layers above leave it; the glass reflects
// and transmits all it receives, so its weight is its share. A lobe that cannot contribute (no
// diffuse: metallic 1, full transmission or a black base; no specular: metallic 0 and F0·s = 0;
// no clearcoat, sheen or glass) is never sampled; each of the k lobes that can gets
// VKPT_MIN_LOBE_PROBABILITY plus its share of the rest. A material that reflects nothing samples
// the diffuse lobe, with weight 0.
VKPT_FN LobeProbabilities lobeProbabilities(ShadingMaterial m, vec3 wo) {
    float cosThetaO = wo.z;
    float clearcoatWeight = 0.0f;
    float sheenWeight = 0.0f;
    float below = 1.0f; // what the layers above leave the base, at wo
    if (hasClearcoat(m)) {
        clearcoatWeight = clearcoatAlbedoAt(m, wo);
        below = 1.0f - clearcoatWeight;
    }
    if (hasSheen(m)) {
        sheenWeight = below * luminance(m.sheenColor) * min(sheenLobeAlbedo(m, cosThetaO), 1.0f);
        below *= 1.0f - sheenAlbedoBound(m, cosThetaO);
    }
    float opaque = 1.0f - m.transmission; // the opaque dielectric's share of the non-metal part
    vec3 dielectricSpecular = m.specular * specularAlbedoEstimate(m, dielectricF0(m), wo);
    float specularWeight =
        below * mix(opaque * luminance(dielectricSpecular),
                    luminance(specularAlbedoEstimate(m, m.baseColor, wo)), m.metallic);
    if (!(m.metallic > 0.0f || opaque * m.specular * maxComponent(dielectricF0(m)) > 0.0f))
        specularWeight = 0.0f;
    vec3 underSpecular = max(vec3(1.0f) - dielectricSpecular, vec3(0.0f));
    float diffuseWeight =
        below * (1.0f - m.metallic) * opaque * luminance(diffuseReflectance(m) * underSpecular);
    float glassWeight = below * glassShare(m);
    float transmittedWeight = 0.0f;
    if (hasDiffuseTransmission(m))
        transmittedWeight = below * (1.0f - m.metallic) * opaque * m.diffuseTransmission *
                            luminance(m.diffuseTransmissionColor * underSpecular);
    float lobes = (diffuseWeight > 0.0f ? 1.0f : 0.0f) + (specularWeight > 0.0f ? 1.0f : 0.0f) +
                  (clearcoatWeight > 0.0f ? 1.0f : 0.0f) + (sheenWeight > 0.0f ? 1.0f : 0.0f) +
                  (glassWeight > 0.0f ? 1.0f : 0.0f) + (transmittedWeight > 0.0f ? 1.0f : 0.0f);
    LobeProbabilities p;
    p.diffuse = 0.0f;
    p.specular = 0.0f;
    p.clearcoat = 0.0f;
    p.sheen = 0.0f;
    p.glass = 0.0f;
    p.diffuseTransmission = 0.0f;
    if (lobes == 0.0f) {
        p.diffuse = 1.0f;
        return p;
    }
    // With one lobe its probability is 1 exactly, not 0.1 + 0.9 w/w rounded.
    if (lobes == 1.0f) {
        p.diffuse = diffuseWeight > 0.0f ? 1.0f : 0.0f;
        p.specular = specularWeight > 0.0f ? 1.0f : 0.0f;
        p.clearcoat = clearcoatWeight > 0.0f ? 1.0f : 0.0f;
        p.sheen = sheenWeight > 0.0f ? 1.0f : 0.0f;
        p.glass = glassWeight > 0.0f ? 1.0f : 0.0f;
        p.diffuseTransmission = transmittedWeight > 0.0f ? 1.0f : 0.0f;
        return p;
    }
    float minimum = VKPT_MIN_LOBE_PROBABILITY;
    float share = (1.0f - lobes * minimum) / (diffuseWeight + specularWeight + clearcoatWeight +
                                              sheenWeight + glassWeight + transmittedWeight);
    if (diffuseWeight > 0.0f) p.diffuse = minimum + share * diffuseWeight;
    if (specularWeight > 0.0f) p.specular = minimum + share * specularWeight;
    if (clearcoatWeight > 0.0f) p.clearcoat = minimum + share * clearcoatWeight;
    if (sheenWeight > 0.0f) p.sheen = minimum + share * sheenWeight;
    if (glassWeight > 0.0f) p.glass = minimum + share * glassWeight;
    if (transmittedWeight > 0.0f) p.diffuseTransmission = minimum + share * transmittedWeight;
    return p;
}

// The clearcoat sampler's density of wi (both in the shading frame).
VKPT_FN float clearcoatPdf(ShadingMaterial m, vec3 wo, vec3 wi) {
    vec3 woC = toClearcoatFrame(m, wo);
    vec3 wiC = toClearcoatFrame(m, wi);
    if (!(woC.z > 0.0f && wiC.z > 0.0f)) return 0.0f;
    return ggxReflectionPdf(woC, normalize(woC + wiC), m.clearcoatAlpha);
}

// The one-sample mixture's pdf for wi: every lobe counts, whichever drew it, so that MIS against
// light sampling weighs the direction by the density it really had. Below the surface only the
// glass lobe's sampler reaches (a smooth glass's density is 0 everywhere: its samples are delta).
VKPT_FN float mixtureBsdfPdf(ShadingMaterial m, vec3 wo, vec3 wi, LobeProbabilities p) {
    float pdf = p.glass > 0.0f ? p.glass * dielectricPdf(glassLobeOf(m), wo, wi) : 0.0f;
    if (!(wi.z > 0.0f)) {
        if (hasDiffuseTransmission(m)) pdf += p.diffuseTransmission * -wi.z * VKPT_INV_PI;
        return pdf;
    }
    vec3 h = normalize(wo + wi);
    pdf += p.diffuse * wi.z * VKPT_INV_PI;
    if (p.specular > 0.0f) pdf += p.specular * baseGgxReflectionPdf(m, wo, h);
    if (p.clearcoat > 0.0f) pdf += p.clearcoat * clearcoatPdf(m, wo, wi);
    if (p.sheen > 0.0f) pdf += p.sheen * uniformHemispherePdf();
    return pdf;
}

VKPT_FN float bsdfPdf(ShadingMaterial m, vec3 wo, vec3 wi) {
    if (!m.metallicRoughness) return cosineHemispherePdf(wi.z);
    if (!(wo.z > 0.0f)) return 0.0f;
    return mixtureBsdfPdf(m, wo, wi, lobeProbabilities(m, wo));
}

// The BSDF for wi: f (no cosine) and the solid-angle pdf with which sampleBsdf would choose it.
struct BsdfValue {
    vec3 f;
    float pdf;
};

VKPT_FN BsdfValue evaluateBsdfValue(ShadingMaterial m, vec3 wo, vec3 wi) {
    BsdfValue value;
    value.f = evaluateBsdf(m, wo, wi);
    value.pdf = bsdfPdf(m, wo, wi);
    return value;
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

// A BSDF sample's first half: its direction, or the whole sample where no weighing by the
// mixture follows (finished: a Lambertian sample, a delta glass sample, or none).
struct BsdfDirection {
    vec3 wi; // local frame; where !finished
    bool finished;
    BsdfSample whole; // where finished
};

VKPT_FN BsdfDirection finishedBsdfDirection(BsdfSample whole) {
    BsdfDirection d;
    d.wi = whole.direction;
    d.finished = true;
    d.whole = whole;
    return d;
}

// uDirection places the direction within the lobe, uLobe picks the lobe (metallic-roughness
// only; in the order glass, specular, clearcoat, sheen, diffuse transmission, diffuse). A GGX
// sample reflected below the surface is invalid: the path ends there, which is the energy
// single-scattering microfacet models lose by design. The glass lobe's uChoice picks reflection
// or refraction; a delta sample's weight is the lobe's own times its share of the material over
// the probability of choosing it. Every other sample, a rough glass's too, is weighed by the
// whole mixture (weighBsdfSample).
VKPT_FN BsdfDirection sampleBsdfDirection(ShadingMaterial m, vec3 wo, vec2 uDirection,
                                          float uLobe) {
    BsdfSample s = invalidBsdfSample();
    if (!m.metallicRoughness) {
        s.direction = sampleCosineHemisphere(uDirection);
        s.pdf = cosineHemispherePdf(s.direction.z);
        s.weight = m.baseColor; // (ρ/π)·cos θ / (cos θ/π), exactly
        s.valid = s.pdf > 0.0f;
        return finishedBsdfDirection(s);
    }
    if (!(wo.z > 0.0f)) return finishedBsdfDirection(s);
    LobeProbabilities p = lobeProbabilities(m, wo);
    BsdfDirection d;
    d.finished = false;
    d.whole = s;
    bool transmits = false; // the diffuse transmission's sample: the only other that goes below
    if (uLobe < p.glass) {
        DielectricLobe lobe = glassLobeOf(m);
        DielectricSample g = sampleDielectric(lobe, wo, uDirection, uLobe / p.glass);
        if (!g.valid) return finishedBsdfDirection(s);
        if (dielectricIsDelta(lobe)) {
            s.direction = g.direction;
            s.delta = true;
            s.pdf = p.glass * g.pdf;
            s.weight = g.weight * (layersTransmittance(m, wo) * glassShare(m) / p.glass);
            s.valid = s.pdf > 0.0f;
            return finishedBsdfDirection(s);
        }
        d.wi = g.direction;
        return d;
    }
    uLobe -= p.glass;
    if (uLobe < p.specular) {
        d.wi = sampleBaseGgxReflection(m, wo, uDirection);
    } else if (uLobe < p.specular + p.clearcoat) {
        // Below the coat's own horizon, or the base's (tested after the branches), the sample
        // is lost, as clearcoatPdf counts it.
        vec3 woC = toClearcoatFrame(m, wo);
        if (!(woC.z > 0.0f)) return finishedBsdfDirection(s);
        vec3 wiC = sampleGgxReflection(woC, m.clearcoatAlpha, uDirection);
        if (!(wiC.z > 0.0f)) return finishedBsdfDirection(s);
        d.wi = fromClearcoatFrame(m, wiC);
    } else if (uLobe < p.specular + p.clearcoat + p.sheen) {
        d.wi = sampleUniformHemisphere(uDirection);
    } else if (hasDiffuseTransmission(m) &&
               uLobe < p.specular + p.clearcoat + p.sheen + p.diffuseTransmission) {
        d.wi = mirroredThroughSurface(sampleCosineHemisphere(uDirection));
        transmits = true;
    } else {
        d.wi = sampleCosineHemisphere(uDirection);
    }
    if (transmits ? !(d.wi.z < 0.0f) : !(d.wi.z > 0.0f)) return finishedBsdfDirection(s);
    return d;
}

// The second half: the sample along wi weighed by the whole mixture, given the BSDF there
// (evaluateBsdfValue). The kernels evaluate it where they evaluate the light samples' (one copy
// of the BSDF in the compiled kernel: lavapipe inlines every call).
VKPT_FN BsdfSample weighBsdfSample(vec3 wi, BsdfValue value) {
    BsdfSample s = invalidBsdfSample();
    if (!(value.pdf > 0.0f)) return s;
    s.direction = wi;
    s.pdf = value.pdf;
    s.weight = value.f * (abs(wi.z) / value.pdf);
    s.valid = true;
    return s;
}

VKPT_FN BsdfSample sampleBsdf(ShadingMaterial m, vec3 wo, vec2 uDirection, float uLobe) {
    BsdfDirection d = sampleBsdfDirection(m, wo, uDirection, uLobe);
    if (d.finished) return d.whole;
    return weighBsdfSample(d.wi, evaluateBsdfValue(m, wo, d.wi));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_BSDF_H
