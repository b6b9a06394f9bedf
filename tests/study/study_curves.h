// study_curves.h — reading a trade study's curves: when each run reaches an error, which
// adaptive setting gets there first, and what adaptive sampling saves over uniform sampling.
#pragma once

#include <string>
#include <vector>

#include "convergence/convergence.h"
#include "study/study_plan.h"

namespace vkpt {

// The errors the headline table is about (relMSE).
inline const std::vector<double> kHeadlineErrors{1e-2, 1e-3};

// The time axis. Wall: render time, without set-up and without the time the study spent
// reading back and measuring the image after each pass — what a user waits on a GPU. Cpu: the
// process's CPU time over the same span (all threads) — on a CPU device such as lavapipe the
// render's cost, which other work on a shared machine does not inflate as it does wall time.
enum class StudyClock { Wall, Cpu };
const char* clockName(StudyClock clock); // "wall", "cpu"
double curveSeconds(const ConvergencePoint& point, StudyClock clock);

struct RunResult {
    StudyRun run;
    std::vector<ConvergencePoint> curve; // error against the run's reference after every pass
    double setupSeconds = 0.0;           // upload and pipelines before the first pass
    std::string sharedWith;              // set: the curve is the first part of that run's
};

// The time at which a curve first has relMSE <= target, interpolated linearly in (log time,
// log error) between the passes on either side of the crossing; the first pass's time when it
// already starts below; NaN when the curve never gets there.
double timeToReach(const std::vector<ConvergencePoint>& curve, double target, StudyClock clock);

// The same on the axis of samples taken (over all pixels): deterministic, unlike time.
double samplesToReach(const std::vector<ConvergencePoint>& curve, double target);

// The points of `curve` within a budget of `spp` samples per pixel (a shared run's prefix).
std::vector<ConvergencePoint> curvePrefix(const std::vector<ConvergencePoint>& curve,
                                          std::uint32_t spp);

// The run of `family` that reaches `target` first in time (clock) or, without a clock, with
// the fewest samples: its index in `results`, or -1 when none does.
int fastestToReach(const std::vector<RunResult>& results, const std::string& family, double target,
                   StudyClock clock);
int fewestSamplesToReach(const std::vector<RunResult>& results, const std::string& family,
                         double target);

// Uniform over adaptive sampling at one error: in time (the fastest adaptive run) and in
// samples taken (the adaptive run that needs fewest). NaN where either never gets there.
struct AdaptiveSpeedup {
    double error = 0.0;
    double uniformSeconds = 0.0;
    double adaptiveSeconds = 0.0;
    std::string fastestLabel;
    double uniformSamples = 0.0;
    double adaptiveSamples = 0.0;
    std::string fewestSamplesLabel;
    double inTime() const { return uniformSeconds / adaptiveSeconds; }
    double inSamples() const { return uniformSamples / adaptiveSamples; }
};
AdaptiveSpeedup adaptiveSpeedup(const std::vector<RunResult>& results, double error,
                                StudyClock clock);

} // namespace vkpt
