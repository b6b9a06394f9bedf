// gpu_materials.cpp — SceneMaterial → gpu::Material, SceneTexture + SceneImage → texels.
#include "prepare/gpu_materials.h"

#include <cmath>
#include <limits>

#include "common/errors.h"

namespace vkpt {

namespace {

gpu::TextureSlot makeSlot(const TextureReference& reference) {
    gpu::TextureSlot slot{};
    // glm::mat3 is column-major: transform[column][row].
    const glm::mat3& m = reference.transform;
    slot.transformRow0 = glm::vec3(m[0][0], m[1][0], m[2][0]);
    slot.transformRow1 = glm::vec3(m[0][1], m[1][1], m[2][1]);
    slot.texture = reference.texture < 0 ? NO_TEXTURE : std::uint32_t(reference.texture);
    return slot;
}

// KHR_materials_ior: the dielectric's normal-incidence reflectance ((ior − 1)/(ior + 1))²
// (the extension's formula with an outside ior of 1), in double so that ior 1.5 gives 0.04f,
// the constant the BRDF used before the extension, to the bit.
float iorF0(float ior) {
    const double r = (double(ior) - 1.0) / (double(ior) + 1.0);
    return float(r * r);
}

// KHR_materials_volume's Beer–Lambert coefficient per channel: light that travels
// attenuationDistance keeps attenuationColor, so σ = −ln(attenuationColor)/attenuationDistance.
// An infinite distance is no attenuation; a black channel is opaque (the largest float, whose
// product with any distance past 1e-38 still ends the light).
glm::vec3 attenuationCoefficient(const SceneMaterial& m) {
    if (!(m.thickness > 0.0f) || std::isinf(m.attenuationDistance)) return glm::vec3(0.0f);
    glm::vec3 sigma;
    for (int c = 0; c < 3; ++c) {
        const double colour = double(m.attenuationColor[c]);
        const double value = colour > 0.0 ? -std::log(colour) / double(m.attenuationDistance)
                                          : double(std::numeric_limits<float>::max());
        sigma[c] = float(std::min(value, double(std::numeric_limits<float>::max())));
    }
    return sigma;
}

std::uint32_t samplerBits(const SceneTexture& texture) {
    return std::uint32_t(texture.wrapS) | (std::uint32_t(texture.wrapT) << 2) |
           (texture.nearest ? TEXTURE_FILTER_NEAREST : 0u);
}

} // namespace

std::vector<gpu::Material> makeGpuMaterials(const std::vector<SceneMaterial>& materials) {
    std::vector<gpu::Material> result;
    result.reserve(materials.size());
    for (const SceneMaterial& m : materials) {
        gpu::Material g{};
        g.baseColor = m.baseColor;
        g.emission = m.emission;
        const bool specularLobes =
            m.hasSpecularTextures() || m.hasAnisotropy() || m.hasIridescence();
        g.flags = (m.doubleSided ? MATERIAL_DOUBLE_SIDED : 0u) |
                  (m.isDiffuseOnly() ? 0u : MATERIAL_METALLIC_ROUGHNESS) |
                  (specularLobes ? MATERIAL_SPECULAR_LOBES : 0u) |
                  (m.hasDiffuseTransmission() || m.hasDispersion() ? MATERIAL_LOBES : 0u);
        g.metallic = m.metallic;
        g.roughness = m.roughness;
        g.alphaCutoff = m.alphaCutoff;
        g.alphaMode = std::uint32_t(m.alphaMode);
        g.specularColor = m.specularColor;
        g.specular = m.specular;
        g.baseColorTexture = makeSlot(m.baseColorTexture);
        g.metallicRoughnessTexture = makeSlot(m.metallicRoughnessTexture);
        g.emissiveTexture = makeSlot(m.emissiveTexture);
        g.normalTexture = makeSlot(m.normalTexture);
        g.normalScale = m.normalScale;
        g.transmission = m.transmission;
        g.ior = m.ior;
        g.iorF0 = iorF0(m.ior);
        g.thickness = m.thickness;
        g.attenuationCoefficient = attenuationCoefficient(m);
        g.transmissionTexture = makeSlot(m.transmissionTexture);
        g.sheenColor = m.sheenColor;
        g.sheenRoughness = m.sheenRoughness;
        g.clearcoat = m.clearcoat;
        g.clearcoatRoughness = m.clearcoatRoughness;
        g.clearcoatTexture = makeSlot(m.clearcoatTexture);
        g.clearcoatRoughnessTexture = makeSlot(m.clearcoatRoughnessTexture);
        g.clearcoatNormalTexture = makeSlot(m.clearcoatNormalTexture);
        g.clearcoatNormalScale = m.clearcoatNormalScale;
        g.sheenColorTexture = makeSlot(m.sheenColorTexture);
        g.sheenRoughnessTexture = makeSlot(m.sheenRoughnessTexture);
        result.push_back(g);
    }
    return result;
}

std::vector<gpu::SpecularLobeParams>
makeGpuSpecularLobes(const std::vector<SceneMaterial>& materials) {
    std::vector<gpu::SpecularLobeParams> result;
    result.reserve(materials.size());
    for (const SceneMaterial& m : materials) {
        gpu::SpecularLobeParams g{};
        g.specularTexture = makeSlot(m.specularTexture);
        g.specularColorTexture = makeSlot(m.specularColorTexture);
        g.anisotropyStrength = m.hasAnisotropy() ? m.anisotropyStrength : 0.0f;
        g.anisotropyRotationCos = float(std::cos(double(m.anisotropyRotation)));
        g.anisotropyRotationSin = float(std::sin(double(m.anisotropyRotation)));
        g.anisotropyTexture = makeSlot(m.anisotropyTexture);
        g.iridescence = m.hasIridescence() ? m.iridescence : 0.0f;
        g.iridescenceIor = m.iridescenceIor;
        g.iridescenceThicknessMinimum = m.iridescenceThicknessMinimum;
        g.iridescenceThicknessMaximum = m.iridescenceThicknessMaximum;
        g.iridescenceTexture = makeSlot(m.iridescenceTexture);
        g.iridescenceThicknessTexture = makeSlot(m.iridescenceThicknessTexture);
        result.push_back(g);
    }
    return result;
}

std::vector<gpu::MaterialLobes> makeGpuMaterialLobes(const std::vector<SceneMaterial>& materials) {
    std::vector<gpu::MaterialLobes> result;
    result.reserve(materials.size());
    for (const SceneMaterial& m : materials) {
        gpu::MaterialLobes g{};
        g.diffuseTransmission = m.hasDiffuseTransmission() ? m.diffuseTransmission : 0.0f;
        g.diffuseTransmissionColor = m.diffuseTransmissionColor;
        g.diffuseTransmissionTexture = makeSlot(m.diffuseTransmissionTexture);
        g.diffuseTransmissionColorTexture = makeSlot(m.diffuseTransmissionColorTexture);
        g.dispersion = m.hasDispersion() ? m.dispersion : 0.0f;
        result.push_back(g);
    }
    return result;
}

GpuTextures makeGpuTextures(const Scene& scene) {
    GpuTextures result;
    std::vector<std::uint64_t> imageOffsets;
    imageOffsets.reserve(scene.images.size());
    for (const SceneImage& image : scene.images) {
        imageOffsets.push_back(result.texels.size());
        result.texels.insert(result.texels.end(), image.texels.begin(), image.texels.end());
    }
    if (result.texels.size() > std::numeric_limits<std::uint32_t>::max())
        throw InputError(scene.sourcePath + ": textures hold " +
                         std::to_string(result.texels.size()) +
                         " texels, more than 2^32 − 1 (32-bit texel offsets)");
    for (const SceneTexture& texture : scene.textures) {
        const auto image = std::size_t(texture.image);
        VKPT_ASSERT(image < scene.images.size(), "texture image index checked by the loader");
        result.textures.push_back({std::uint32_t(imageOffsets[image]), scene.images[image].width,
                                   scene.images[image].height, samplerBits(texture)});
    }
    return result;
}

} // namespace vkpt
