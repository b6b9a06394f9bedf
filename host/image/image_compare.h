// image_compare.h — statistical comparison of renders: Monte Carlo images differ by noise, so
// every check states its bound from the images' own variance and a confidence level.
#pragma once

#include <cstdint>
#include <string>

#include "image/render_output.h"

namespace vkpt {

// Per-pixel two-sample test of luminance means: z = (μa − μb) / sqrt(σa²/na + σb²/nb), judged
// as Welch's t-test (Student's t with Welch–Satterthwaite degrees of freedom), because each σ
// is estimated from the pixel's own samples and the normal tail would be optimistic for a few
// dozen of them. The family-wise false-alarm rate alpha is split over the pixels with Šidák's
// correction, so a correct renderer fails with probability about alpha whatever the image size.
// A pixel is also rejected when it cannot be tested: fewer than 2 samples on either side (no
// variance), a non-finite mean or variance, or zero variance on both sides with means that
// differ beyond float rounding (relative 1e-5, absolute 1e-7). Images of different sizes are
// a programmer error (InternalError).
struct ZTestResult {
    bool passed = false;
    double alphaFamily = 0.0;
    double alphaPerPixel = 0.0;
    double criticalZ = 0.0; // the normal (many-sample) limit of the per-pixel critical value
    std::uint64_t rejectedPixels = 0;
    double worstZ = 0.0; // signed z of largest magnitude among the testable pixels
    std::uint32_t worstX = 0;
    std::uint32_t worstY = 0;
    std::string summary; // one line: what failed and where, or the figures when passed
};

ZTestResult zTestPerPixel(const RenderOutput& a, const RenderOutput& b, double alphaFamily = 0.01);

// The image mean of luminance with its standard error sqrt(Σ s²) / N (from per-pixel variances
// of the mean s²). The standard error is NaN when a pixel has fewer than 2 samples.
struct MeanEstimate {
    double mean = 0.0;
    double standardError = 0.0;
};
MeanEstimate meanLuminance(const RenderOutput& output);

// Upper quantile of the standard normal: z with P(Z > z) = p, accurate to about 1e-15
// relative for p in [1e-300, 0.5] (Acklam's approximation refined by Newton steps). Returns
// +inf for p <= 0, -inf for p >= 1 and NaN for NaN.
double normalUpperQuantile(double p);

} // namespace vkpt
