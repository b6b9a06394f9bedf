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

// A light connection in two halves around the BSDF, so that a caller evaluating the BSDF for
// other directions too (the kernels' hemisphere probes) can do so at one place: lavapipe
// inlines every call, and each call site of the BSDF is another copy of it to compile.

// The half before the BSDF: the light sample and which side of the surface it lies on.
struct LightApproach {
    LightSample light;
    float cosSurface; // towards the light, against the shading normal
    bool through;     // lit from the far side, through a thin wall that transmits diffusely
    bool valid;       // false: no emitter, nothing emitted, or the light behind the surface
};

// u.x picks the emitter, u.yz the point on it (rng.h, DIM_LIGHT_FIRST).
VKPT_FN LightApproach approachLight(SurfacePoint s, vec4 u VKPT_SCENE_PARAM) {
    LightApproach a;
    a.light = sampleLight(s.position, u VKPT_SCENE_ARG);
    a.cosSurface = dot(a.light.direction, s.shadingNormal);
    float side = dot(a.light.direction, s.geometricNormal);
    // A light on the far side counts only through a thin wall that transmits diffusely, and
    // then on the far side of both normals, as a transmitted BSDF sample must be.
    a.through = sceneHasDiffuseTransmission(VKPT_SCENE_ARG_ONLY) &&
                lightSampledThrough(s.shading) && a.cosSurface < 0.0f && side < 0.0f;
    a.valid = a.light.valid && a.light.radiance != vec3(0.0f) &&
              (a.through || (a.cosSurface > 0.0f && side > 0.0f));
    return a;
}

// The half after it: the connection of a valid approach, given the BSDF towards the light.
VKPT_FN LightConnection completeLightConnection(SurfacePoint s, LightApproach a, BsdfValue bsdf) {
    LightConnection c = noLightConnection();
    if (bsdf.f == vec3(0.0f)) return c;
    // Both ends move off their surfaces, so the shadow ray can hit neither of them; a shadow
    // ray through a thin wall leaves from its far side.
    c.origin = offsetFromSurface(s.position, a.through ? -s.geometricNormal : s.geometricNormal,
                                 s.coordinateScale);
    if (a.light.atInfinity) {
        c.direction = a.light.direction;
        c.tMax = VKPT_FAR;
    } else {
        vec3 target = a.light.delta ? a.light.position
                                    : offsetFromSurface(a.light.position, a.light.towardsReceiver,
                                                        a.light.coordinateScale);
        c.direction = target - c.origin;
    }
    c.contribution = bsdf.f * a.light.radiance * abs(a.cosSurface);
    c.lightPdf = a.light.pdfSolidAngle;
    c.bsdfPdf = a.light.delta ? 0.0f : bsdf.pdf;
    c.valid = true;
    return c;
}

// One light sample at `s` as the shadow ray that decides it; u as approachLight's.
VKPT_FN LightConnection connectLightSample(SurfacePoint s, vec4 u VKPT_SCENE_PARAM) {
    LightApproach a = approachLight(s, u VKPT_SCENE_ARG);
    if (!a.valid) return noLightConnection();
    return completeLightConnection(s, a, evaluateSurfaceBsdf(s, a.light.direction));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_LIGHT_CONNECTION_H
