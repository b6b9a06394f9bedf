// emitter_power.cpp — the mean emitted luminance of a primitive, its emissive texture included.
#include "prepare/emitter_power.h"

#include <algorithm>
#include <cmath>

#include "shared/materials.h"
#include "shared/sampling.h"

namespace vkpt {

namespace {

constexpr std::uint32_t kMinGrid = 4;
constexpr std::uint32_t kMaxGrid = 16;

// The texels the triangle covers on its emissive texture (TEXCOORD_0 before any transform),
// which sets how fine the grid must be to see each of them about once.
double coveredTexels(std::uint32_t primitiveIndex, const gpu::Material& material,
                     const gpu::SceneView& view) {
    const gpu::TextureInfo texture = view.textures[material.emissiveTexture.texture];
    const glm::vec2 t0 = view.uvs[3 * primitiveIndex];
    const glm::vec2 t1 = view.uvs[3 * primitiveIndex + 1];
    const glm::vec2 t2 = view.uvs[3 * primitiveIndex + 2];
    const glm::vec2 a = t1 - t0;
    const glm::vec2 b = t2 - t0;
    const double uvArea = 0.5 * std::abs(double(a.x) * b.y - double(a.y) * b.x);
    return uvArea * double(texture.width) * double(texture.height);
}

std::uint32_t gridSize(double texels) {
    const double side = std::ceil(std::sqrt(std::max(texels, 0.0)));
    return std::uint32_t(std::clamp(side, double(kMinGrid), double(kMaxGrid)));
}

// The emission at the grid point (i, j) of an n × n grid on the primitive.
glm::vec3 emissionAtGridPoint(std::uint32_t primitiveIndex, const gpu::Triangle& primitive,
                              const gpu::Material& material, glm::vec2 u,
                              const gpu::SceneView& view) {
    if (gpu::isSpherePrimitive(primitive)) {
        const glm::vec3 normal = gpu::sampleUniformSphere(u);
        return gpu::emissionAt(
            material, gpu::primitiveUv(primitiveIndex, primitive, 0.0f, 0.0f, normal, view), view);
    }
    const glm::vec3 b = gpu::sampleTriangleBarycentrics(u);
    return gpu::emissionAt(
        material, gpu::primitiveUv(primitiveIndex, primitive, b.y, b.z, glm::vec3(0.0f), view),
        view);
}

} // namespace

double meanEmittedLuminance(std::uint32_t primitiveIndex, const gpu::SceneView& view) {
    const gpu::Triangle& primitive = view.primitives[primitiveIndex];
    const gpu::Material& material = view.materials[primitive.materialIndex];
    if (!gpu::hasTexture(material.emissiveTexture, view))
        return double(gpu::luminance(material.emission));
    const std::uint32_t n = gpu::isSpherePrimitive(primitive)
                                ? kMaxGrid
                                : gridSize(coveredTexels(primitiveIndex, material, view));
    double sum = 0.0;
    for (std::uint32_t i = 0; i < n; ++i)
        for (std::uint32_t j = 0; j < n; ++j) {
            const glm::vec2 u((float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n));
            sum += double(
                gpu::luminance(emissionAtGridPoint(primitiveIndex, primitive, material, u, view)));
        }
    return sum / double(n * n);
}

} // namespace vkpt
