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

double luminanceOf(const glm::vec3& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; // Rec. 709, as shared/sampling.h
}

// Sums over the pixels of the relative error figures (error_metrics.h).
struct ErrorSums {
    double perSample = 0.0;          // Σ s² / (μ² + ε)
    double halvesLuminance = 0.0;    // Σ w·(L(A) − L(B))² / (μ² + ε)
    double halvesRgb = 0.0;          // Σ_c w·(A − B)² / (x² + ε)
    double halfWidthsUnscaled = 0.0; // Σ 1.96 · s
    bool halvesComplete = true;      // every pixel has samples in both halves
    std::uint32_t minSamples = std::numeric_limits<std::uint32_t>::max();
};

bool hasHalves(const RenderOutput& output) {
    const std::size_t pixels = output.sampleCounts.size();
    return output.halfCounts[0].size() == pixels && output.halfCounts[1].size() == pixels &&
           output.halves[0].pixels.size() == pixels && output.halves[1].pixels.size() == pixels;
}

void addHalves(const RenderOutput& output, std::size_t i, double mean, ErrorSums& sums) {
    const double na = output.halfCounts[0][i], nb = output.halfCounts[1][i];
    if (na == 0 || nb == 0) {
        sums.halvesComplete = false;
        return;
    }
    const double w = na * nb / ((na + nb) * (na + nb));
    const glm::vec3 a = output.halves[0].pixels[i], b = output.halves[1].pixels[i];
    const double dl = luminanceOf(a) - luminanceOf(b);
    sums.halvesLuminance += w * dl * dl / (mean * mean + kRelMseEpsilon);
    for (int c = 0; c < 3; ++c) {
        const double d = double(a[c]) - double(b[c]), x = output.image.pixels[i][c];
        sums.halvesRgb += w * d * d / (x * x + kRelMseEpsilon);
    }
}

ErrorSums sumErrors(const RenderOutput& output) {
    const std::size_t pixels = output.sampleCounts.size();
    VKPT_ASSERT(output.luminanceMean.size() == pixels && output.luminanceM2.size() == pixels,
                "render output statistics do not match");
    ErrorSums sums;
    sums.halvesComplete = hasHalves(output);
    if (pixels == 0) sums.minSamples = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint32_t n = output.sampleCounts[i];
        sums.minSamples = std::min(sums.minSamples, n);
        if (n < 2) continue;
        // Welford's M2 cannot go negative in exact arithmetic; never let rounding make it so.
        const double m2 = std::max(0.0, double(output.luminanceM2[i]));
        const double varianceOfMean = m2 / double(n - 1) / double(n);
        const double mean = output.luminanceMean[i];
        sums.halfWidthsUnscaled += kZ95 * std::sqrt(varianceOfMean);
        sums.perSample += varianceOfMean / (mean * mean + kRelMseEpsilon);
        if (sums.halvesComplete) addHalves(output, i, mean, sums);
    }
    return sums;
}

double scaleOf(const ErrorSums& sums) {
    if (!sums.halvesComplete || !(sums.perSample > 0.0)) return 1.0;
    return std::clamp(sums.halvesLuminance / sums.perSample, kMinVarianceScale, kMaxVarianceScale);
}

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
    const ErrorSums sums = sumErrors(output);
    const std::size_t pixels = output.sampleCounts.size();
    VarianceEstimate estimate;
    estimate.minSamples = sums.minSamples;
    if (pixels == 0 || sums.minSamples < 2) {
        estimate.meanHalfWidth = estimate.estimatedRelMse = std::nan("");
        return estimate;
    }
    estimate.varianceScale = scaleOf(sums);
    estimate.meanHalfWidth =
        std::sqrt(estimate.varianceScale) * sums.halfWidthsUnscaled / double(pixels);
    estimate.estimatedRelMse = sums.halvesComplete ? sums.halvesRgb / (3.0 * double(pixels))
                                                   : sums.perSample / double(pixels);
    return estimate;
}

double varianceScaleFromHalves(const RenderOutput& output) {
    return scaleOf(sumErrors(output));
}

} // namespace vkpt
