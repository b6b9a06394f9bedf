// accumulation.cpp — pixel states and counters read back from the device.
#include "render/accumulation.h"

#include <cstring>

#include "common/errors.h"
#include "gpu/buffer.h"

namespace vkpt {

namespace {

// Kahan's best estimate of the sum is the running sum less its compensation; the device summed
// the samples times ACCUMULATION_SCALE (a power of two: exact to undo).
glm::dvec3 radianceSumOf(const gpu::PixelState& p) {
    return (glm::dvec3(p.radianceSum) - glm::dvec3(p.compensation)) / double(ACCUMULATION_SCALE);
}

} // namespace

RenderOutput makeRenderOutput(std::span<const gpu::PixelState> pixels, std::uint32_t width,
                              std::uint32_t height) {
    VKPT_ASSERT(pixels.size() == std::size_t(width) * height, "one state per pixel");
    RenderOutput output;
    output.image = Image(width, height);
    output.sampleCounts.resize(pixels.size());
    output.luminanceMean.resize(pixels.size());
    output.luminanceM2.resize(pixels.size());
    for (int h = 0; h < 2; ++h) {
        output.halves[h] = Image(width, height);
        output.halfCounts[h].resize(pixels.size());
    }
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        const gpu::PixelState& p = pixels[i];
        output.image.pixels[i] =
            p.count ? glm::vec3(radianceSumOf(p) / double(p.count)) : glm::vec3(0.0f);
        output.sampleCounts[i] = p.count;
        output.luminanceMean[i] = p.luminanceMean;
        output.luminanceM2[i] = p.luminanceM2;
        output.halves[0].pixels[i] = p.evenMean;
        output.halves[1].pixels[i] = p.oddMean;
        output.halfCounts[0][i] = p.evenCount;
        output.halfCounts[1][i] = p.oddCount;
    }
    return output;
}

PixelRecord recordFromPixelState(const gpu::PixelState& p) {
    PixelRecord r;
    r.mean = p.count ? radianceSumOf(p) / double(p.count) : glm::dvec3(0.0);
    r.luminanceMean = p.luminanceMean;
    r.luminanceM2 = p.luminanceM2;
    r.count = p.count;
    r.samplesTaken = p.samplesTaken;
    r.converged = p.converged != 0;
    r.halves[0] = {glm::dvec3(p.evenMean), p.evenCount};
    r.halves[1] = {glm::dvec3(p.oddMean), p.oddCount};
    return r;
}

gpu::PixelState pixelStateFromRecord(const PixelRecord& r) {
    gpu::PixelState p{};
    const glm::dvec3 scaledSum = r.mean * double(r.count) * double(ACCUMULATION_SCALE);
    p.radianceSum = glm::vec3(scaledSum);
    p.compensation = glm::vec3(glm::dvec3(p.radianceSum) - scaledSum);
    p.count = r.count;
    p.samplesTaken = r.samplesTaken;
    p.luminanceMean = float(r.luminanceMean);
    p.luminanceM2 = float(r.luminanceM2);
    p.converged = r.converged ? 1u : 0u;
    p.evenMean = glm::vec3(r.halves[0].mean);
    p.evenCount = r.halves[0].count;
    p.oddMean = glm::vec3(r.halves[1].mean);
    p.oddCount = r.halves[1].count;
    return p;
}

std::vector<PixelRecord> cropRecords(std::span<const gpu::PixelState> pixels, std::uint32_t width,
                                     const PixelRect& crop) {
    std::vector<PixelRecord> records;
    records.reserve(crop.area());
    for (std::uint32_t y = crop.y0; y < crop.y1; ++y)
        for (std::uint32_t x = crop.x0; x < crop.x1; ++x)
            records.push_back(recordFromPixelState(pixels[std::size_t(y) * width + x]));
    return records;
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
