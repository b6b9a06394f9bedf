// surface.h — what the integrators need to know about a hit: where, which way the surface
// faces the incoming ray, its material with textures applied, and its emission.
#pragma once

#include "bvh/bvh_traverse.h"
#include "prepare/prepared_scene.h"
#include "shared/bsdf.h"

namespace vkpt {

struct SurfacePoint {
    glm::vec3 position{0.0f};
    glm::vec3 geometricNormal{0.0f};  // unit, on the side the ray came from
    glm::vec3 shadingNormal{0.0f};    // unit, interpolated, on the same side
    glm::vec3 rawShadingNormal{0.0f}; // as stored (a sphere's outward normal), for the normals view
    bool frontFace = false;           // triangle: the counter-clockwise side; sphere: outside
    float coordinateScale = 0.0f;     // of the primitive, for gpu::offsetFromSurface
    std::uint32_t triangle = 0;       // the primitive, BVH-ordered
    const gpu::Material* material = nullptr;
    glm::vec2 uv{0.0f};             // TEXCOORD_0 (spheres: gpu::sphereUv), when textured
    gpu::ShadingMaterial shading{}; // the BSDF's parameters, textures applied
    glm::vec3 emission{0.0f};       // emissive factor × texture, before the side test
    glm::vec3 outgoing{0.0f};       // unit, back along the incoming ray
};

// The BSDF at a surface point for world directions: value f (no cosine) and the solid-angle
// pdf with which sampleBsdf would choose wi, both in the shading normal's frame.
struct BsdfValue {
    glm::vec3 f{0.0f};
    float pdf = 0.0f;
};
BsdfValue evaluateSurfaceBsdf(const SurfacePoint& surface, const glm::vec3& wi);

// The hit of a ray from `origin` along `direction` (the query that found `hit`).
SurfacePoint makeSurfacePoint(const PreparedScene& scene, const ClosestHit& hit,
                              const glm::vec3& origin, const glm::vec3& direction);

// Emission leaves the front face only, unless the material is double-sided.
glm::vec3 emittedRadiance(const SurfacePoint& surface);

// Texture coordinates of a point of primitive `index`: barycentric (u, v) on a triangle, or
// the outward normal's sphereUv on a sphere. (0, 0) when the scene has no texture coordinates.
glm::vec2 primitiveUv(const PreparedScene& scene, std::uint32_t index, float u, float v,
                      const glm::vec3& sphereNormal);

// A texture slot of a material at uv: the texel value, or 1 when the slot is empty.
glm::vec4 sampleSlot(const PreparedScene& scene, const gpu::TextureSlot& slot, glm::vec2 uv,
                     bool srgb);

// Alpha MASK: whether the hit on `index` at (u, v) / sphere normal lets rays through.
bool alphaMasked(const PreparedScene& scene, std::uint32_t index, float u, float v,
                 const glm::vec3& sphereNormal);

} // namespace vkpt
