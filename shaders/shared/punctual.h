// punctual.h — the light KHR_lights_punctual's point, spot and directional lights deliver to a
// receiving point: the direction to the light, its distance and the irradiance on a surface
// facing it. The renderers multiply by f·cos θ and trace the shadow ray.
//
// Units (docs/scene-model.md): a point or spot light of intensity 1 cd delivers radiant
// intensity 1 in image units, i.e. irradiance 1/d² at distance d; a directional light of 1 lux
// delivers irradiance 1. Emitter.intensity already holds intensity × colour.
#ifndef VKPT_PUNCTUAL_H
#define VKPT_PUNCTUAL_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

struct PunctualIncidence {
    vec3 direction;  // unit, from the receiver towards the light
    float distance;  // to the light; VKPT_FAR for a directional light
    vec3 irradiance; // on a surface facing the light
    bool valid;      // false where the light delivers nothing (outside range or cone, d = 0)
};

// The extension's recommended range window (KHR_lights_punctual, "Range Property"):
// clamp(1 − (d/range)⁴, 0, 1), applied on top of the inverse square law; range 0 is unlimited.
// The light is exactly 0 from d = range on, as the extension requires.
VKPT_FN float punctualRangeWindow(float distanceToLight, float range) {
    if (!(range > 0.0f)) return 1.0f;
    float ratio = distanceToLight / range;
    float ratio2 = ratio * ratio;
    return clamp(1.0f - ratio2 * ratio2, 0.0f, 1.0f);
}

// The extension's reference falloff between the cones (KHR_lights_punctual, "Inner and Outer
// Cone Angles"): linear in the cosine of the angle from the spot axis, from 0 at the outer cone
// to 1 at the inner one, then squared; the difference of cosines is kept >= 0.001 as there.
VKPT_FN float spotFalloff(Emitter light, vec3 towardsReceiver) {
    float cosAngle = dot(light.direction, towardsReceiver);
    float scale = 1.0f / max(0.001f, light.cosInnerCone - light.cosOuterCone);
    float linear = clamp((cosAngle - light.cosOuterCone) * scale, 0.0f, 1.0f);
    return linear * linear;
}

VKPT_FN PunctualIncidence punctualIncidence(Emitter light, vec3 receiver) {
    PunctualIncidence result;
    result.direction = vec3(0.0f, 0.0f, 1.0f);
    result.distance = VKPT_FAR;
    result.irradiance = vec3(0.0f);
    result.valid = false;
    if (light.kind == EMITTER_DIRECTIONAL) {
        result.direction = -light.direction;
        result.irradiance = light.intensity;
        result.valid = true;
        return result;
    }
    if (light.kind != EMITTER_POINT && light.kind != EMITTER_SPOT) return result;
    vec3 toLight = light.position - receiver;
    float distanceSquared = dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return result;
    float distanceToLight = sqrt(distanceSquared);
    result.direction = toLight / distanceToLight;
    result.distance = distanceToLight;
    float attenuation = punctualRangeWindow(distanceToLight, light.range) / distanceSquared;
    if (light.kind == EMITTER_SPOT) attenuation *= spotFalloff(light, -result.direction);
    result.irradiance = light.intensity * attenuation;
    result.valid = attenuation > 0.0f;
    return result;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_PUNCTUAL_H
