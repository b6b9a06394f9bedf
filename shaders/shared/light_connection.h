// light_connection.h — one light sample at a surface point as the shadow ray that decides it,
// for both executors: the kernels store it as a shadow record (lib/lights.glsl), the reference
// traces it at once (host/reference/direct_lighting.cpp). The building block of the path
// integrator's next-event estimation and of CS184's light-sampling direct integrator.
#ifndef VKPT_LIGHT_CONNECTION_H
#define VKPT_LIGHT_CONNECTION_H

#include "bsdf.h"
#include "host_device.h"
#include "lights.h"
#include "path_rules.h"
#include "ray_offset.h"
#include "scene_view.h"
#include "surface.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// A finite light is a segment between the two offset ends (t in (0, 1); a punctual light's end
// is the light itself); a light at infinity is a ray along its unit direction to VKPT_FAR.
struct LightConnection {
    vec3 origin;       // the receiver moved off its surface
    float tMax;        // 1 for a segment, VKPT_FAR for a light at infinity
    vec3 direction;    // to the segment's end, or unit towards the light at infinity
    float lightPdf;    // solid angle; for a punctual light its selection probability
    vec3 contribution; // f·Le·cos θ (punctual: f·E·cos θ), before the estimator's weight
    float bsdfPdf;     // of the BSDF sampler in the same direction; 0 for a delta light
    bool valid;        // false: no emitter, back face, below the surface, f = 0
};

VKPT_FN LightConnection noLightConnection() {
    LightConnection c;
    c.origin = vec3(0.0f);
    c.tMax = 1.0f;
    c.direction = vec3(0.0f);
    c.lightPdf = 0.0f;
    c.contribution = vec3(0.0f);
    c.bsdfPdf = 0.0f;
    c.valid = false;
    return c;
}

// u.x picks the emitter, u.yz the point on it (rng.h, DIM_LIGHT_FIRST).
VKPT_FN LightConnection connectLightSample(SurfacePoint s, vec4 u VKPT_SCENE_PARAM) {
    LightConnection c = noLightConnection();
    LightSample light = sampleLight(s.position, u VKPT_SCENE_ARG);
    if (!light.valid || light.radiance == vec3(0.0f)) return c;
    float cosSurface = dot(light.direction, s.shadingNormal);
    float side = dot(light.direction, s.geometricNormal);
    // A light on the far side counts only through a thin wall that transmits diffusely, and
    // then on the far side of both normals, as a transmitted BSDF sample must be.
    bool through = sceneHasDiffuseTransmission(VKPT_SCENE_ARG_ONLY) &&
                   lightSampledThrough(s.shading) && cosSurface < 0.0f && side < 0.0f;
    if (!through && (cosSurface <= 0.0f || side <= 0.0f)) return c;
    BsdfValue bsdf = evaluateSurfaceBsdf(s, light.direction);
    if (bsdf.f == vec3(0.0f)) return c;
    // Both ends move off their surfaces, so the shadow ray can hit neither of them; a shadow
    // ray through a thin wall leaves from its far side.
    c.origin = offsetFromSurface(s.position, through ? -s.geometricNormal : s.geometricNormal,
                                 s.coordinateScale);
    if (light.atInfinity) {
        c.direction = light.direction;
        c.tMax = VKPT_FAR;
    } else {
        vec3 target = light.delta ? light.position
                                  : offsetFromSurface(light.position, light.towardsReceiver,
                                                      light.coordinateScale);
        c.direction = target - c.origin;
    }
    c.contribution = bsdf.f * light.radiance * abs(cosSurface);
    c.lightPdf = light.pdfSolidAngle;
    c.bsdfPdf = light.delta ? 0.0f : bsdf.pdf;
    c.valid = true;
    return c;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_LIGHT_CONNECTION_H
