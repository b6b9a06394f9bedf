// gpu_materials.cpp — SceneMaterial → gpu::Material, SceneTexture + SceneImage → texels.
#include "prepare/gpu_materials.h"

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
        g.flags = (m.doubleSided ? MATERIAL_DOUBLE_SIDED : 0u) |
                  (m.isDiffuseOnly() ? 0u : MATERIAL_METALLIC_ROUGHNESS);
        g.metallic = m.metallic;
        g.roughness = m.roughness;
        g.alphaCutoff = m.alphaCutoff;
        g.alphaMode = std::uint32_t(m.alphaMode);
        g.specularColor = m.specularColor;
        g.specular = m.specular;
        g.baseColorTexture = makeSlot(m.baseColorTexture);
        g.metallicRoughnessTexture = makeSlot(m.metallicRoughnessTexture);
        g.emissiveTexture = makeSlot(m.emissiveTexture);
        g.sheenColor = m.sheenColor;
        g.sheenRoughness = m.sheenRoughness;
        g.clearcoat = m.clearcoat;
        g.clearcoatRoughness = m.clearcoatRoughness;
        g.clearcoatTexture = makeSlot(m.clearcoatTexture);
        g.clearcoatRoughnessTexture = makeSlot(m.clearcoatRoughnessTexture);
        g.sheenColorTexture = makeSlot(m.sheenColorTexture);
        g.sheenRoughnessTexture = makeSlot(m.sheenRoughnessTexture);
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
