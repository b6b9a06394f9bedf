// pixel_accumulator.h — one pixel's running estimate: the radiance sum and Welford's
// mean and M2 of the per-sample luminance (numerically stable, unlike Σx and Σx²), and the
// radiance sums of the two halves of the samples (even and odd sample indices).
#pragma once

#include <algorithm>
#include <cstdint>

#include <glm/glm.hpp>

namespace vkpt {

struct PixelAccumulator {
    glm::dvec3 radianceSum{0.0};
    double luminanceMean = 0.0;
    double luminanceM2 = 0.0;
    std::uint32_t count = 0;
    glm::dvec3 halfSums[2] = {glm::dvec3(0.0), glm::dvec3(0.0)};
    std::uint32_t halfCounts[2] = {0, 0};

    // Welford, "Note on a Method for Calculating Corrected Sums of Squares and Products",
    // Technometrics 4(3), 1962. Each term of M2 is ≥ 0 in exact arithmetic; the max() keeps
    // rounding from ever making the sum negative.
    void add(const glm::vec3& radiance, float luminance, std::uint32_t half) {
        radianceSum += glm::dvec3(radiance);
        ++count;
        halfSums[half] += glm::dvec3(radiance);
        ++halfCounts[half];
        double delta = double(luminance) - luminanceMean;
        luminanceMean += delta / double(count);
        luminanceM2 = std::max(luminanceM2 + delta * (double(luminance) - luminanceMean), 0.0);
    }

    glm::vec3 mean() const {
        return count ? glm::vec3(radianceSum / double(count)) : glm::vec3(0.0f);
    }
};

} // namespace vkpt
