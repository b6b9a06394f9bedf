// adaptive.h — the per-pixel stopping rule of adaptive sampling, shared by both renderers.
#ifndef VKPT_ADAPTIVE_H
#define VKPT_ADAPTIVE_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Two-sided 95 % quantile of the standard normal distribution.
#define ADAPTIVE_Z95 1.96f

// Luminance below this counts as dark: adaptive sampling then asks for an absolute error of
// tolerance × floor instead of a relative one, so black and near-black pixels stop (one
// 8-bit display step at exposure 0; the host scales it by 2^-EV).
#define ADAPTIVE_DARK_FLOOR (1.0f / 256.0f)

// CS184's rule, I = 1.96·√(c·σ²/n) ≤ tol·μ, tested only once a pixel has minSamples samples so
// that a first batch of zeros cannot stop a pixel with rare bright paths. mean and m2 are
// Welford's running mean and sum of squared deviations of the per-sample luminance. c, the
// variance scale, calibrates σ²/n (which assumes independent samples) to the error the two
// halves of the image's samples show (image/error_metrics.h, varianceScaleFromHalves): 1 until
// the render driver has measured it.
VKPT_FN bool isPixelConverged(uint count, float mean, float m2, uint minSamples, float tolerance,
                              float darkFloor, float varianceScale) {
    if (count < max(minSamples, 2u)) return false;
    float variance = max(m2, 0.0f) / float(count - 1u);
    float halfWidth = ADAPTIVE_Z95 * sqrt(varianceScale * variance / float(count));
    return halfWidth <= tolerance * max(mean, darkFloor);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_ADAPTIVE_H
