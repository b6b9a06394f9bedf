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

// The error of a render without a reference, from its two halves (docs/integrator.md, "Two
// halves"). The halves A and B of a pixel (nA and nB finite samples of n) are independent
// estimates, so E[(A − B)²] = Var A + Var B, and w = nA·nB/n² turns that into the variance of
// the whole mean, Var = (A − B)²·w (1/4 for equal halves) — whatever the correlation of the
// samples within a half, which the per-sample variance σ²/n ignores (with the Sobol sampler it
// overstates the error 1.4–1.9×). Over the N pixels and 3 channels c, x the whole mean:
//   estimatedRelMse = 1/(3N) · Σ w·(A − B)² / (x² + ε)       (relMSE's expectation)
// One pixel's difference has one degree of freedom, so a pixel's own error is the per-sample
// variance calibrated by the image: with s² = M2 / (n − 1) / n of the per-sample luminance L
// (μ its mean),
//   varianceScale   = Σ w·(L(A) − L(B))² / (μ² + ε)  ÷  Σ s² / (μ² + ε)
//   meanHalfWidth   = 1/N · Σ 1.96 · √(varianceScale · s²)   (the adaptive sampler's half-width)
// Without halves (a producer that keeps none) or while a half of some pixel is empty, the
// per-sample variance stands alone: estimatedRelMse = 1/N · Σ s² / (μ² + ε), varianceScale 1.
// Everything is NaN while any pixel has fewer than 2 samples. minSamples is the fewest samples
// any pixel has.
struct VarianceEstimate {
    double meanHalfWidth = 0.0;
    double estimatedRelMse = 0.0;
    double varianceScale = 1.0;
    std::uint32_t minSamples = 0;
};
VarianceEstimate estimateFromVariance(const RenderOutput& output);

// The image-wide varianceScale above, clamped to [kMinVarianceScale, kMaxVarianceScale] (a
// guard against an image too small or too uniform to measure it); 1 without halves.
inline constexpr double kMinVarianceScale = 0.25;
inline constexpr double kMaxVarianceScale = 4.0;
double varianceScaleFromHalves(const RenderOutput& output);

} // namespace vkpt
