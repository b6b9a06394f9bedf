// render_output.h — what a render produces per pixel, on either executor: the mean radiance
// and the adaptive sampler's luminance statistics, from which comparisons draw their bounds.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"

namespace vkpt {

struct RenderOutput {
    Image image;                             // mean radiance per pixel
    std::vector<std::uint32_t> sampleCounts; // samples taken per pixel
    std::vector<float> luminanceMean;        // Welford running mean of per-sample luminance
    std::vector<float> luminanceM2;          // Welford sum of squared deviations
    // The means of the even and the odd sample indices (state/render_state.h, HalfEstimate) and
    // their finite-sample counts; empty where a producer keeps no halves.
    Image halves[2];
    std::vector<std::uint32_t> halfCounts[2];
};

} // namespace vkpt
