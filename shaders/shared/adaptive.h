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

// CS184's rule, I = 1.96·σ/√n ≤ tol·μ, tested only once a pixel has minSamples samples so
// that a first batch of zeros cannot stop a pixel with rare bright paths. mean and m2 are
// Welford's running mean and sum of squared deviations of the per-sample luminance.
VKPT_FN bool isPixelConverged(uint count, float mean, float m2, uint minSamples, float tolerance,
                              float darkFloor) {
    if (count < max(minSamples, 2u)) return false;
    float variance = max(m2, 0.0f) / float(count - 1u);
    float halfWidth = ADAPTIVE_Z95 * sqrt(variance / float(count));
    return halfWidth <= tolerance * max(mean, darkFloor);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_ADAPTIVE_H
