// convergence.h — error against time while a render runs: the points of the curve that
// --reference, --target-error and --time-limit report after every pass, the rule that stops a
// render at a target error, and the curve as JSON. No Vulkan here: vkpt feeds it after each
// pass, vkpt-ref once at the end, the trade study for every run.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "common/render_stats.h"
#include "image/error_metrics.h"
#include "image/image.h"
#include "image/render_output.h"

namespace vkpt {

class JsonWriter;

struct ConvergenceSettings {
    std::string referencePath;     // --reference: a PFM of the render's size
    double targetError = 0.0;      // --target-error: a relMSE; 0 = none
    double timeLimitSeconds = 0.0; // --time-limit; 0 = none

    bool any() const {
        return !referencePath.empty() || targetError > 0.0 || timeLimitSeconds > 0.0;
    }
    // Only these need the image after each pass (one readback per pass).
    bool needsPixels() const { return !referencePath.empty() || targetError > 0.0; }
};

// Without a reference, --target-error trusts the estimate (the two halves' difference,
// image/error_metrics.h) only once the pixels still sampling have this many samples (adaptive
// sampling's default minimum, for the same reason): before the rare bright paths of a pixel have
// shown up its error looks small, and a firefly divides itself out of the relative error. On the
// Cornell box the estimate is 0.5 of the true relMSE at 16 spp but 1.1 at 64 spp
// (tests/render/error_estimate_test.cpp).
inline constexpr std::uint32_t kMinSamplesForEstimate = 64;

struct ConvergencePoint {
    static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
    PassFigures figures;
    double rmse = kUnknown;   // against the reference
    double relMse = kUnknown; // against the reference
    double meanHalfWidth = kUnknown;
    double estimatedRelMse = kUnknown;
    std::uint32_t minSamples = 0; // fewest samples of any pixel
};

// The reference a render is measured against: a PFM of exactly width × height whose every
// value is finite. Throws InputError naming the file and the problem.
Image loadReference(const std::string& path, std::uint32_t width, std::uint32_t height);

class ConvergenceTracker {
public:
    // reference: null for none (then only the variance estimate is known). targetError 0: none.
    ConvergenceTracker(const Image* reference, double targetError);

    // Measures `output` (null: the pixels were not read; only the figures are kept) and appends
    // the point to the curve.
    const ConvergencePoint& record(const PassFigures& figures, const RenderOutput* output);

    // The error --target-error is held to: relMSE against the reference when there is one,
    // otherwise the variance estimate once the active pixels have kMinSamplesForEstimate
    // samples (or none is active); NaN while unknown.
    double trackedError(const ConvergencePoint& point) const;
    // The last point is at or below the target (false without a target or a point).
    bool targetReached() const;

    const std::vector<ConvergencePoint>& curve() const { return curve_; }
    bool hasReference() const { return reference_ != nullptr; }
    double targetError() const { return targetError_; }

private:
    const Image* reference_;
    double targetError_;
    std::vector<ConvergencePoint> curve_;
};

// One line per pass for stderr: "pass 12, 0.53 s, 48 spp: relMSE 2.31e-02, RMSE 4.12e-02,
// mean half-width 5.10e-02, estimated relMSE 2.10e-02".
std::string describePoint(const ConvergencePoint& point);

struct ConvergenceReport {
    ConvergenceSettings settings;
    RenderStop stop = RenderStop::Budget;
    bool targetReached = false;
    std::vector<ConvergencePoint> curve;
};

// "convergence": settings, ε, the stop reason and every point of the curve (unknown values
// as null).
void writeConvergenceJson(JsonWriter& json, const ConvergenceReport& report);

// The summary's lines: the last point's errors, and why the render stopped.
void printConvergenceSummary(const ConvergenceReport& report);

} // namespace vkpt
