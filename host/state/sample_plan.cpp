// sample_plan.cpp — task shares and the settings key.
#include "state/sample_plan.h"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "common/errors.h"
#include "shared/adaptive.h"

namespace vkpt {

namespace {

bool parseWhole(const std::string& text, std::uint32_t& value) {
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size() && !text.empty();
}

const char* integratorName(const RenderSettings& s) {
    switch (s.integrator) {
    case Integrator::Path:
        return "path";
    case Integrator::Direct:
        return s.lightSampling == LightSampling::Hemisphere ? "direct-hemisphere" : "direct-light";
    case Integrator::Normals:
        return "normals";
    }
    return "?";
}

const char* samplerName(Sampler sampler) {
    return sampler == Sampler::Sobol ? "sobol" : "independent";
}

// %a prints a float exactly, so that two keys are equal exactly when the values are.
std::string exactFloat(float value) {
    char text[64];
    std::snprintf(text, sizeof text, "%a", double(value));
    return text;
}

std::string adaptiveKey(const RenderSettings& s) {
    if (!s.adaptive.enabled) return "off";
    const float darkFloor = ADAPTIVE_DARK_FLOOR * std::exp2(-s.exposure);
    return std::to_string(s.adaptive.batchSize) + "/" + exactFloat(s.adaptive.tolerance) + "/" +
           std::to_string(s.adaptive.minSamples) + "/" + exactFloat(darkFloor) + "/" +
           (s.adaptive.calibrated ? "halves" : "variance");
}

} // namespace

TaskShare parseTaskShare(const std::string& text) {
    const std::size_t slash = text.find('/');
    TaskShare task;
    if (slash == std::string::npos || !parseWhole(text.substr(0, slash), task.index) ||
        !parseWhole(text.substr(slash + 1), task.count))
        throw InputError("option --task: '" + text + "' is not K/N (task K of N, K from 0)");
    if (task.count == 0 || task.index >= task.count)
        throw InputError("option --task: " + text + ": K must be in 0.." +
                         (task.count ? std::to_string(task.count - 1) : std::string("N-1")));
    return task;
}

SampleRange taskSampleRange(std::uint32_t samplesPerPixel, const TaskShare& task) {
    const auto boundary = [&](std::uint64_t k) {
        return std::uint32_t(k * samplesPerPixel / task.count);
    };
    return {boundary(task.index), boundary(std::uint64_t(task.index) + 1)};
}

std::string settingsKey(const RenderSettings& s) {
    std::string key = "integrator=" + std::string(integratorName(s));
    key += " sampler=" + std::string(samplerName(s.sampler));
    key += " max-depth=" + std::to_string(s.maxDepth);
    key += " rr-depth=" + std::to_string(s.rrStartDepth);
    key += " light-samples=" +
           std::to_string(s.integrator == Integrator::Normals ? 0u : s.lightSamples);
    key += " path-filter=" + std::to_string(static_cast<std::uint32_t>(s.pathFilter));
    key += " clamp=" + exactFloat(s.clamp);
    key += " adaptive=" + adaptiveKey(s);
    return key;
}

} // namespace vkpt
