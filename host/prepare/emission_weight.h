// emission_weight.h — how bright an emitting triangle is on average, for light sampling's
// selection weights: the emissive factor times the mean of its emissive texture over the
// triangle. A texture that is mostly black (an emissive map of a few lit details) would
// otherwise draw as many light samples as a uniformly lit surface of the same factor.
#pragma once

#include <cstdint>
#include <span>

#include "shared/host_device.h"

namespace vkpt {

// What an emissive texture needs to be read on the host: the prepared textures and texels
// and three texture coordinates per primitive (all empty in a scene without textures).
struct EmissionTextures {
    std::span<const gpu::TextureInfo> textures;
    std::span<const std::uint32_t> texels;
    std::span<const glm::vec2> uvs;
};

// The least weight a textured emitter keeps, as a fraction of its untextured weight: a
// texture's bright parts that the estimate below misses must still be reachable by light
// sampling, or the estimator would lose their light (any positive weight keeps it unbiased).
inline constexpr double kMinEmissionTextureWeight = 1.0 / 64.0;

// The luminance of the emitted radiance of triangle `primitive`, averaged over its area: the
// material's emission times its emissive texture, read as shading reads it at 8 × 8 points
// stratified uniformly over the triangle, and at least kMinEmissionTextureWeight of the
// untextured luminance. Without an emissive texture (or texture coordinates), the emission's
// luminance.
double meanEmittedLuminance(std::uint32_t primitive, const gpu::Material& material,
                            const EmissionTextures& textures);

} // namespace vkpt
