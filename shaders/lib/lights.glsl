// lights.glsl — next-event estimation's half of the kernels, as host/reference/light_sampling.cpp
// and direct_lighting.cpp do it: an emitter chosen by power (through emitterCdf when there are
// several), then by its kind a uniform point on a triangle, a point in a sphere's visible cone,
// a punctual light's incidence or a direction from the environment; the shadow ray towards it;
// and the solid-angle pdfs of reaching an emitter or the environment by a BSDF sample.
// Needs what lib/surface.glsl needs, and emitterCdf, environmentTexels and environmentCdf
// declared (and binds the emitters texel view).
#ifndef VKPT_LIGHTS_GLSL
#define VKPT_LIGHTS_GLSL

#include "lib/environment.glsl"
#include "lib/surface.glsl"
#include "shared/path_rules.h"
#include "shared/punctual.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"
#include "shared/sphere.h"

// Solid-angle pdf with which light sampling chooses the environment along a unit direction.
float environmentLightPdf(vec3 direction) {
    if (!hasEnvironment()) return 0.0;
    return fetchEmitter(frame.environment.emitterIndex).selectProbability *
           environmentPdf(sceneEnvironment(), direction);
}

// The first emitter whose inclusive CDF entry exceeds u (std::upper_bound), the last one if
// none; with one emitter there is no CDF to read.
uint selectEmitter(float u) {
    uint count = frame.emitterCount;
    if (!featureEmitterCdf || count <= 1u) return 0u;
    uint lo = 0u;
    uint hi = count;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (u < emitterCdf[mid]) {
            hi = mid;
        } else {
            lo = mid + 1u;
        }
    }
    return min(lo, count - 1u);
}

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

void sampleTriangleLight(inout LightSample light, Emitter emitter, vec3 receiver, vec2 u) {
    Triangle tri = fetchTriangle(emitter.primitive);
    vec3 b = sampleTriangleBarycentrics(u);
    light.position = b.x * tri.v0 + b.y * tri.v1 + b.z * tri.v2;
    light.coordinateScale = triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    vec3 toLight = light.position - receiver;
    float distanceSquared = dot(toLight, toLight);
    if (!(distanceSquared > 0.0)) return;
    light.direction = toLight / sqrt(distanceSquared);
    vec3 face = unitFaceNormal(tri.v0, tri.v1, tri.v2);
    float cosAtLight = -dot(face, light.direction);
    Material material = fetchMaterial(tri.materialIndex);
    if (emitsOnThisSide(material, cosAtLight > 0.0)) {
        light.radiance = material.emission;
        if (hasTexture(material.emissiveTexture))
            light.radiance =
                emissionAt(material, primitiveUv(emitter.primitive, tri, b.y, b.z, vec3(0.0)));
    }
    light.towardsReceiver = cosAtLight > 0.0 ? face : -face;
    light.pdfSolidAngle =
        areaToSolidAnglePdf(emitter.selectProbability / emitter.area, distanceSquared, cosAtLight);
    light.valid = light.pdfSolidAngle > 0.0;
}

void sampleSphereEmitter(inout LightSample light, Emitter emitter, vec3 receiver, vec2 u) {
    Triangle sphere = fetchTriangle(emitter.primitive);
    SphereLightSample point = sampleSphereLight(receiver, sphere.v0, sphere.v1.x, u);
    if (!point.valid) return;
    light.position = point.position;
    light.coordinateScale = sphereCoordinateScale(sphere.v0, sphere.v1.x);
    vec3 toLight = light.position - receiver;
    float distance = length(toLight);
    if (!(distance > 0.0)) return;
    light.direction = toLight / distance;
    bool facesReceiver = dot(point.normal, light.direction) < 0.0;
    Material material = fetchMaterial(sphere.materialIndex);
    if (emitsOnThisSide(material, facesReceiver)) {
        light.radiance = material.emission;
        if (hasTexture(material.emissiveTexture))
            light.radiance = emissionAt(
                material, primitiveUv(emitter.primitive, sphere, 0.0, 0.0, point.normal));
    }
    light.towardsReceiver = facesReceiver ? point.normal : -point.normal;
    light.pdfSolidAngle = emitter.selectProbability * point.pdfSolidAngle;
    light.valid = light.pdfSolidAngle > 0.0;
}

void samplePunctualLight(inout LightSample light, Emitter emitter, vec3 receiver) {
    PunctualIncidence incidence = punctualIncidence(emitter, receiver);
    if (!incidence.valid) return;
    light.delta = true;
    light.direction = incidence.direction;
    light.radiance = incidence.irradiance;
    light.pdfSolidAngle = emitter.selectProbability;
    if (emitter.kind == EMITTER_DIRECTIONAL) {
        light.atInfinity = true;
    } else {
        light.position = emitter.position; // a point: the shadow ray ends there exactly
    }
    light.valid = light.pdfSolidAngle > 0.0;
}

