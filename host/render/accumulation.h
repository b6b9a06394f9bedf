// accumulation.h — what the device's accumulators and counters mean on the host: pixel states
// become the RenderOutput both renderers produce, counter words become statistics.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/render_stats.h"
#include "image/render_output.h"
#include "lib/wavefront.h"
#include "state/render_state.h"

namespace vkpt {

class Buffer;

// Mean radiance (Kahan sum over count, in double), sample counts, luminance statistics and the
// two halves' means and counts.
RenderOutput makeRenderOutput(std::span<const gpu::PixelState> pixels, std::uint32_t width,
                              std::uint32_t height);

// Σ samples traced over the pixels, non-finite ones included (RenderStats::samplesTaken).
std::uint64_t totalSamplesTaken(std::span<const gpu::PixelState> pixels);

// One pixel state as the executor-neutral record (the Kahan sum's best estimate over the count,
// in double) and back: Kahan's running sum becomes the float nearest the sum and the
// compensation the rest, so the record's sum survives to within the compensation's rounding.
PixelRecord recordFromPixelState(const gpu::PixelState& pixel);
gpu::PixelState pixelStateFromRecord(const PixelRecord& record);

// The records of `crop`, row-major, from the whole image's pixel states.
std::vector<PixelRecord> cropRecords(std::span<const gpu::PixelState> pixels, std::uint32_t width,
                                     const PixelRect& crop);

// A snapshot of queueCounters.
struct DeviceCounters {
    std::uint32_t words[COUNTER_WORDS] = {};

    std::uint32_t raysInQueue(std::uint32_t half) const { return words[COUNTER_RAYS + half]; }
    std::uint32_t nextActivePixels() const { return words[COUNTER_ACTIVE_NEXT]; }
    std::uint64_t wide(std::uint32_t index) const {
        return std::uint64_t(words[index]) | (std::uint64_t(words[index + 1]) << 32);
    }
    RayCounts rays() const {
        return {wide(COUNTER_CAMERA_RAYS), wide(COUNTER_EXTENSION_RAYS), wide(COUNTER_SHADOW_RAYS)};
    }
};

// Reads the host-visible copy that the last submission wrote (PassRecorder::readBackCounters).
DeviceCounters readCounters(const Buffer& readback);

// Rays by kind, traversal work and discarded samples into `stats`.
void addCounterStats(const DeviceCounters& counters, RenderStats& stats);

} // namespace vkpt
