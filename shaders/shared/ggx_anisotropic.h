// ggx_anisotropic.h — KHR_materials_anisotropy's GGX lobe: the distribution stretched by αt
// along the anisotropy direction and αb across it, height-correlated Smith visibility, the pdf
// of reflected visible normals and their sampler. Every function takes directions in the
// anisotropy frame (x along the direction, y across it, z the shading normal; toAnisotropyFrame
// turns a shading-frame direction). Kept apart from ggx.h so that the isotropic lobe keeps its
// exact arithmetic and a scene without anisotropy compiles none of this.
#ifndef VKPT_GGX_ANISOTROPIC_H
#define VKPT_GGX_ANISOTROPIC_H

#include "ggx.h"
#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// A shading-frame direction in the frame whose x axis is the unit `direction` (x, y in the
// shading frame's tangent plane).
VKPT_FN vec3 toAnisotropyFrame(vec2 direction, vec3 w) {
    return vec3(direction.x * w.x + direction.y * w.y, direction.x * w.y - direction.y * w.x, w.z);
}

VKPT_FN vec3 fromAnisotropyFrame(vec2 direction, vec3 w) {
    return vec3(direction.x * w.x - direction.y * w.y, direction.y * w.x + direction.x * w.y, w.z);
}

// The anisotropic GGX distribution (Heitz 2014, "Understanding the Masking-Shadowing Function",
// eq. 85): 1 / (π αx αy ((x/αx)² + (y/αy)² + z²)²) for a unit half vector h; alpha = (αx, αy).
VKPT_FN float ggxDistributionAnisotropic(vec3 h, vec2 alpha) {
    float t = (h.x * h.x) / (alpha.x * alpha.x) + (h.y * h.y) / (alpha.y * alpha.y) + h.z * h.z;
    return 1.0f / (VKPT_PI * alpha.x * alpha.y * t * t);
}

// √(z² + αx² x² + αy² y²): Smith's Λ for the anisotropic distribution is that over z, minus 1,
// halved (Heitz 2014, eq. 86: the roughness projected on w's azimuth).
VKPT_FN float smithRootAnisotropic(vec3 w, vec2 alpha) {
    return sqrt(w.z * w.z + alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y);
}

// Height-correlated G2 over 4 cos θo cos θi, as ggxVisibility.
VKPT_FN float ggxVisibilityAnisotropic(vec3 wo, vec3 wi, vec2 alpha) {
    float denominator =
        wi.z * smithRootAnisotropic(wo, alpha) + wo.z * smithRootAnisotropic(wi, alpha);
    return denominator > 0.0f ? 0.5f / denominator : 0.0f;
}

// D · G2 / (4 cos θo cos θi) with F = 1, both directions above the surface.
VKPT_FN float ggxReflectionAnisotropic(vec3 wo, vec3 wi, vec3 h, vec2 alpha) {
    return ggxDistributionAnisotropic(h, alpha) * ggxVisibilityAnisotropic(wo, wi, alpha);
}

// G1(wo) D(h) / (4 cos θo) with G1 = 2 cos θo / (cos θo + root(wo)), as ggxReflectionPdf.
VKPT_FN float ggxReflectionPdfAnisotropic(vec3 wo, vec3 h, vec2 alpha) {
    return ggxDistributionAnisotropic(h, alpha) / (2.0f * (wo.z + smithRootAnisotropic(wo, alpha)));
}

// Heitz 2018 ("Sampling the GGX Distribution of Visible Normals", JCGT 7(4)), which stretches by
// (αx, αy): the isotropic sampler of ggx.h with the two roughnesses apart.
VKPT_FN vec3 sampleGgxVisibleNormalAnisotropic(vec3 wo, vec2 alpha, vec2 u) {
    return sampleGgxVisibleNormalStretched(wo, alpha, u);
}

VKPT_FN vec3 sampleGgxReflectionAnisotropic(vec3 wo, vec2 alpha, vec2 u) {
    vec3 h = sampleGgxVisibleNormalAnisotropic(wo, alpha, u);
    return normalize(2.0f * dot(wo, h) * h - wo);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_GGX_ANISOTROPIC_H
