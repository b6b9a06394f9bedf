// pass_schedule.h — how a render is cut into passes and chunks. A pass gives every active
// pixel the same k samples (so all active pixels have always taken the same number); a chunk
// is as many active pixels as the path slots hold at k samples each.
#pragma once

#include <cstdint>

namespace vkpt {

// Enough to keep a device busy when a handful of pixels are left, few enough that accumulate's
// per-pixel loop stays far inside lavapipe's loop budget (docs/gpu.md).
inline constexpr std::uint32_t kMaxSamplesPerPass = 1024;

struct ScheduleInputs {
    std::uint32_t samplesPerPixel = 1; // the budget
    std::uint32_t samplesDone = 0;     // by every active pixel so far
    std::uint32_t activePixels = 0;
    std::uint32_t slotCount = 0;
    bool adaptive = false;
    std::uint32_t adaptiveBatch = 1;
    std::uint32_t adaptiveMinSamples = 0;
};

// k for the next pass. Uniform sampling: as many samples as the slots hold for the active
// pixels, within the budget and kMaxSamplesPerPass. Adaptive sampling: a pass ends where the
// stopping rule is tested (a multiple of the batch, from the minimum count on), at the first
// such point that gives the pass at least a quarter of the slots' paths, so that a pixel that
// converges wastes few traced samples while the device stays busy.
std::uint32_t samplesForPass(const ScheduleInputs& inputs);

// Active pixels per chunk at k samples each: all of them when they fit in the slots.
std::uint32_t pixelsPerChunk(std::uint32_t activePixels, std::uint32_t samplesPerPass,
                             std::uint32_t slotCount);

} // namespace vkpt
