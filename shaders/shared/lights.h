// lights.h — next-event estimation's choice of a light, for both executors: an emitter chosen
// by the light BVH (light_tree.h) or by power (through the emitter CDF when there are several),
// then by its kind a uniform point
// on a triangle, a point in a sphere's visible cone, a punctual light's incidence or a
// direction from the environment; and the solid-angle pdfs with which that choice reaches an
// emitter or the environment, for the other half of MIS. Reaches the scene through
// scene_view.h.
#ifndef VKPT_LIGHTS_H
#define VKPT_LIGHTS_H

#include "environment.h"
#include "host_device.h"
#include "intersect.h"
#include "light_tree.h"
#include "materials.h"
#include "path_rules.h"
#include "punctual.h"
#include "sampling.h"
#include "scene_environment.h"
#include "scene_view.h"
#include "sphere.h"
#include "surface.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// The first emitter whose inclusive CDF entry exceeds u (std::upper_bound), the last one if
// none; with one emitter there is no CDF to read.
VKPT_FN uint selectEmitter(float u VKPT_SCENE_PARAM) {
    uint count = sceneEmitterCount(VKPT_SCENE_ARG_ONLY);
    if (!sceneHasEmitterCdf(VKPT_SCENE_ARG_ONLY) || count <= 1u) return 0u;
    uint lo = 0u;
    uint hi = count;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (u < sceneEmitterCdf(mid VKPT_SCENE_ARG)) {
            hi = mid;
        } else {
            lo = mid + 1u;
        }
    }
    return min(lo, count - 1u);
}

// The light BVH chooses infinite lights (directional, environment) by power alone, with the
// probability the power table gives them (host/prepare/light_tree.h); their selectProbability is
// that probability in both samplers, so that the environment's MIS pdf (scene_environment.h)
// needs no receiver.
VKPT_FN bool isInfiniteEmitter(Emitter emitter) {
    return emitter.kind == EMITTER_DIRECTIONAL || emitter.kind == EMITTER_ENVIRONMENT;
}

// The probability with which sampleLight chooses emitter `index` from `receiver`.
VKPT_FN float emitterSelectProbability(uint index, Emitter emitter,
                                       vec3 receiver VKPT_SCENE_PARAM) {
    if (!sceneHasLightTree(VKPT_SCENE_ARG_ONLY) || isInfiniteEmitter(emitter))
        return emitter.selectProbability;
    return lightTreePmf(index, receiver VKPT_SCENE_ARG);
}

// Named `light` where it is a variable: `sample` is a GLSL keyword.
struct LightSample {
    vec3 position;
    vec3 towardsReceiver; // unit emitter normal turned towards the receiver
    vec3 direction;       // unit, receiver → light
    // Area and environment samples: radiance emitted towards the receiver (0 from a back face).
    // Punctual (delta) samples: the irradiance they cause on a surface facing them.
    vec3 radiance;
    float pdfSolidAngle;   // punctual: the selection probability alone
    float coordinateScale; // of the emitter primitive, for offsetFromSurface
    bool valid;            // false: no emitters, or the point is seen edge-on
    bool delta;            // a punctual light: no MIS, no BSDF sample can reach it
    bool atInfinity;       // directional or environment: a shadow ray without an end point
};

VKPT_FN LightSample noLightSample() {
    LightSample light;
    light.position = vec3(0.0f);
    light.towardsReceiver = vec3(0.0f);
    light.direction = vec3(0.0f);
    light.radiance = vec3(0.0f);
    light.pdfSolidAngle = 0.0f;
    light.coordinateScale = 0.0f;
    light.valid = false;
    light.delta = false;
    light.atInfinity = false;
    return light;
}

