// render_state.cpp — rectangles, sample ranges, Chan's combination and the image of a state.
#include "state/render_state.h"

#include <algorithm>
#include <cfloat>

#include "common/errors.h"

namespace vkpt {

namespace {

float saturatedFloat(double value) {
    return float(std::clamp(value, -double(FLT_MAX), double(FLT_MAX)));
}

} // namespace

PixelRect fullFrame(std::uint32_t width, std::uint32_t height) {
    return {0, 0, width, height};
}

PixelRect boundingRect(const PixelRect& a, const PixelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

std::string describeRect(const PixelRect& r) {
    return "x " + std::to_string(r.x0) + ".." + std::to_string(r.x1) + ", y " +
           std::to_string(r.y0) + ".." + std::to_string(r.y1);
}

std::vector<SampleRange> normalizedRanges(std::vector<SampleRange> ranges) {
    std::erase_if(ranges, [](const SampleRange& r) { return r.end <= r.begin; });
    std::sort(ranges.begin(), ranges.end(),
              [](const SampleRange& a, const SampleRange& b) { return a.begin < b.begin; });
    std::vector<SampleRange> joined;
    for (const SampleRange& r : ranges) {
        if (!joined.empty() && joined.back().end >= r.begin)
            joined.back().end = std::max(joined.back().end, r.end);
        else
            joined.push_back(r);
    }
    return joined;
}

std::string describeRanges(const std::vector<SampleRange>& ranges) {
    std::string text;
    for (const SampleRange& r : ranges)
        text += (text.empty() ? "[" : " [") + std::to_string(r.begin) + "," +
                std::to_string(r.end) + ")";
    return text.empty() ? "none" : text;
}

// Chan, Golub and LeVeque (1979), eq. 2.1: with δ = μb − μa and n = na + nb,
// μ = μa + δ·nb/n and M2 = M2a + M2b + δ²·na·nb/n. The radiance mean is the count-weighted
// mean, which is the same update per channel.
HalfEstimate combineHalves(const HalfEstimate& a, const HalfEstimate& b) {
    HalfEstimate c;
    c.count = a.count + b.count;
    if (a.count == 0 || b.count == 0) {
        c.mean = a.count ? a.mean : b.mean;
        return c;
    }
    c.mean = a.mean + (b.mean - a.mean) * (double(b.count) / double(c.count));
    return c;
}

PixelRecord combineRecords(const PixelRecord& a, const PixelRecord& b) {
    PixelRecord c;
    c.samplesTaken = a.samplesTaken + b.samplesTaken;
    c.converged = a.converged || b.converged;
    c.count = a.count + b.count;
    for (int h = 0; h < 2; ++h)
        c.halves[h] = combineHalves(a.halves[h], b.halves[h]);
    if (a.count == 0 || b.count == 0) {
        const PixelRecord& only = a.count ? a : b;
        c.mean = only.mean;
        c.luminanceMean = only.luminanceMean;
        c.luminanceM2 = only.luminanceM2;
        return c;
    }
    const double na = a.count, nb = b.count, n = na + nb;
    c.mean = a.mean + (b.mean - a.mean) * (nb / n);
    const double delta = b.luminanceMean - a.luminanceMean;
    c.luminanceMean = a.luminanceMean + delta * (nb / n);
    c.luminanceM2 = a.luminanceM2 + b.luminanceM2 + delta * delta * (na * nb / n);
    return c;
}

FeatureRecord combineFeatures(const FeatureRecord& a, const FeatureRecord& b) {
    FeatureRecord c;
    c.samples = a.samples + b.samples;
    c.depth = std::min(a.depth, b.depth);
    if (a.samples == 0 || b.samples == 0) {
        const FeatureRecord& only = a.samples ? a : b;
        c.albedo = only.albedo;
        c.normal = only.normal;
        return c;
    }
    const double wb = double(b.samples) / double(c.samples);
    c.albedo = glm::vec3(glm::dvec3(a.albedo) + (glm::dvec3(b.albedo) - glm::dvec3(a.albedo)) * wb);
    c.normal = glm::vec3(glm::dvec3(a.normal) + (glm::dvec3(b.normal) - glm::dvec3(a.normal)) * wb);
    return c;
}

RenderOutput renderOutputOf(const RenderState& state) {
    const std::uint32_t width = state.identity.width, height = state.identity.height;
    VKPT_ASSERT(state.pixels.size() == state.window.area(), "one record per window pixel");
    RenderOutput output;
    output.image = Image(width, height);
    const std::size_t count = std::size_t(width) * height;
    output.sampleCounts.assign(count, 0);
    output.luminanceMean.assign(count, 0.0f);
    output.luminanceM2.assign(count, 0.0f);
    for (int h = 0; h < 2; ++h) {
        output.halves[h] = Image(width, height);
        output.halfCounts[h].assign(count, 0);
    }
    for (std::uint32_t y = state.window.y0; y < state.window.y1; ++y)
        for (std::uint32_t x = state.window.x0; x < state.window.x1; ++x) {
            const PixelRecord& p = state.at(x, y);
            const std::size_t i = std::size_t(y) * width + x;
            output.image.pixels[i] = p.count ? glm::vec3(p.mean) : glm::vec3(0.0f);
            output.sampleCounts[i] = p.count;
            output.luminanceMean[i] = saturatedFloat(p.luminanceMean);
            output.luminanceM2[i] = saturatedFloat(p.luminanceM2);
            for (int h = 0; h < 2; ++h) {
                output.halves[h].pixels[i] = glm::vec3(p.halves[h].mean);
                output.halfCounts[h][i] = p.halves[h].count;
            }
        }
    return output;
}

std::uint64_t totalSamplesTaken(const std::vector<PixelRecord>& pixels) {
    std::uint64_t total = 0;
    for (const PixelRecord& p : pixels)
        total += p.samplesTaken;
    return total;
}

double varianceOfMean(const PixelRecord& p) {
    if (p.count < 2) return 0.0;
    return std::max(p.luminanceM2, 0.0) / double(p.count - 1) / double(p.count);
}

} // namespace vkpt
