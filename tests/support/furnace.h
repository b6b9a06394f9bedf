// furnace.h — the white furnace of a BSDF (shared/bsdf.h): its directional albedo
// ∫ f cos θi dωi at a view, by Monte Carlo with its own sampler, and the standard error.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "shared/bsdf.h"
#include "shared/rng.h"

namespace vkpt::test {

// The view direction at cos θo in the xz plane.
inline glm::vec3 viewAt(float cosTheta) {
    return glm::vec3(std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta)), 0.0f, cosTheta);
}

struct AlbedoEstimate {
    double mean = 0.0;
    double sigma = 0.0; // standard error of the mean
};

// The albedo of channel `channel` at cos θo from `samples` draws of sampleBsdf (stream `seed`);
// an invalid sample counts as 0.
inline AlbedoEstimate estimateAlbedo(const gpu::ShadingMaterial& m, float cosThetaO, int samples,
                                     std::uint32_t seed, int channel = 0) {
    const glm::vec3 wo = viewAt(cosThetaO);
    double sum = 0.0, sumSquares = 0.0;
    for (std::uint32_t i = 0; i < std::uint32_t(samples); ++i) {
        const glm::vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_BSDF);
        const gpu::BsdfSample s = gpu::sampleBsdf(m, wo, glm::vec2(u.x, u.y), u.w);
        const double w = s.valid ? double(s.weight[channel]) : 0.0;
        sum += w;
        sumSquares += w * w;
    }
    AlbedoEstimate e;
    e.mean = sum / samples;
    e.sigma = std::sqrt(std::max(0.0, sumSquares / samples - e.mean * e.mean) / samples);
    return e;
}

} // namespace vkpt::test
