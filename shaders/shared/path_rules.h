// path_rules.h — the decisions of the path integrator that both renderers must make
// identically so that, at one seed, their paths are the same paths.
#ifndef VKPT_PATH_RULES_H
#define VKPT_PATH_RULES_H

#include "bsdf.h"
#include "dispersion.h"
#include "host_device.h"
#include "sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Russian roulette (Arvo and Kirk 1990), from the rrStartDepth-th scattering event on: the
// path continues with probability q = clamp(max(throughput), 0.05, 1) and its throughput is
// divided by q, which keeps the estimator unbiased. The floor bounds the weight 1/q by 20.
#define RR_MIN_SURVIVAL 0.05f

VKPT_FN float russianRouletteSurvival(vec3 throughput, uint scatterCount, uint rrStartDepth) {
    if (scatterCount < rrStartDepth) return 1.0f;
    float q = max(max(throughput.x, throughput.y), throughput.z);
    return clamp(q, RR_MIN_SURVIVAL, 1.0f);
}

// Path filters for --direct-only / --indirect-only: a contribution is kept by the number of
// scattering events on its path (0 = emitter seen directly, 1 = direct lighting).
#define PATH_FILTER_ALL 0u
#define PATH_FILTER_DIRECT_ONLY 1u
#define PATH_FILTER_INDIRECT_ONLY 2u

VKPT_FN bool pathFilterKeeps(uint pathFilter, uint scatterCount) {
    if (pathFilter == PATH_FILTER_DIRECT_ONLY) return scatterCount <= 1u;
    if (pathFilter == PATH_FILTER_INDIRECT_ONLY) return scatterCount >= 2u;
    return true;
}

// Solid-angle pdf of a point sampled on a surface with area pdf pdfArea, seen at squared
// distance distanceSquared under cosine cosAtLight; 0 where the point is seen edge-on.
VKPT_FN float areaToSolidAnglePdf(float pdfArea, float distanceSquared, float cosAtLight) {
    float c = abs(cosAtLight);
    return c > 0.0f ? pdfArea * distanceSquared / c : 0.0f;
}

// Multiple importance sampling of emission found by a BSDF sample (docs/integrator.md): the
// pdf a path keeps for the next vertex's weight (PathState::previousBsdfPdf on the device) is
// PDF_NOT_LIGHT_SAMPLED when light sampling could not have produced the direction: a delta
// lobe (light sampling never evaluates one) or a transmission (a shadow ray starts on the side
// the path arrived from, and glass blocks shadow rays). Emission then counts with weight 1.
#define PDF_NOT_LIGHT_SAMPLED -1.0f

VKPT_FN bool bsdfSampleTransmits(BsdfSample s) {
    return s.direction.z < 0.0f;
}

// Light sampling reaches the far side of a thin wall whose diffuse base transmits
// (KHR_materials_diffuse_transmission): its shadow ray leaves from that side
// (light_connection.h). Not a volume's: a shadow ray from inside meets the volume's own boundary,
// which blocks it.
VKPT_FN bool lightSampledThrough(ShadingMaterial m) {
    return hasDiffuseTransmission(m) && m.thinWalled;
}

// m: the material that made the sample.
VKPT_FN float misPdfOfBsdfSample(BsdfSample s, ShadingMaterial m) {
    if (s.delta) return PDF_NOT_LIGHT_SAMPLED;
    if (bsdfSampleTransmits(s) && !lightSampledThrough(m)) return PDF_NOT_LIGHT_SAMPLED;
    return s.pdf;
}

// The power heuristic of one BSDF sample against N light samples (Veach 1997, §9.2.4), or 1
// when light sampling could not have chosen the direction.
VKPT_FN float emissionMisWeight(float previousBsdfPdf, float lightSamples, float pdfLight) {
    if (previousBsdfPdf < 0.0f) return 1.0f;
    return powerHeuristic(1.0f, previousBsdfPdf, lightSamples, pdfLight);
}

// KHR_materials_dispersion (dispersion.h): the wavelength a path carries after meeting material
// m. At its first dispersive glass the path takes λ from uWavelength (DIM_CAMERA's z at bounce
// 0, so one wavelength per path wherever it binds) and its throughput the weight w(λ), once; at
// that vertex and every later dispersive one the glass is taken at λ. Anything else is left
// unchanged: what a path gathered before it had λ does not depend on λ, and E[w] = 1.
VKPT_FN float bindWavelength(VKPT_INOUT(ShadingMaterial) m, VKPT_INOUT(vec3) throughput,
                             float wavelength, float uWavelength) {
    if (!hasDispersion(m)) return wavelength;
    if (wavelength == VKPT_NO_WAVELENGTH) {
        wavelength = sampleWavelength(uWavelength);
        throughput *= wavelengthWeight(wavelength);
    }
    m = atWavelength(m, wavelength);
    return wavelength;
}

// Whether a sampled world direction continues the path: a reflection must leave above the
// geometric surface and a transmission below it. An interpolated shading normal can put either
// on the wrong side, where a reflection would re-enter the surface or a transmission leak
// back; such a path ends, as a reflection below the surface always did.
VKPT_FN bool continuesOnItsSide(BsdfSample s, vec3 direction, vec3 geometricNormal) {
    float side = dot(direction, geometricNormal);
    return bsdfSampleTransmits(s) ? side < 0.0f : side > 0.0f;
}

// The normal along which the next ray's origin leaves the surface: to the side it goes.
VKPT_FN vec3 continuationNormal(BsdfSample s, vec3 geometricNormal) {
    return bsdfSampleTransmits(s) ? -geometricNormal : geometricNormal;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_PATH_RULES_H