VKPT_FN void sampleTriangleLight(VKPT_INOUT(LightSample) light, Emitter emitter,
                                 float selectProbability, vec3 receiver, vec2 u VKPT_SCENE_PARAM) {
    Triangle tri = scenePrimitive(emitter.primitive VKPT_SCENE_ARG);
    vec3 b = sampleTriangleBarycentrics(u);
    light.position = b.x * tri.v0 + b.y * tri.v1 + b.z * tri.v2;
    light.coordinateScale = triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    vec3 toLight = light.position - receiver;
    float distanceSquared = dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return;
    light.direction = toLight / sqrt(distanceSquared);
    vec3 face = unitFaceNormal(tri.v0, tri.v1, tri.v2);
    float cosAtLight = -dot(face, light.direction);
    Material material = sceneMaterial(tri.materialIndex VKPT_SCENE_ARG);
    if (emitsOnThisSide(material, cosAtLight > 0.0f VKPT_SCENE_ARG)) {
        light.radiance = material.emission;
        if (hasTexture(material.emissiveTexture VKPT_SCENE_ARG))
            light.radiance =
                emissionAt(material, primitiveUv(emitter.primitive, tri, b.y, b.z,
                                                 vec3(0.0f) VKPT_SCENE_ARG) VKPT_SCENE_ARG);
    }
    light.towardsReceiver = cosAtLight > 0.0f ? face : -face;
    light.pdfSolidAngle =
        areaToSolidAnglePdf(selectProbability / emitter.area, distanceSquared, cosAtLight);
    light.valid = light.pdfSolidAngle > 0.0f;
}

VKPT_FN void sampleSphereEmitter(VKPT_INOUT(LightSample) light, Emitter emitter,
                                 float selectProbability, vec3 receiver, vec2 u VKPT_SCENE_PARAM) {
    Triangle sphere = scenePrimitive(emitter.primitive VKPT_SCENE_ARG);
    SphereLightSample point = sampleSphereLight(receiver, sphere.v0, sphere.v1.x, u);
    if (!point.valid) return;
    light.position = point.position;
    light.coordinateScale = sphereCoordinateScale(sphere.v0, sphere.v1.x);
    vec3 toLight = light.position - receiver;
    float distance = length(toLight);
    if (!(distance > 0.0f)) return;
    light.direction = toLight / distance;
    bool facesReceiver = dot(point.normal, light.direction) < 0.0f;
    Material material = sceneMaterial(sphere.materialIndex VKPT_SCENE_ARG);
    if (emitsOnThisSide(material, facesReceiver VKPT_SCENE_ARG)) {
        light.radiance = material.emission;
        if (hasTexture(material.emissiveTexture VKPT_SCENE_ARG))
            light.radiance =
                emissionAt(material, primitiveUv(emitter.primitive, sphere, 0.0f, 0.0f,
                                                 point.normal VKPT_SCENE_ARG) VKPT_SCENE_ARG);
    }
    light.towardsReceiver = facesReceiver ? point.normal : -point.normal;
    light.pdfSolidAngle = selectProbability * point.pdfSolidAngle;
    light.valid = light.pdfSolidAngle > 0.0f;
}

VKPT_FN void samplePunctualLight(VKPT_INOUT(LightSample) light, Emitter emitter,
                                 float selectProbability, vec3 receiver) {
    PunctualIncidence incidence = punctualIncidence(emitter, receiver);
    if (!incidence.valid) return;
    light.delta = true;
    light.direction = incidence.direction;
    light.radiance = incidence.irradiance;
    light.pdfSolidAngle = selectProbability;
    if (emitter.kind == EMITTER_DIRECTIONAL) {
        light.atInfinity = true;
    } else {
        light.position = emitter.position; // a point: the shadow ray ends there exactly
    }
    light.valid = light.pdfSolidAngle > 0.0f;
}

