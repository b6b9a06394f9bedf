// emitters.h — the list light sampling chooses from: emitting triangles and spheres, the
// KHR_lights_punctual lights and the environment, each selected in proportion to its power.
#pragma once

#include <span>
#include <vector>

#include "scene/scene.h"
#include "shared/host_device.h"

namespace vkpt {

struct EmitterList {
    std::vector<gpu::Emitter> emitters;
    std::vector<float> cdf;     // inclusive selection CDF, one entry per emitter, the last 1
    std::vector<double> powers; // each emitter's selection weight, as described below
    double totalPower = 0.0;    // Σ of the powers below, in radiance units × area × solid angle
};

// What buildEmitters needs besides the scene and its primitives: for the lights that reach the
// whole scene (directional, environment), the radius of its bounding sphere.
struct EmitterSources {
    double environmentPower = 0.0; // 0: no environment
    double sceneRadius = 1.0;
};

// Builds the list and writes each emitting primitive's emitterIndex (NO_EMITTER elsewhere);
// `primitives` are the scene's triangles and spheres in the prepared (BVH) order. Powers (the
// selection weights): an emitting surface π·L·A per emitting side (triangle) or π·L·4πr²
// (sphere), a point light 4π·I, a spot light 2π(1 − (cos θi + cos θo)/2)·I (pbrt-v3's estimate),
// a directional light π·R²·E, the environment as given; L, I and E by luminance, a triangle's L
// its emission averaged over it, emissive texture included (emission_mean.h: a black-textured
// triangle gets power 0 and is never chosen), a sphere's its factor's. Zero-area triangles
// cannot be hit or sampled, so they are left out; a triangle that repeats an earlier emitting
// one (same corners in the same order, same material) shares its record.
EmitterList buildEmitters(const Scene& scene, std::span<gpu::Triangle> primitives,
                          std::span<const gpu::Material> materials, const EmitterSources& sources);

float triangleArea(const gpu::Triangle& triangle);

} // namespace vkpt
