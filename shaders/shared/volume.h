// volume.h — KHR_materials_volume in both renderers: which medium a path travels in, and the
// Beer–Lambert transmittance of a segment through it. A path starts outside every volume; a
// refraction through the front face of a volume material enters it, through a back face leaves
// it. One medium at a time: a volume inside another, or two that overlap, are not nested — a
// path leaving the inner one is outside both (docs/integrator.md).
#ifndef VKPT_VOLUME_H
#define VKPT_VOLUME_H

#include "host_device.h"
#include "scene_view.h"
#include "surface.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// An optical depth past which the transmittance is 0 in float (e^−104 is below the smallest
// subnormal); capping it keeps σ·∞ and 0·∞ out of exp.
#define VKPT_MAX_OPTICAL_DEPTH 200.0f

// e^(−σ d) per channel (Beer–Lambert). d = VKPT_FAR stands for a ray to infinity.
VKPT_FN vec3 beerLambertTransmittance(vec3 sigma, float distance) {
    vec3 depth = min(sigma * distance, vec3(VKPT_MAX_OPTICAL_DEPTH));
    return exp(-depth);
}

// The length of a segment from its origin to origin + t·direction, VKPT_FAR to infinity.
VKPT_FN float segmentLength(vec3 direction, float t) {
    return t >= VKPT_FAR ? VKPT_FAR : t * length(direction);
}

// The medium (its σ; 0 outside every volume) after a transmission through s: a thin wall
// changes nothing; a volume material's front face enters its medium, its back face leaves it.
VKPT_FN vec3 mediumAfterTransmission(vec3 current, SurfacePoint s VKPT_SCENE_PARAM) {
    Material m = sceneMaterial(placedMaterialIndex(
        s.instance, scenePrimitive(s.triangle VKPT_SCENE_ARG) VKPT_SCENE_ARG) VKPT_SCENE_ARG);
    if (!(m.thickness > 0.0f)) return current;
    return s.frontFace ? m.attenuationCoefficient : vec3(0.0f);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_VOLUME_H
