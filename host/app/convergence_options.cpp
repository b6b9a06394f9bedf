// convergence_options.cpp — option table of --reference, --target-error and --time-limit.
#include "app/convergence_options.h"

#include <cmath>

#include "common/errors.h"

namespace vkpt {

namespace {

double parsePositive(const std::string& option, const std::string& text) {
    const float value = parseFloat(option, text);
    if (!(value > 0.0f) || !std::isfinite(value))
        throw InputError("option --" + option + ": '" + text + "' is not a positive number");
    return double(value);
}

} // namespace

void addConvergenceOptions(CommandLine& cl, ConvergenceSettings& s) {
    cl.add({"reference",
            {},
            "FILE",
            "report RMSE and relMSE against this PFM (same size) after every pass",
            [&s](auto v) { s.referencePath = v[0]; }});
    cl.add({"target-error",
            {},
            "E",
            "stop once relMSE <= E (against --reference, else estimated from the two halves)",
            [&s](auto v) { s.targetError = parsePositive("target-error", v[0]); }});
    cl.add({"time-limit",
            {},
            "S",
            "stop at the first pass end after S seconds of rendering",
            [&s](auto v) { s.timeLimitSeconds = parsePositive("time-limit", v[0]); }});
}

std::optional<Image> loadReferenceFor(const ConvergenceSettings& convergence,
                                      const RenderSettings& settings) {
    if (convergence.referencePath.empty()) return std::nullopt;
    return loadReference(convergence.referencePath, settings.width, settings.height);
}

} // namespace vkpt
