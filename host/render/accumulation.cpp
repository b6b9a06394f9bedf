// accumulation.cpp — pixel states and counters read back from the device.
#include "render/accumulation.h"

#include <cstring>

#include "common/errors.h"
#include "gpu/buffer.h"

namespace vkpt {

RenderOutput makeRenderOutput(std::span<const gpu::PixelState> pixels, std::uint32_t width,
                              std::uint32_t height) {
    VKPT_ASSERT(pixels.size() == std::size_t(width) * height, "one state per pixel");
    RenderOutput output;
    output.image = Image(width, height);
    output.sampleCounts.resize(pixels.size());
    output.luminanceMean.resize(pixels.size());
    output.luminanceM2.resize(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const gpu::PixelState& p = pixels[i];
        // Kahan's best estimate of the sum is the running sum less its compensation; the
        // device summed the samples times ACCUMULATION_SCALE (a power of two: exact to undo).
        glm::dvec3 sum =
            (glm::dvec3(p.radianceSum) - glm::dvec3(p.compensation)) / double(ACCUMULATION_SCALE);
        output.image.pixels[i] = p.count ? glm::vec3(sum / double(p.count)) : glm::vec3(0.0f);
        output.sampleCounts[i] = p.count;
        output.luminanceMean[i] = p.luminanceMean;
        output.luminanceM2[i] = p.luminanceM2;
    }
    return output;
}

std::uint64_t totalSamplesTaken(std::span<const gpu::PixelState> pixels) {
    std::uint64_t total = 0;
    for (const gpu::PixelState& p : pixels)
        total += p.samplesTaken;
    return total;
}

DeviceCounters readCounters(const Buffer& readback) {
    VKPT_ASSERT(readback.mapped() != nullptr && readback.size() >= sizeof(DeviceCounters::words),
                "counters readback must be mapped");
    DeviceCounters counters;
    std::memcpy(counters.words, readback.mapped(), sizeof(counters.words));
    return counters;
}

void addCounterStats(const DeviceCounters& counters, RenderStats& stats) {
    stats.rays = counters.rays();
    stats.nodesVisited = counters.wide(COUNTER_NODES_VISITED);
    stats.triangleTests = counters.wide(COUNTER_TRIANGLE_TESTS);
    stats.nonFiniteSamples = counters.wide(COUNTER_NON_FINITE);
}

} // namespace vkpt
