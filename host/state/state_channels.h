// state_channels.h — internal to vkpt_state: the names of the state file's channels, declared
// once for its writer and its reader (docs/distributed.md lists them), and the encoding of a
// double in two float channels.
#pragma once

#include <ImfThreading.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <thread>

namespace vkpt::state_channels {

inline constexpr const char* kRgb[3] = {"R", "G", "B"};
inline constexpr const char* kXyz[3] = {"X", "Y", "Z"};

// What compositors and denoisers read.
inline constexpr const char* kAlbedoPrefix = "albedo."; // + R, G, B
inline constexpr const char* kNormalPrefix = "normal."; // + X, Y, Z
inline constexpr const char* kDepth = "Z";
// With a denoised image (RenderState::denoised) R, G, B hold it, and the raw mean moves here.
inline constexpr const char* kRawPrefix = "raw."; // + R, G, B
inline constexpr const char* kSampleCount = "sampleCount";
inline constexpr const char* kVariance = "variance";
// The two halves' means (even and odd sample indices), + R, G, B: what a denoiser reads beside
// the mean, and what the error estimate compares (docs/integrator.md, "Two halves").
inline constexpr const char* kHalfPrefix[2] = {"half0.", "half1."};

// What merging and resuming read.
inline constexpr const char* kMeanLoPrefix = "vkpt.meanLo."; // + R, G, B
inline constexpr const char* kCount = "vkpt.count";
inline constexpr const char* kSamplesTaken = "vkpt.samplesTaken";
inline constexpr const char* kConverged = "vkpt.converged";
inline constexpr const char* kLuminanceMean = "vkpt.luminanceMean";
inline constexpr const char* kLuminanceMeanLo = "vkpt.luminanceMeanLo";
inline constexpr const char* kLuminanceM2 = "vkpt.luminanceM2";
inline constexpr const char* kLuminanceM2Lo = "vkpt.luminanceM2Lo";
inline constexpr const char* kFeatureSamples = "vkpt.featureSamples"; // with the AOV channels
inline constexpr const char* kHalfLoPrefix[2] = {"vkpt.half0Lo.", "vkpt.half1Lo."}; // + R, G, B
inline constexpr const char* kHalfCount[2] = {"vkpt.half0Count", "vkpt.half1Count"};

// Threads for a file's compression or decompression. OpenEXR runs those tasks on its global
// thread pool, which is empty until told otherwise (then one thread does all of it: 0.98 s of
// ZIP for the 1024² preview's 26 channels, before the halves' 14, on 2 cores, 0.5 s with both).
inline int exrThreads() {
    static const int threads = [] {
        const int count = int(std::max(1u, std::thread::hardware_concurrency()));
        Imf::setGlobalThreadCount(count);
        return count;
    }();
    return threads;
}

// String attributes of the header.
inline constexpr const char* kFormatAttribute = "vkpt.format";
inline constexpr const char* kSceneHashAttribute = "vkpt.sceneHash";
inline constexpr const char* kSettingsAttribute = "vkpt.settings";
inline constexpr const char* kSeedAttribute = "vkpt.seed";
inline constexpr const char* kRegionsAttribute = "vkpt.regions";
inline constexpr const char* kProgramAttribute = "vkpt.program";
inline constexpr const char* kSceneAttribute = "vkpt.scene";
inline constexpr const char* kTaskAttribute = "vkpt.task";

// A double as two floats, hi + lo: hi is the float nearest the value, lo the float nearest
// the rest, together about 48 bits of the double's 53 (Dekker's double-float).
struct SplitDouble {
    float hi = 0.0f;
    float lo = 0.0f;
};

// Floats saturate instead of overflowing (a double-to-float conversion out of range is
// undefined); NaN, which no moment should be, becomes 0.
inline float saturated(double value) {
    if (std::isnan(value)) return 0.0f;
    return float(std::fmax(-double(FLT_MAX), std::fmin(value, double(FLT_MAX))));
}

inline SplitDouble splitDouble(double value) {
    SplitDouble s;
    s.hi = saturated(value);
    s.lo = saturated(value - double(s.hi));
    return s;
}

inline double joinDouble(float hi, float lo) {
    return double(hi) + double(lo);
}

} // namespace vkpt::state_channels
