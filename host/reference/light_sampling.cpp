// light_sampling.cpp — emitter selection by the CDF, uniform points on the chosen triangle.
#include "reference/light_sampling.h"

#include "prepare/emitters.h"
#include "shared/intersect.h"
#include "shared/path_rules.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"

namespace vkpt {

LightSample sampleLight(const PreparedScene& scene, const glm::vec3& receiver, const glm::vec4& u) {
    LightSample sample;
    if (scene.emitters.empty()) return sample;
    const gpu::Emitter& emitter = scene.emitters[selectEmitter(scene.emitters, u.x)];
    const gpu::Triangle& tri = scene.triangles[emitter.triangleIndex];
    glm::vec3 b = gpu::sampleTriangleBarycentrics(glm::vec2(u.y, u.z));
    sample.position = b.x * tri.v0 + b.y * tri.v1 + b.z * tri.v2;
    sample.coordinateScale = gpu::triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    glm::vec3 toLight = sample.position - receiver;
    float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return sample;
    sample.direction = toLight / std::sqrt(distanceSquared);
    glm::vec3 face = gpu::unitFaceNormal(tri.v0, tri.v1, tri.v2);
    float cosAtLight = -glm::dot(face, sample.direction);
    const gpu::Material& material = scene.materials[tri.materialIndex];
    bool doubleSided = (material.flags & MATERIAL_DOUBLE_SIDED) != 0;
    sample.radiance = (cosAtLight > 0.0f || doubleSided) ? material.emission : glm::vec3(0.0f);
    sample.towardsReceiver = cosAtLight > 0.0f ? face : -face;
    sample.pdfSolidAngle = gpu::areaToSolidAnglePdf(emitter.selectProbability / emitter.area,
                                                    distanceSquared, cosAtLight);
    sample.valid = sample.pdfSolidAngle > 0.0f;
    return sample;
}

float lightPdf(const PreparedScene& scene, const SurfacePoint& surface, const glm::vec3& origin) {
    std::uint32_t index = scene.triangles[surface.triangle].emitterIndex;
    if (index == NO_EMITTER) return 0.0f;
    const gpu::Emitter& emitter = scene.emitters[index];
    glm::vec3 toLight = surface.position - origin;
    float distanceSquared = glm::dot(toLight, toLight);
    float cosAtLight = glm::dot(surface.geometricNormal, toLight) / std::sqrt(distanceSquared);
    return gpu::areaToSolidAnglePdf(emitter.selectProbability / emitter.area, distanceSquared,
                                    cosAtLight);
}

} // namespace vkpt
