// emission_weight.cpp — the mean emitted luminance of a triangle with an emissive texture.
#include "prepare/emission_weight.h"

#include <algorithm>
#include <cmath>

#include "shared/sampling.h"
#include "shared/texture_sampling.h"

namespace vkpt {

namespace {

constexpr int kStrata = 8; // per side of the unit square warped onto the triangle

bool hasEmissiveTexture(std::uint32_t primitive, const gpu::Material& material,
                        const EmissionTextures& textures) {
    const std::uint32_t texture = material.emissiveTexture.texture;
    return texture != NO_TEXTURE && texture < textures.textures.size() &&
           3u * std::size_t(primitive) + 2u < textures.uvs.size();
}

} // namespace

double meanEmittedLuminance(std::uint32_t primitive, const gpu::Material& material,
                            const EmissionTextures& textures) {
    const double untextured = double(gpu::luminance(material.emission));
    if (!hasEmissiveTexture(primitive, material, textures)) return untextured;
    const gpu::TextureSlot& slot = material.emissiveTexture;
    const gpu::TextureInfo& info = textures.textures[slot.texture];
    const glm::vec2* corner = &textures.uvs[3u * std::size_t(primitive)];
    double sum = 0.0;
    for (int a = 0; a < kStrata; ++a)
        for (int b = 0; b < kStrata; ++b) {
            // The square-root warp maps the unit square uniformly onto the triangle.
            const float s = std::sqrt((float(a) + 0.5f) / float(kStrata));
            const float t = (float(b) + 0.5f) / float(kStrata);
            const glm::vec2 uv =
                (1.0f - s) * corner[0] + s * (1.0f - t) * corner[1] + s * t * corner[2];
            const glm::vec4 texel = gpu::sampleTexture(info, gpu::transformUv(slot, uv), true,
                                                       textures.texels.data());
            sum += double(gpu::luminance(material.emission * glm::vec3(texel)));
        }
    const double mean = sum / double(kStrata * kStrata);
    return std::max(mean, kMinEmissionTextureWeight * untextured);
}

} // namespace vkpt
