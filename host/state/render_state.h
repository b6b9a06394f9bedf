// render_state.h — a render as the sum of independent sample ranges (DESIGN.md): per pixel, the
// count and moments of the samples taken, which regions and sample ranges those samples are, and
// what must match for two states to be parts of one render. Both executors convert to and from
// it; merging, checkpoints and resuming work on it alone.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/render_output.h"

namespace vkpt {

// A pixel rectangle [x0, x1) × [y0, y1), (0, 0) at the top left.
struct PixelRect {
    std::uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    std::uint32_t width() const { return x1 - x0; }
    std::uint32_t height() const { return y1 - y0; }
    std::size_t area() const { return std::size_t(width()) * height(); }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool contains(std::uint32_t x, std::uint32_t y) const {
        return x >= x0 && x < x1 && y >= y0 && y < y1;
    }
    bool intersects(const PixelRect& o) const {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
    bool operator==(const PixelRect&) const = default;
};

PixelRect fullFrame(std::uint32_t width, std::uint32_t height);
PixelRect boundingRect(const PixelRect& a, const PixelRect& b);
std::string describeRect(const PixelRect& rect); // "x 0..32, y 16..48"

// Sample indices [begin, end) of every pixel: the random numbers' key (shared/rng.h).
struct SampleRange {
    std::uint32_t begin = 0, end = 0;

    std::uint32_t size() const { return end - begin; }
    bool overlaps(const SampleRange& o) const { return begin < o.end && o.begin < end; }
    bool operator==(const SampleRange&) const = default;
};

// Sorted, with touching ranges joined: [0,4) [4,8) → [0,8).
std::vector<SampleRange> normalizedRanges(std::vector<SampleRange> ranges);
std::string describeRanges(const std::vector<SampleRange>& ranges); // "[0,8) [12,16)"

// Every pixel of `rect` took every sample of `ranges` — except, under adaptive sampling, a
// pixel that converged, which stopped early (then ranges is the one prefix [0, B)).
struct Region {
    PixelRect rect;
    std::vector<SampleRange> ranges;
};

// The mean of one half of a pixel's finite samples: half h holds the samples whose index has
// parity h (shared/sampler.h, sampleHalf), which the sampler draws from a sequence of its own.
// The two halves are independent estimates of the pixel; their difference measures the error
// of the whole mean, and a denoiser reads them (docs/integrator.md, "Two halves").
struct HalfEstimate {
    glm::dvec3 mean{0.0};    // radiance
    std::uint32_t count = 0; // finite samples of the half
};

// One pixel's estimate, whichever executor made it. The moments are Chan, Golub and LeVeque's
// (count, mean, M2), so that two disjoint sets of samples combine exactly ("Updating Formulae and
// a Pairwise Algorithm for Computing Sample Variances", 1979); doubles, so that the reference's
// accumulators round-trip and the device's floats fit without loss.
struct PixelRecord {
    glm::dvec3 mean{0.0};           // radiance, over the finite samples
    double luminanceMean = 0.0;     // Welford mean of the per-sample luminance
    double luminanceM2 = 0.0;       // Welford sum of squared deviations
    std::uint32_t count = 0;        // finite samples accumulated
    std::uint32_t samplesTaken = 0; // samples traced, non-finite ones included
    bool converged = false;         // adaptive sampling stopped the pixel
    HalfEstimate halves[2];         // even and odd sample indices: count = their counts' sum
};

// Two disjoint sample sets of one half: the count-weighted mean.
HalfEstimate combineHalves(const HalfEstimate& a, const HalfEstimate& b);

// Chan et al.'s pairwise combination of two disjoint sample sets; a converged flag survives.
PixelRecord combineRecords(const PixelRecord& a, const PixelRecord& b);

// What a denoiser and a compositor need besides the colour (the AOVs of the EXR file), over the
// camera samples that recorded them (shared/sample_features.h).
struct FeatureRecord {
    glm::vec3 albedo{0.0f}; // mean over the samples, a miss counting as 0
    glm::vec3 normal{0.0f}; // mean world-space shading normal, facing the camera; 0 on a miss
    float depth = std::numeric_limits<float>::infinity(); // camera-space z of the nearest hit
    std::uint32_t samples = 0; // camera samples averaged: a pixel's share of a merge
};

// Two disjoint sets of samples' features: means weighted by their counts (in double), the
// nearer depth.
FeatureRecord combineFeatures(const FeatureRecord& a, const FeatureRecord& b);

// What must be equal for two states to be parts of one render.
struct StateIdentity {
    std::string sceneHash; // sceneContentHash of the prepared scene and camera
    std::string settings;  // settingsKey: every option that changes a sample's value
    std::uint32_t seed = 0;
    std::uint32_t width = 0; // the whole image
    std::uint32_t height = 0;

    bool operator==(const StateIdentity&) const = default;
};

// Where a state came from, for people (not checked).
struct StateOrigin {
    std::string program; // "vkpt", "vkpt-ref", "vkpt-merge"
    std::string scene;   // the scene path as given
    std::string task;    // "2/8", or empty
};

struct RenderState {
    StateIdentity identity;
    StateOrigin origin;
    PixelRect window;                    // the pixels held (the EXR data window)
    std::vector<Region> regions;         // which samples of which pixels
    std::vector<PixelRecord> pixels;     // window.area(), row-major
    std::vector<FeatureRecord> features; // window.area(), or empty (no AOVs)
    // The denoised radiance (window.area()), or empty. Written as the file's R, G, B, which a
    // viewer shows, with the raw mean in the raw.* layer; never read back: a state that is
    // merged or resumed is denoised again from its moments.
    std::vector<glm::vec3> denoised;

    PixelRecord& at(std::uint32_t x, std::uint32_t y) {
        return pixels[std::size_t(y - window.y0) * window.width() + (x - window.x0)];
    }
    const PixelRecord& at(std::uint32_t x, std::uint32_t y) const {
        return pixels[std::size_t(y - window.y0) * window.width() + (x - window.x0)];
    }
};

// The image and statistics of a state over the whole frame; pixels outside the window are 0.
RenderOutput renderOutputOf(const RenderState& state);

// Σ samples traced over the pixels (RenderStats::samplesTaken).
std::uint64_t totalSamplesTaken(const std::vector<PixelRecord>& pixels);

// The per-pixel variance of the mean luminance, M2 / (n − 1) / n; 0 below 2 samples.
double varianceOfMean(const PixelRecord& pixel);

} // namespace vkpt
