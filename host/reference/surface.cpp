// surface.cpp — hit points from barycentrics, normals turned towards the incoming ray.
#include "reference/surface.h"

#include "shared/intersect.h"
#include "shared/ray_offset.h"

namespace vkpt {

namespace {

glm::vec3 interpolate(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, float u, float v) {
    return glm::vec3(a) * (1.0f - u - v) + glm::vec3(b) * u + glm::vec3(c) * v;
}

} // namespace

SurfacePoint makeSurfacePoint(const PreparedScene& scene, const ClosestHit& hit,
                              const glm::vec3& rayDirection) {
    const gpu::Triangle& tri = scene.triangles[hit.triangle];
    const gpu::TriangleNormals& normals = scene.normals[hit.triangle];
    SurfacePoint s;
    s.triangle = hit.triangle;
    s.material = &scene.materials[tri.materialIndex];
    // Barycentric interpolation keeps the point on the triangle's plane, unlike o + t·d.
    s.position = tri.v0 * (1.0f - hit.u - hit.v) + tri.v1 * hit.u + tri.v2 * hit.v;
    s.coordinateScale = gpu::triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    glm::vec3 face = gpu::unitFaceNormal(tri.v0, tri.v1, tri.v2);
    s.frontFace = glm::dot(face, rayDirection) < 0.0f;
    s.geometricNormal = s.frontFace ? face : -face;
    s.rawShadingNormal = interpolate(normals.n0, normals.n1, normals.n2, hit.u, hit.v);
    float rawLength = glm::length(s.rawShadingNormal);
    glm::vec3 shading = rawLength > 0.0f ? s.rawShadingNormal / rawLength : s.geometricNormal;
    s.shadingNormal = glm::dot(shading, s.geometricNormal) < 0.0f ? -shading : shading;
    return s;
}

glm::vec3 emittedRadiance(const SurfacePoint& surface) {
    bool emitsHere = surface.frontFace || (surface.material->flags & MATERIAL_DOUBLE_SIDED) != 0;
    return emitsHere ? surface.material->emission : glm::vec3(0.0f);
}

glm::vec3 lambertAlbedo(const SurfacePoint& surface) {
    return glm::vec3(surface.material->baseColor);
}

} // namespace vkpt
