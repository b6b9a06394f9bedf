// surface.h — what the integrators need to know about a hit: where, which way the surface
// faces the incoming ray, its material, and whether it emits towards the ray.
#pragma once

#include "bvh/bvh_traverse.h"
#include "prepare/prepared_scene.h"

namespace vkpt {

struct SurfacePoint {
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f}; // unit, on the side the ray came from
    glm::vec3 shadingNormal{0.0f};   // unit, interpolated, on the same side
    glm::vec3 rawShadingNormal{0.0f}; // interpolated as stored, for the normals integrator
    bool frontFace = false;          // the ray arrived on the counter-clockwise side
    float coordinateScale = 0.0f;    // of the triangle's vertices, for gpu::offsetFromSurface
    std::uint32_t triangle = 0;
    const gpu::Material* material = nullptr;
};

SurfacePoint makeSurfacePoint(const PreparedScene& scene, const ClosestHit& hit,
                              const glm::vec3& rayDirection);

// Emission leaves the front face only, unless the material is double-sided.
glm::vec3 emittedRadiance(const SurfacePoint& surface);

glm::vec3 lambertAlbedo(const SurfacePoint& surface);

} // namespace vkpt
