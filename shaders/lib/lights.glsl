// lights.glsl — next-event estimation's half of the kernels, as host/reference/light_sampling.cpp
// and direct_lighting.cpp do it: an emitter chosen by power, a uniform point on it, the
// shadow segment between the two offset points, and the solid-angle pdf of reaching an emitter
// by a BSDF sample. Needs frame, triangles, materials and emitters declared.
#ifndef VKPT_LIGHTS_GLSL
#define VKPT_LIGHTS_GLSL

#include "lib/surface.glsl"
#include "shared/path_rules.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"

// The first emitter whose inclusive cdf exceeds u (std::upper_bound), the last one if none.
uint selectEmitter(float u) {
    uint lo = 0u;
    uint hi = frame.emitterCount;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (u < emitters[mid].cdf) {
            hi = mid;
        } else {
            lo = mid + 1u;
        }
    }
    return min(lo, frame.emitterCount - 1u);
}

struct LightSample {
    vec3 position;
    vec3 towardsReceiver; // unit emitter normal turned towards the receiver
    vec3 direction;       // unit, receiver → light
    vec3 radiance;        // emitted towards the receiver (0 from a back face)
    float pdfSolidAngle;
    float coordinateScale; // of the emitter triangle's vertices, for offsetFromSurface
    bool valid; // false: no emitters, or the point is seen edge-on
};

// u.x selects the emitter, u.yz the point on it.
LightSample sampleLight(vec3 receiver, vec4 u) {
    // Named `light`: `sample` is a GLSL keyword.
    LightSample light = LightSample(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), 0.0, 0.0, false);
    if (frame.emitterCount == 0u) return light;
    Emitter emitter = emitters[selectEmitter(u.x)];
    Triangle tri = triangles[emitter.triangleIndex];
    vec3 b = sampleTriangleBarycentrics(vec2(u.y, u.z));
    light.position = b.x * tri.v0 + b.y * tri.v1 + b.z * tri.v2;
    light.coordinateScale = triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    vec3 toLight = light.position - receiver;
    float distanceSquared = dot(toLight, toLight);
    if (!(distanceSquared > 0.0)) return light;
    light.direction = toLight / sqrt(distanceSquared);
    vec3 face = unitFaceNormal(tri.v0, tri.v1, tri.v2);
    float cosAtLight = -dot(face, light.direction);
    Material material = materials[tri.materialIndex];
    bool doubleSided = (material.flags & MATERIAL_DOUBLE_SIDED) != 0u;
    light.radiance = (cosAtLight > 0.0 || doubleSided) ? material.emission : vec3(0.0);
    light.towardsReceiver = cosAtLight > 0.0 ? face : -face;
    light.pdfSolidAngle =
        areaToSolidAnglePdf(emitter.selectProbability / emitter.area, distanceSquared, cosAtLight);
    light.valid = light.pdfSolidAngle > 0.0;
    return light;
}

// Solid-angle pdf with which sampleLight would have produced the hit `s` from `origin`.
float lightPdf(SurfacePoint s, vec3 origin) {
    uint index = triangles[s.triangle].emitterIndex;
    if (index == NO_EMITTER) return 0.0;
    Emitter emitter = emitters[index];
    vec3 toLight = s.position - origin;
    float distanceSquared = dot(toLight, toLight);
    float cosAtLight = dot(s.geometricNormal, toLight) / sqrt(distanceSquared);
    return areaToSolidAnglePdf(emitter.selectProbability / emitter.area, distanceSquared,
                               cosAtLight);
}

// One light sample at `s`, as a shadow segment whose contribution is f·Le·cos θ (before the
// estimator's weight); SHADOW_NONE when it cannot contribute (no emitter, back face, below
// the surface). bsdfPdf and lightPdf come back for the caller's weight.
ShadowRay makeLightSampleRay(SurfacePoint s, vec4 u, out float lightPdfOut, out float bsdfPdf) {
    ShadowRay ray = ShadowRay(vec3(0.0), SHADOW_NONE, vec3(0.0), 1.0, vec3(0.0), 0.0);
    lightPdfOut = 0.0;
    bsdfPdf = 0.0;
    LightSample light = sampleLight(s.position, u);
    if (!light.valid || light.radiance == vec3(0.0)) return ray;
    float cosSurface = dot(light.direction, s.shadingNormal);
    if (cosSurface <= 0.0 || dot(light.direction, s.geometricNormal) <= 0.0) return ray;
    // Both ends move off their surfaces, so the shadow ray can hit neither of them.
    vec3 origin = offsetFromSurface(s.position, s.geometricNormal, s.coordinateScale);
    vec3 target = offsetFromSurface(light.position, light.towardsReceiver, light.coordinateScale);
    ray.origin = origin;
    ray.flags = SHADOW_SEGMENT;
    ray.direction = target - origin;
    ray.contribution = lambertAlbedo(s) * VKPT_INV_PI * light.radiance * cosSurface;
    lightPdfOut = light.pdfSolidAngle;
    bsdfPdf = cosineHemispherePdf(cosSurface);
    return ray;
}

#endif // VKPT_LIGHTS_GLSL
