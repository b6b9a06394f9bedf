// error_metrics.cpp — RMSE and relative MSE against a reference, and their estimates from the
// per-pixel luminance variances, summed in double over the pixels.
#include "image/error_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.h"

namespace vkpt {

namespace {

constexpr double kZ95 = 1.96; // the adaptive sampler's ADAPTIVE_Z95

} // namespace

ReferenceError compareWithReference(const Image& image, const Image& reference) {
    VKPT_ASSERT(image.width == reference.width && image.height == reference.height,
                "an image and its reference must have the same size");
    double squared = 0.0, relative = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = image.pixels[i][c], r = reference.pixels[i][c];
            const double d2 = (x - r) * (x - r);
            squared += d2;
            relative += d2 / (r * r + kRelMseEpsilon);
        }
    const double count = 3.0 * double(std::max<std::size_t>(image.pixels.size(), 1));
    return {std::sqrt(squared / count), relative / count};
}

VarianceEstimate estimateFromVariance(const RenderOutput& output) {
    const std::size_t pixels = output.sampleCounts.size();
    VKPT_ASSERT(output.luminanceMean.size() == pixels && output.luminanceM2.size() == pixels,
                "render output statistics do not match");
    VarianceEstimate estimate;
    estimate.minSamples = pixels ? std::numeric_limits<std::uint32_t>::max() : 0;
    double halfWidths = 0.0, relative = 0.0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint32_t n = output.sampleCounts[i];
        estimate.minSamples = std::min(estimate.minSamples, n);
        if (n < 2) continue;
        // Welford's M2 cannot go negative in exact arithmetic; never let rounding make it so.
        const double m2 = std::max(0.0, double(output.luminanceM2[i]));
        const double varianceOfMean = m2 / double(n - 1) / double(n);
        const double mean = output.luminanceMean[i];
        halfWidths += kZ95 * std::sqrt(varianceOfMean);
        relative += varianceOfMean / (mean * mean + kRelMseEpsilon);
    }
    if (pixels == 0 || estimate.minSamples < 2) {
        estimate.meanHalfWidth = estimate.estimatedRelMse = std::nan("");
        return estimate;
    }
    estimate.meanHalfWidth = halfWidths / double(pixels);
    estimate.estimatedRelMse = relative / double(pixels);
    return estimate;
}

} // namespace vkpt
