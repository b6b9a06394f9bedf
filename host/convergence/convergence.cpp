// convergence.cpp — points of the error curve, the target-error rule, the JSON and the
// summary lines.
#include "convergence/convergence.h"

#include <cmath>
#include <cstdio>

#include "common/errors.h"
#include "common/json_writer.h"
#include "image/image_io.h"

namespace vkpt {

namespace {

std::string formatError(double value) {
    if (!std::isfinite(value)) return "unknown";
    char text[32];
    std::snprintf(text, sizeof(text), "%.3e", value);
    return text;
}

void writeNumberOrNull(JsonWriter& json, const char* name, double value) {
    json.key(name);
    if (std::isfinite(value))
        json.value(value);
    else
        json.null();
}

void writePoint(JsonWriter& json, const ConvergencePoint& p) {
    const PassFigures& f = p.figures;
    json.beginObject().field("pass", f.pass).field("seconds", f.seconds);
    json.field("renderSeconds", f.renderSeconds).field("cpuSeconds", f.cpuSeconds);
    json.field("spp", f.samplesPerPixel);
    json.field("samplesTaken", f.samplesTaken).field("activePixels", f.activePixels);
    writeNumberOrNull(json, "rmse", p.rmse);
    writeNumberOrNull(json, "relMse", p.relMse);
    writeNumberOrNull(json, "meanHalfWidth", p.meanHalfWidth);
    writeNumberOrNull(json, "estimatedRelMse", p.estimatedRelMse);
    json.endObject();
}

} // namespace

Image loadReference(const std::string& path, std::uint32_t width, std::uint32_t height) {
    Image reference = readPfm(path);
    if (reference.width != width || reference.height != height)
        throw InputError(path + ": the reference is " + std::to_string(reference.width) + "x" +
                         std::to_string(reference.height) + ", the render " +
                         std::to_string(width) + "x" + std::to_string(height));
    const std::uint64_t bad = countNonFinitePixels(reference);
    if (bad > 0)
        throw InputError(path + ": " + std::to_string(bad) +
                         " pixels of the reference are not finite");
    return reference;
}

ConvergenceTracker::ConvergenceTracker(const Image* reference, double targetError)
    : reference_(reference), targetError_(targetError) {}

const ConvergencePoint& ConvergenceTracker::record(const PassFigures& figures,
                                                   const RenderOutput* output) {
    ConvergencePoint point;
    point.figures = figures;
    if (output) {
        if (reference_) {
            const ReferenceError error = compareWithReference(output->image, *reference_);
            point.rmse = error.rmse;
            point.relMse = error.relMse;
        }
        const VarianceEstimate estimate = estimateFromVariance(*output);
        point.meanHalfWidth = estimate.meanHalfWidth;
        point.estimatedRelMse = estimate.estimatedRelMse;
        point.minSamples = estimate.minSamples;
    }
    curve_.push_back(point);
    return curve_.back();
}

double ConvergenceTracker::trackedError(const ConvergencePoint& point) const {
    if (reference_) return point.relMse;
    const bool enoughSamples =
        point.figures.samplesPerPixel >= kMinSamplesForEstimate || point.figures.activePixels == 0;
    return enoughSamples ? point.estimatedRelMse : ConvergencePoint::kUnknown;
}

bool ConvergenceTracker::targetReached() const {
    if (!(targetError_ > 0.0) || curve_.empty()) return false;
    return trackedError(curve_.back()) <= targetError_; // false for NaN
}

std::string describePoint(const ConvergencePoint& p) {
    char head[160];
    std::snprintf(head, sizeof(head), "pass %u, %.3f s, %u spp, %u active pixels", p.figures.pass,
                  p.figures.seconds, p.figures.samplesPerPixel, p.figures.activePixels);
    std::string line = head;
    if (std::isfinite(p.relMse))
        line += ": relMSE " + formatError(p.relMse) + ", RMSE " + formatError(p.rmse) + ",";
    else
        line += ":";
    line += " mean half-width " + formatError(p.meanHalfWidth) + ", estimated relMSE " +
            formatError(p.estimatedRelMse);
    return line;
}

void writeConvergenceJson(JsonWriter& json, const ConvergenceReport& r) {
    json.key("convergence").beginObject();
    json.key("reference");
    if (r.settings.referencePath.empty())
        json.null();
    else
        json.value(r.settings.referencePath);
    writeNumberOrNull(json, "targetError",
                      r.settings.targetError > 0.0 ? r.settings.targetError : std::nan(""));
    writeNumberOrNull(json, "timeLimit",
                      r.settings.timeLimitSeconds > 0.0 ? r.settings.timeLimitSeconds
                                                        : std::nan(""));
    json.field("relMseEpsilon", kRelMseEpsilon).field("stop", stopName(r.stop));
    json.field("targetReached", r.targetReached);
    json.key("curve").beginArray();
    for (const ConvergencePoint& point : r.curve)
        writePoint(json, point);
    json.endArray();
    json.endObject();
}

void printConvergenceSummary(const ConvergenceReport& r) {
    if (!r.curve.empty() && r.settings.needsPixels())
        std::printf("  error: %s\n", describePoint(r.curve.back()).c_str());
    std::printf("  stopped: %s", stopName(r.stop));
    if (r.settings.targetError > 0.0) {
        const char* outcome = r.targetReached ? "reached"
                              : r.stop == RenderStop::Budget
                                  ? "not reached: the --spp budget ran out first"
                                  : "not reached";
        std::printf("; target relMSE %.3g %s", r.settings.targetError, outcome);
    }
    if (r.settings.timeLimitSeconds > 0.0)
        std::printf("; time limit %.3g s", r.settings.timeLimitSeconds);
    std::printf("\n");
}

} // namespace vkpt
