// batch_policy.h — how many samples per pixel the next batch of a render takes, whatever runs
// it: what the executor asks for, cut so that an observer sees the error at log-spaced counts,
// a checkpoint comes on time and a time limit is kept.
#pragma once

#include <cstdint>

namespace vkpt {

// k capped so that batches grow geometrically, for a render whose error is measured after every
// batch: at most max(1, samplesDone / 4) samples per pixel, so measurements come at 1, 2, 3, 4,
// 5, 6, 7, 8, 10, 12, 15, ... spp — evenly spaced on the log axis that error curves are read
// on — and a render that stops at a target error overshoots it by at most a quarter.
std::uint32_t samplesForGeometricGrowth(std::uint32_t k, std::uint32_t samplesDone);

// k capped for a time limit: the samples per pixel that `activePixels` pixels take within
// `secondsLeft` at `secondsPerPixelSample` (the last batch's rate), at least 1 and at most k.
// An unknown rate (<= 0, before the first batch) leaves k as it is.
std::uint32_t samplesWithinTime(std::uint32_t k, std::uint64_t activePixels,
                                double secondsPerPixelSample, double secondsLeft);

// Adaptive sampling calibrates its per-pixel error estimate to the image's two halves at fixed
// sample counts, first · 2^k (first = max(minSamples / 2, kFirstCalibrationSamples): ready before
// the first stopping test at minSamples), so that the scale a pixel's test uses is a function of
// the samples alone — never of how a device or a time limit cut the batches — and vkpt and
// vkpt-ref stop the same pixels. At 16 samples a half has 8, and the image's thousands of pixels
// pin the scale down (error_metrics.h).
inline constexpr std::uint32_t kFirstCalibrationSamples = 16;
std::uint32_t firstCalibrationPoint(std::uint32_t minSamples);
// The first calibration point after samplesDone.
std::uint32_t nextCalibrationPoint(std::uint32_t samplesDone, std::uint32_t first);
bool isCalibrationPoint(std::uint32_t samplesDone, std::uint32_t first);

// The scale quantised to 1/64, so that the reference's doubles and the device's floats (which
// give scales a few ulps apart) almost always hand the pixels the same value.
float quantizedVarianceScale(double scale);

} // namespace vkpt
