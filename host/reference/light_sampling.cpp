// light_sampling.cpp — emitter selection by the CDF, then a point, direction or incidence by
// the emitter's kind: uniform points on triangles, the cone of a sphere, punctual lights, the
// environment's luminance CDF.
#include "reference/light_sampling.h"

#include "prepare/emitters.h"
#include "shared/environment.h"
#include "shared/intersect.h"
#include "shared/path_rules.h"
#include "shared/punctual.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"
#include "shared/sphere.h"

namespace vkpt {

namespace {

// With one emitter there is no CDF to read: it is always the one.
std::uint32_t chooseEmitter(const PreparedScene& scene, float u) {
    return scene.emitterCdf.empty() ? 0u : selectEmitter(scene.emitterCdf, u);
}

bool emitsBothSides(const gpu::Material& material) {
    return (material.flags & MATERIAL_DOUBLE_SIDED) != 0;
}

void sampleTriangle(const PreparedScene& scene, const gpu::Emitter& emitter,
                    const glm::vec3& receiver, glm::vec2 u, LightSample& sample) {
    const gpu::Triangle& tri = scene.triangles[emitter.primitive];
    glm::vec3 b = gpu::sampleTriangleBarycentrics(u);
    sample.position = b.x * tri.v0 + b.y * tri.v1 + b.z * tri.v2;
    sample.coordinateScale = gpu::triangleCoordinateScale(tri.v0, tri.v1, tri.v2);
    glm::vec3 toLight = sample.position - receiver;
    float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return;
    sample.direction = toLight / std::sqrt(distanceSquared);
    glm::vec3 face = gpu::unitFaceNormal(tri.v0, tri.v1, tri.v2);
    float cosAtLight = -glm::dot(face, sample.direction);
    const gpu::Material& material = scene.materials[tri.materialIndex];
    if (cosAtLight > 0.0f || emitsBothSides(material)) {
        glm::vec2 uv = primitiveUv(scene, emitter.primitive, b.y, b.z, glm::vec3(0.0f));
        sample.radiance =
            material.emission * glm::vec3(sampleSlot(scene, material.emissiveTexture, uv, true));
    }
    sample.towardsReceiver = cosAtLight > 0.0f ? face : -face;
    sample.pdfSolidAngle = gpu::areaToSolidAnglePdf(emitter.selectProbability / emitter.area,
                                                    distanceSquared, cosAtLight);
    sample.valid = sample.pdfSolidAngle > 0.0f;
}

void sampleSphere(const PreparedScene& scene, const gpu::Emitter& emitter,
                  const glm::vec3& receiver, glm::vec2 u, LightSample& sample) {
    const gpu::Triangle& sphere = scene.triangles[emitter.primitive];
    gpu::SphereLightSample point = gpu::sampleSphereLight(receiver, sphere.v0, sphere.v1.x, u);
    if (!point.valid) return;
    sample.position = point.position;
    sample.coordinateScale = gpu::sphereCoordinateScale(sphere.v0, sphere.v1.x);
    glm::vec3 toLight = sample.position - receiver;
    float distance = glm::length(toLight);
    if (!(distance > 0.0f)) return;
    sample.direction = toLight / distance;
    bool facesReceiver = glm::dot(point.normal, sample.direction) < 0.0f;
    const gpu::Material& material = scene.materials[sphere.materialIndex];
    if (facesReceiver || emitsBothSides(material)) {
        glm::vec2 uv = primitiveUv(scene, emitter.primitive, 0.0f, 0.0f, point.normal);
        sample.radiance =
            material.emission * glm::vec3(sampleSlot(scene, material.emissiveTexture, uv, true));
    }
    sample.towardsReceiver = facesReceiver ? point.normal : -point.normal;
    sample.pdfSolidAngle = emitter.selectProbability * point.pdfSolidAngle;
    sample.valid = sample.pdfSolidAngle > 0.0f;
}

void samplePunctual(const gpu::Emitter& emitter, const glm::vec3& receiver, LightSample& sample) {
    gpu::PunctualIncidence incidence = gpu::punctualIncidence(emitter, receiver);
    if (!incidence.valid) return;
    sample.delta = true;
    sample.direction = incidence.direction;
    sample.radiance = incidence.irradiance;
    sample.pdfSolidAngle = emitter.selectProbability;
    if (emitter.kind == EMITTER_DIRECTIONAL) {
        sample.atInfinity = true;
    } else {
        sample.position = emitter.position; // a point: the shadow ray ends there exactly
    }
    sample.valid = sample.pdfSolidAngle > 0.0f;
}

void sampleEnvironmentLight(const PreparedScene& scene, const gpu::Emitter& emitter, glm::vec2 u,
                            LightSample& sample) {
    gpu::EnvironmentSample e = gpu::sampleEnvironment(
        scene.environment, u, scene.environmentTexels.data(), scene.environmentCdf.data());
    if (!e.valid) return;
    sample.atInfinity = true;
    sample.direction = e.direction;
    sample.radiance = e.radiance;
    sample.pdfSolidAngle = emitter.selectProbability * e.pdf;
    sample.valid = sample.pdfSolidAngle > 0.0f;
}

} // namespace

LightSample sampleLight(const PreparedScene& scene, const glm::vec3& receiver, const glm::vec4& u) {
    LightSample sample;
    if (scene.emitters.empty()) return sample;
    const gpu::Emitter& emitter = scene.emitters[chooseEmitter(scene, u.x)];
    const glm::vec2 uPoint(u.y, u.z);
    switch (emitter.kind) {
    case EMITTER_TRIANGLE:
        sampleTriangle(scene, emitter, receiver, uPoint, sample);
        break;
    case EMITTER_SPHERE:
        sampleSphere(scene, emitter, receiver, uPoint, sample);
        break;
    case EMITTER_ENVIRONMENT:
        sampleEnvironmentLight(scene, emitter, uPoint, sample);
        break;
    default:
        samplePunctual(emitter, receiver, sample);
        break;
    }
    return sample;
}

float lightPdf(const PreparedScene& scene, const SurfacePoint& surface, const glm::vec3& origin) {
    const gpu::Triangle& primitive = scene.triangles[surface.triangle];
    if (primitive.emitterIndex == NO_EMITTER) return 0.0f;
    const gpu::Emitter& emitter = scene.emitters[primitive.emitterIndex];
    if (gpu::isSpherePrimitive(primitive)) {
        return emitter.selectProbability *
               gpu::sphereLightPdf(origin, primitive.v0, primitive.v1.x, surface.position);
    }
    glm::vec3 toLight = surface.position - origin;
    float distanceSquared = glm::dot(toLight, toLight);
    float cosAtLight = glm::dot(surface.geometricNormal, toLight) / std::sqrt(distanceSquared);
    return gpu::areaToSolidAnglePdf(emitter.selectProbability / emitter.area, distanceSquared,
                                    cosAtLight);
}

float environmentLightPdf(const PreparedScene& scene, const glm::vec3& direction) {
    const std::uint32_t index = scene.environment.emitterIndex;
    if (index == NO_EMITTER) return 0.0f;
    return scene.emitters[index].selectProbability *
           gpu::environmentPdf(scene.environment, direction, scene.environmentTexels.data(),
                               scene.environmentCdf.data());
}

glm::vec3 environmentRadianceAlong(const PreparedScene& scene, const glm::vec3& direction) {
    if (scene.environment.emitterIndex == NO_EMITTER) return glm::vec3(0.0f);
    return gpu::environmentRadiance(scene.environment, direction, scene.environmentTexels.data(),
                                    scene.environmentCdf.data());
}

} // namespace vkpt