void sampleEnvironmentLight(inout LightSample light, Emitter emitter, vec2 u) {
    EnvironmentSample e = sampleEnvironment(sceneEnvironment(), u);
    if (!e.valid) return;
    light.atInfinity = true;
    light.direction = e.direction;
    light.radiance = e.radiance;
    light.pdfSolidAngle = emitter.selectProbability * e.pdf;
    light.valid = light.pdfSolidAngle > 0.0;
}

// u.x selects the emitter, u.yz the point or direction on it.
LightSample sampleLight(vec3 receiver, vec4 u) {
    // Named `light`: `sample` is a GLSL keyword.
    LightSample light =
        LightSample(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0, 0.0, false, false, false);
    if (frame.emitterCount == 0u) return light;
    Emitter emitter = fetchEmitter(selectEmitter(u.x));
    vec2 uPoint = vec2(u.y, u.z);
    if (emitter.kind == EMITTER_TRIANGLE) {
        sampleTriangleLight(light, emitter, receiver, uPoint);
    } else if (featureSpheres && emitter.kind == EMITTER_SPHERE) {
        sampleSphereEmitter(light, emitter, receiver, uPoint);
    } else if (featureEnvironment && emitter.kind == EMITTER_ENVIRONMENT) {
        sampleEnvironmentLight(light, emitter, uPoint);
    } else if (featurePunctualLights) {
        samplePunctualLight(light, emitter, receiver);
    }
    return light;
}

// Solid-angle pdf with which sampleLight would have produced the hit `s` from `origin`.
float lightPdf(SurfacePoint s, vec3 origin) {
    Triangle primitive = fetchTriangle(s.triangle);
    if (primitive.emitterIndex == NO_EMITTER) return 0.0;
    Emitter emitter = fetchEmitter(primitive.emitterIndex);
    if (featureSpheres && isSpherePrimitive(primitive)) {
        return emitter.selectProbability *
               sphereLightPdf(origin, primitive.v0, primitive.v1.x, s.position);
    }
    vec3 toLight = s.position - origin;
    float distanceSquared = dot(toLight, toLight);
    float cosAtLight = dot(s.geometricNormal, toLight) / sqrt(distanceSquared);
    return areaToSolidAnglePdf(emitter.selectProbability / emitter.area, distanceSquared,
                               cosAtLight);
}

// One light sample at `s`, as a shadow ray whose contribution is f·Le·cos θ (punctual:
// f·E·cos θ) before the estimator's weight; SHADOW_NONE when it cannot contribute (no
// emitter, back face, below the surface, f = 0). A finite light is a segment between the two
// offset ends (t in (0, 1); a punctual light's end is the light itself); a light at infinity
// is a ray along its unit direction to VKPT_FAR. The light's pdf comes back for the caller's
// weight, and the BSDF's (0 for a delta light, which no BSDF sample can reach).
ShadowRay makeLightSampleRay(SurfacePoint s, vec4 u, out float lightPdfOut, out float bsdfPdfOut) {
    ShadowRay ray = ShadowRay(vec3(0.0), SHADOW_NONE, vec3(0.0), 1.0, vec3(0.0), 0.0);
    lightPdfOut = 0.0;
    bsdfPdfOut = 0.0;
    LightSample light = sampleLight(s.position, u);
    if (!light.valid || light.radiance == vec3(0.0)) return ray;
    float cosSurface = dot(light.direction, s.shadingNormal);
    if (cosSurface <= 0.0 || dot(light.direction, s.geometricNormal) <= 0.0) return ray;
    BsdfValue bsdf = evaluateSurfaceBsdf(s, light.direction);
    if (bsdf.f == vec3(0.0)) return ray;
    // Both ends move off their surfaces, so the shadow ray can hit neither of them.
    vec3 origin = offsetFromSurface(s.position, s.geometricNormal, s.coordinateScale);
    ray.origin = origin;
    ray.flags = SHADOW_SEGMENT;
    if (light.atInfinity) {
        ray.direction = light.direction;
        ray.tMax = VKPT_FAR;
    } else {
        vec3 target = light.delta ? light.position
                                  : offsetFromSurface(light.position, light.towardsReceiver,
                                                      light.coordinateScale);
        ray.direction = target - origin;
    }
    ray.contribution = bsdf.f * light.radiance * cosSurface;
    lightPdfOut = light.pdfSolidAngle;
    bsdfPdfOut = light.delta ? 0.0 : bsdf.pdf;
    return ray;
}

#endif // VKPT_LIGHTS_GLSL
