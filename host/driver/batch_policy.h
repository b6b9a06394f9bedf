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

} // namespace vkpt
