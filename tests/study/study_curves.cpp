// study_curves.cpp — crossing times on log–log curves and the adaptive/uniform comparison.
#include "study/study_curves.h"

#include <cmath>
#include <functional>

namespace vkpt {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Axis = std::function<double(const ConvergencePoint&)>;

// Where the curve first gets to `target`, on `axis`, interpolated on log–log axes.
double crossing(const std::vector<ConvergencePoint>& curve, double target, const Axis& axis) {
    const ConvergencePoint* previous = nullptr;
    for (const ConvergencePoint& point : curve) {
        if (!(std::isfinite(point.relMse) && point.relMse > 0.0 && axis(point) > 0.0)) continue;
        if (point.relMse > target) {
            previous = &point;
            continue;
        }
        if (!previous || !(point.relMse < previous->relMse)) return axis(point);
        const double la = std::log(previous->relMse), lb = std::log(point.relMse);
        const double xa = std::log(axis(*previous)), xb = std::log(axis(point));
        return std::exp(xa + (std::log(target) - la) / (lb - la) * (xb - xa));
    }
    return kNaN;
}

int bestRun(const std::vector<RunResult>& results, const std::string& family,
            const std::function<double(const RunResult&)>& cost) {
    int best = -1;
    double bestCost = kNaN;
    for (std::size_t i = 0; i < results.size(); ++i) {
        if (results[i].run.family != family) continue;
        const double c = cost(results[i]);
        if (std::isfinite(c) && !(c >= bestCost)) best = int(i), bestCost = c;
    }
    return best;
}

} // namespace

const char* clockName(StudyClock clock) {
    return clock == StudyClock::Wall ? "wall" : "cpu";
}

double curveSeconds(const ConvergencePoint& point, StudyClock clock) {
    return clock == StudyClock::Wall ? point.figures.renderSeconds : point.figures.cpuSeconds;
}

double timeToReach(const std::vector<ConvergencePoint>& curve, double target, StudyClock clock) {
    return crossing(curve, target,
                    [clock](const ConvergencePoint& p) { return curveSeconds(p, clock); });
}

double samplesToReach(const std::vector<ConvergencePoint>& curve, double target) {
    return crossing(curve, target,
                    [](const ConvergencePoint& p) { return double(p.figures.samplesTaken); });
}

std::vector<ConvergencePoint> curvePrefix(const std::vector<ConvergencePoint>& curve,
                                          std::uint32_t spp) {
    std::vector<ConvergencePoint> prefix;
    for (const ConvergencePoint& point : curve)
        if (point.figures.samplesPerPixel <= spp) prefix.push_back(point);
    return prefix;
}

int fastestToReach(const std::vector<RunResult>& results, const std::string& family, double target,
                   StudyClock clock) {
    return bestRun(results, family,
                   [&](const RunResult& r) { return timeToReach(r.curve, target, clock); });
}

int fewestSamplesToReach(const std::vector<RunResult>& results, const std::string& family,
                         double target) {
    return bestRun(results, family,
                   [&](const RunResult& r) { return samplesToReach(r.curve, target); });
}

AdaptiveSpeedup adaptiveSpeedup(const std::vector<RunResult>& results, double error,
                                StudyClock clock) {
    AdaptiveSpeedup s;
    s.error = error;
    s.uniformSeconds = s.adaptiveSeconds = s.uniformSamples = s.adaptiveSamples = kNaN;
    if (const int u = fastestToReach(results, "uniform", error, clock); u >= 0) {
        s.uniformSeconds = timeToReach(results[u].curve, error, clock);
        s.uniformSamples = samplesToReach(results[u].curve, error);
    }
    if (const int a = fastestToReach(results, "adaptive", error, clock); a >= 0) {
        s.adaptiveSeconds = timeToReach(results[a].curve, error, clock);
        s.fastestLabel = results[a].run.label;
    }
    if (const int a = fewestSamplesToReach(results, "adaptive", error); a >= 0) {
        s.adaptiveSamples = samplesToReach(results[a].curve, error);
        s.fewestSamplesLabel = results[a].run.label;
    }
    return s;
}

} // namespace vkpt
