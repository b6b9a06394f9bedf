// error_metrics.h — how far a render is from the truth: against a reference image (RMSE and
// relative MSE) and, without one, estimated from the variances the accumulator keeps. These
// are the figures of --reference, --target-error and the trade study (docs/trade/README.md).
#pragma once

#include <cstdint>

#include "image/image.h"
#include "image/render_output.h"

namespace vkpt {

// ε of the relative MSE: it keeps black and near-black pixels from dominating (a pixel of
// value 0.1 weighs half as much as a bright one; one of value 0 counts its squared error
// times 100). 1e-2 is the value of Rousselle et al. and most denoising papers.
inline constexpr double kRelMseEpsilon = 1e-2;

// Against a reference r, over the N pixels and the 3 channels c of image x:
//   RMSE   = sqrt( 1/(3N) · Σ (x − r)² )
//   relMSE = 1/(3N) · Σ (x − r)² / (r² + ε)
// Both images must have the same size (InternalError otherwise); non-finite values give NaN.
struct ReferenceError {
    double rmse = 0.0;
    double relMse = 0.0;
};
ReferenceError compareWithReference(const Image& image, const Image& reference);

// From each pixel's Welford statistics of the per-sample luminance L (n samples, mean μ,
// M2): the variance of the pixel's mean s² = M2 / (n − 1) / n, and then
//   meanHalfWidth   = 1/N · Σ 1.96 · s          (the adaptive sampler's 95 % half-width)
//   estimatedRelMse = 1/N · Σ s² / (μ² + ε)     (relMSE's expectation, were the image the
//                                                  luminance and the estimator unbiased)
// Both are NaN while any pixel has fewer than 2 samples (no variance yet). minSamples is the
// fewest samples any pixel has.
struct VarianceEstimate {
    double meanHalfWidth = 0.0;
    double estimatedRelMse = 0.0;
    std::uint32_t minSamples = 0;
};
VarianceEstimate estimateFromVariance(const RenderOutput& output);

} // namespace vkpt
