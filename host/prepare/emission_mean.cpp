// emission_mean.cpp — an emissive texture read at the nearest texel and averaged over a
// triangle at stratified points.
#include "prepare/emission_mean.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "shared/texture_sampling.h"

namespace vkpt {

namespace {

// Points per triangle edge for averaging a texture over it (k² points): enough that a triangle
// spanning many texels is averaged over them, few enough for 10^5 emitting triangles.
constexpr int kMaxPointsPerEdge = 8;

// The sRGB decoding of each byte value, as the kernels decode an emissive texel.
const std::array<float, 256>& srgbByteToLinear() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i)
            t[std::size_t(i)] = gpu::srgbChannelToLinear(float(i) / 255.0f);
        return t;
    }();
    return table;
}

// An emissive texture read at the nearest texel, with the material's transform and the
// sampler's wrap modes (the kernels filter bilinearly; for an average over a triangle the
// difference is a fraction of a texel at its rim).
class EmissiveTexture {
public:
    EmissiveTexture(const Scene& scene, const TextureReference& reference)
        : transform_(reference.transform) {
        const SceneTexture& texture = scene.textures[std::size_t(reference.texture)];
        image_ = &scene.images[std::size_t(texture.image)];
        wrapS_ = std::uint32_t(texture.wrapS);
        wrapT_ = std::uint32_t(texture.wrapT);
    }

    glm::vec3 at(glm::vec2 uv) const {
        const int width = int(image_->width), height = int(image_->height);
        if (width <= 0 || height <= 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y))
            return glm::vec3(1.0f);
        const float s = gpu::reduceTextureCoordinate(uv.x, wrapS_) * float(width);
        const float t = gpu::reduceTextureCoordinate(uv.y, wrapT_) * float(height);
        const int x = gpu::wrapTexelIndex(int(std::floor(s)), width, wrapS_);
        const int y = gpu::wrapTexelIndex(int(std::floor(t)), height, wrapT_);
        const std::uint32_t texel = image_->texels[std::size_t(y) * image_->width + std::size_t(x)];
        const std::array<float, 256>& decode = srgbByteToLinear();
        return {decode[texel & 0xffu], decode[(texel >> 8u) & 0xffu],
                decode[(texel >> 16u) & 0xffu]};
    }

    glm::vec2 transformed(glm::vec2 uv) const {
        const glm::vec3 moved = transform_ * glm::vec3(uv, 1.0f);
        return {moved.x, moved.y};
    }

    double texelCount() const { return double(image_->width) * double(image_->height); }

private:
    glm::mat3 transform_;
    const SceneImage* image_ = nullptr;
    std::uint32_t wrapS_ = 0, wrapT_ = 0;
};

// The texture's mean over the triangle with corners uv[0..2]: the centroids of the k² equal
// sub-triangles that cutting each edge into k makes (k(k+1)/2 upright, k(k−1)/2 upside down),
// k growing with the number of texels the triangle covers.
glm::vec3 meanOverTriangle(const EmissiveTexture& texture, const glm::vec2* corners) {
    const glm::vec2 a = texture.transformed(corners[0]), b = texture.transformed(corners[1]),
                    c = texture.transformed(corners[2]);
    const double uvArea =
        0.5 * std::abs(double((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)));
    const double texels = uvArea * texture.texelCount();
    const int k =
        std::clamp(int(std::ceil(std::sqrt(std::min(texels, 1e6)))), 1, kMaxPointsPerEdge);
    glm::dvec3 sum(0.0);
    const auto add = [&](float i, float j) { // barycentric (i, j)/k on edges b − a, c − a
        const float u = i / float(k), v = j / float(k);
        sum += glm::dvec3(texture.at(a + u * (b - a) + v * (c - a)));
    };
    for (int j = 0; j < k; ++j)
        for (int i = 0; i + j < k; ++i) {
            add(float(i) + 1.0f / 3.0f, float(j) + 1.0f / 3.0f);
            if (i + j < k - 1) add(float(i) + 2.0f / 3.0f, float(j) + 2.0f / 3.0f);
        }
    return glm::vec3(sum / double(k * k));
}

} // namespace

glm::vec3 meanTriangleEmission(const Scene& scene, std::size_t triangle) {
    const SceneMaterial& material = scene.materials[scene.materialIndices[triangle]];
    const bool hasTexcoords = scene.texcoords.size() == scene.positions.size();
    if (material.emissiveTexture.texture < 0 || !hasTexcoords) return material.emission;
    return material.emission * meanOverTriangle(EmissiveTexture(scene, material.emissiveTexture),
                                                &scene.texcoords[3 * triangle]);
}

} // namespace vkpt