VKPT_FN void sampleEnvironmentLight(VKPT_INOUT(LightSample) light, Emitter emitter,
                                    vec2 u VKPT_SCENE_PARAM) {
    EnvironmentSample e =
        sampleEnvironment(sceneEnvironment(VKPT_SCENE_ARG_ONLY), u VKPT_SCENE_ARG);
    if (!e.valid) return;
    light.atInfinity = true;
    light.direction = e.direction;
    light.radiance = e.radiance;
    light.pdfSolidAngle = emitter.selectProbability * e.pdf;
    light.valid = light.pdfSolidAngle > 0.0f;
}

// The emitter u chooses from `receiver` and the probability of that choice; NO_EMITTER when
// the light BVH finds no emitter that can reach the receiver.
struct EmitterChoice {
    uint index;
    float probability;
};

VKPT_FN EmitterChoice chooseEmitter(vec3 receiver, float u VKPT_SCENE_PARAM) {
    EmitterChoice choice;
    if (sceneHasLightTree(VKPT_SCENE_ARG_ONLY)) {
        LightTreeChoice tree = chooseFromLightTree(receiver, u VKPT_SCENE_ARG);
        choice.index = tree.emitter;
        choice.probability = tree.probability;
        return choice;
    }
    choice.index = selectEmitter(u VKPT_SCENE_ARG);
    choice.probability = sceneEmitter(choice.index VKPT_SCENE_ARG).selectProbability;
    return choice;
}

// u.x selects the emitter, u.yz the point or direction on it.
VKPT_FN LightSample sampleLight(vec3 receiver, vec4 u VKPT_SCENE_PARAM) {
    LightSample light = noLightSample();
    if (sceneEmitterCount(VKPT_SCENE_ARG_ONLY) == 0u) return light;
    EmitterChoice choice = chooseEmitter(receiver, u.x VKPT_SCENE_ARG);
    if (choice.index == NO_EMITTER) return light;
    Emitter emitter = sceneEmitter(choice.index VKPT_SCENE_ARG);
    float probability = isInfiniteEmitter(emitter) ? emitter.selectProbability : choice.probability;
    vec2 uPoint = vec2(u.y, u.z);
    if (emitter.kind == EMITTER_TRIANGLE) {
        sampleTriangleLight(light, emitter, probability, receiver, uPoint VKPT_SCENE_ARG);
    } else if (sceneHasSpheres(VKPT_SCENE_ARG_ONLY) && emitter.kind == EMITTER_SPHERE) {
        sampleSphereEmitter(light, emitter, probability, receiver, uPoint VKPT_SCENE_ARG);
    } else if (sceneHasEnvironment(VKPT_SCENE_ARG_ONLY) && emitter.kind == EMITTER_ENVIRONMENT) {
        sampleEnvironmentLight(light, emitter, uPoint VKPT_SCENE_ARG);
    } else if (sceneHasPunctualLights(VKPT_SCENE_ARG_ONLY)) {
        samplePunctualLight(light, emitter, probability, receiver);
    }
    return light;
}

// Solid-angle pdf with which sampleLight would have produced the hit `s` from `origin`.
VKPT_FN float lightPdf(SurfacePoint s, vec3 origin VKPT_SCENE_PARAM) {
    Triangle primitive = scenePrimitive(s.triangle VKPT_SCENE_ARG);
    if (primitive.emitterIndex == NO_EMITTER) return 0.0f;
    Emitter emitter = sceneEmitter(primitive.emitterIndex VKPT_SCENE_ARG);
    float probability =
        emitterSelectProbability(primitive.emitterIndex, emitter, origin VKPT_SCENE_ARG);
    if (sceneHasSpheres(VKPT_SCENE_ARG_ONLY) && isSpherePrimitive(primitive)) {
        return probability * sphereLightPdf(origin, primitive.v0, primitive.v1.x, s.position);
    }
    vec3 toLight = s.position - origin;
    float distanceSquared = dot(toLight, toLight);
    float cosAtLight = dot(s.geometricNormal, toLight) / sqrt(distanceSquared);
    return areaToSolidAnglePdf(probability / emitter.area, distanceSquared, cosAtLight);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_LIGHTS_H
