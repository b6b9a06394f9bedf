// surface.cpp — hit points on triangles and spheres, normals turned towards the incoming ray,
// materials read through their textures.
#include "reference/surface.h"

#include "shared/intersect.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"
#include "shared/sphere.h"
#include "shared/texture_sampling.h"

namespace vkpt {

namespace {

glm::vec3 interpolate(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, float u,
                      float v) {
    return glm::vec3(a) * (1.0f - u - v) + glm::vec3(b) * u + glm::vec3(c) * v;
}

void fillTriangle(const PreparedScene& scene, const ClosestHit& hit, const glm::vec3& direction,
                  SurfacePoint& s) {
    const gpu::Triangle& tri = scene.triangles[hit.triangle];
    const gpu::TriangleNormals& normals = scene.normals[hit.triangle];
    // Barycentric interpolation keeps the point on the triangle's plane, unlike o + t·d.
    s.position = tri.v0 * (1.0f - hit.u - hit.v) + tri.v1 * hit.u + tri.v2 * hit.v;
    s.coordinateScale = gpu::triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    glm::vec3 face = gpu::unitFaceNormal(tri.v0, tri.v1, tri.v2);
    s.frontFace = glm::dot(face, direction) < 0.0f;
    s.geometricNormal = s.frontFace ? face : -face;
    s.rawShadingNormal = interpolate(normals.n0, normals.n1, normals.n2, hit.u, hit.v);
    float rawLength = glm::length(s.rawShadingNormal);
    glm::vec3 shading = rawLength > 0.0f ? s.rawShadingNormal / rawLength : s.geometricNormal;
    s.shadingNormal = glm::dot(shading, s.geometricNormal) < 0.0f ? -shading : shading;
}

// The point is put back on the sphere along its normal, so that its distance from the surface
// is the radius' rounding, not o + t·d's.
void fillSphere(const PreparedScene& scene, const ClosestHit& hit, const glm::vec3& origin,
                const glm::vec3& direction, SurfacePoint& s) {
    const gpu::Triangle& sphere = scene.triangles[hit.triangle];
    const glm::vec3 outward = gpu::sphereNormalAt(origin + hit.t * direction, sphere.v0);
    s.position = sphere.v0 + sphere.v1.x * outward;
    s.coordinateScale = gpu::sphereCoordinateScale(sphere.v0, sphere.v1.x);
    s.frontFace = glm::dot(outward, direction) < 0.0f;
    s.geometricNormal = s.frontFace ? outward : -outward;
    s.rawShadingNormal = outward;
    s.shadingNormal = s.geometricNormal;
}

} // namespace

glm::vec2 primitiveUv(const PreparedScene& scene, std::uint32_t index, float u, float v,
                      const glm::vec3& sphereNormal) {
    if (scene.uvs.empty()) return glm::vec2(0.0f);
    if (gpu::isSpherePrimitive(scene.triangles[index])) return gpu::sphereUv(sphereNormal);
    const glm::vec2* t = &scene.uvs[3 * std::size_t(index)];
    return t[0] * (1.0f - u - v) + t[1] * u + t[2] * v;
}

glm::vec4 sampleSlot(const PreparedScene& scene, const gpu::TextureSlot& slot, glm::vec2 uv,
                     bool srgb) {
    if (slot.texture == NO_TEXTURE || scene.textures.empty()) return glm::vec4(1.0f);
    return gpu::sampleTexture(scene.textures[slot.texture], gpu::transformUv(slot, uv), srgb,
                              scene.texels.data());
}

bool alphaMasked(const PreparedScene& scene, std::uint32_t index, float u, float v,
                 const glm::vec3& sphereNormal) {
    const gpu::Material& m = scene.materials[scene.triangles[index].materialIndex];
    if (m.alphaMode != ALPHA_MODE_MASK) return false;
    float alpha = m.baseColor.a;
    if (m.baseColorTexture.texture != NO_TEXTURE) {
        glm::vec2 uv = primitiveUv(scene, index, u, v, sphereNormal);
        alpha *= sampleSlot(scene, m.baseColorTexture, uv, true).a;
    }
    return alpha < m.alphaCutoff;
}

SurfacePoint makeSurfacePoint(const PreparedScene& scene, const ClosestHit& hit,
                              const glm::vec3& origin, const glm::vec3& direction) {
    SurfacePoint s;
    s.triangle = hit.triangle;
    const gpu::Triangle& primitive = scene.triangles[hit.triangle];
    s.material = &scene.materials[primitive.materialIndex];
    if (gpu::isSpherePrimitive(primitive)) {
        fillSphere(scene, hit, origin, direction, s);
    } else {
        fillTriangle(scene, hit, direction, s);
    }
    const gpu::Material& m = *s.material;
    s.uv = primitiveUv(scene, hit.triangle, hit.u, hit.v, s.rawShadingNormal);
    glm::vec4 baseColor = m.baseColor * sampleSlot(scene, m.baseColorTexture, s.uv, true);
    glm::vec4 metalRough = sampleSlot(scene, m.metallicRoughnessTexture, s.uv, false);
    s.shading = gpu::makeShadingMaterial(glm::vec3(baseColor), m.metallic * metalRough.b,
                                         m.roughness * metalRough.g, m.specular, m.specularColor,
                                         (m.flags & MATERIAL_METALLIC_ROUGHNESS) != 0);
    s.emission = m.emission * glm::vec3(sampleSlot(scene, m.emissiveTexture, s.uv, true));
    s.outgoing = -glm::normalize(direction);
    return s;
}

BsdfValue evaluateSurfaceBsdf(const SurfacePoint& surface, const glm::vec3& wi) {
    gpu::Basis basis = gpu::makeBasis(surface.shadingNormal);
    glm::vec3 wo = gpu::worldToBasis(basis, surface.outgoing);
    glm::vec3 wiLocal = gpu::worldToBasis(basis, wi);
    return {gpu::evaluateBsdf(surface.shading, wo, wiLocal),
            gpu::bsdfPdf(surface.shading, wo, wiLocal)};
}

glm::vec3 emittedRadiance(const SurfacePoint& surface) {
    bool emitsHere = surface.frontFace || (surface.material->flags & MATERIAL_DOUBLE_SIDED) != 0;
    return emitsHere ? surface.emission : glm::vec3(0.0f);
}

} // namespace vkpt
