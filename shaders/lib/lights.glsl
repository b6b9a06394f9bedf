// lights.glsl — next-event estimation in the kernels: shared/lights.h chooses the light and
// shared/light_connection.h the shadow ray, which becomes a shadow record for trace_shadow.
// Reads what lib/surface.glsl reads, and emitters, emitterCdf, lightTree, environmentTexels and
// environmentCdf (its kernels' SCENE entries).
#ifndef VKPT_LIGHTS_GLSL
#define VKPT_LIGHTS_GLSL

#include "lib/environment.glsl"
#include "lib/surface.glsl"

#include "shared/light_connection.h"

// A light connection as a shadow record whose contribution is f·Le·cos θ (punctual: f·E·cos θ)
// before the estimator's weight; SHADOW_NONE when it cannot contribute.
ShadowRay shadowRecordOf(LightConnection c) {
    if (!c.valid) return ShadowRay(vec3(0.0), SHADOW_NONE, vec3(0.0), 1.0, vec3(0.0), 0.0);
    return ShadowRay(c.origin, SHADOW_SEGMENT, c.direction, c.tMax, c.contribution, 0.0);
}

#endif // VKPT_LIGHTS_GLSL
