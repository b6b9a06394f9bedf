// render_driver.cpp — the batch loop around an executor (render_driver.h).
#include "driver/render_driver.h"

#include <chrono>

#include "common/phase_log.h"
#include "driver/batch_policy.h"
#include "image/error_metrics.h"

namespace vkpt {

namespace {

using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point begin, Clock::time_point end) {
    return std::chrono::duration<double>(end - begin).count();
}

class RenderDriver {
public:
    RenderDriver(RenderExecutor& executor, const RenderRunOptions& options)
        : executor_(executor), options_(options), start_(Clock::now()), lastCheckpoint_(start_),
          startCpu_(processCpuSeconds()) {}

    RenderRunResult run() {
        // A resumed render may have nothing left to do.
        const bool done =
            executor_.activePixels() == 0 || executor_.samplesDone() >= executor_.budget();
        // A resumed adaptive render calibrates on what it resumes (after the first point).
        const std::uint32_t first = executor_.firstCalibration();
        if (!done && first > 0 && executor_.samplesDone() >= first) calibrate();
        const RenderStop stop = done ? RenderStop::Budget : runBatches();
        executor_.finish();
        RenderRunResult result;
        RenderSnapshot pixels = executor_.snapshot();
        result.output = std::move(pixels.output);
        result.records = std::move(pixels.records);
        result.features = executor_.features();
        result.stats.seconds = elapsed();
        result.passes = batches_;
        result.stop = stop;
        result.interrupted = stop == RenderStop::Interrupted;
        return result;
    }

private:
    double elapsed() const { return secondsBetween(start_, Clock::now()); }

    RenderStop runBatches() {
        while (true) {
            const bool more = runBatch();
            if (observe()) return RenderStop::TargetError;
            if (!more)
                return executor_.activePixels() == 0 && executor_.samplesDone() < executor_.budget()
                           ? RenderStop::Converged
                           : RenderStop::Budget;
            if (options_.interrupt && options_.interrupt->load()) return RenderStop::Interrupted;
            checkpointIfDue();
            if (options_.timeLimitSeconds > 0.0 && elapsed() >= options_.timeLimitSeconds)
                return RenderStop::TimeLimit;
        }
    }

    // The executor's batch, cut for log-spaced measurements, the next checkpoint and the time
    // limit.
    std::uint32_t nextBatch() const {
        const std::uint32_t done = executor_.samplesDone();
        const std::uint64_t active = executor_.activePixels();
        std::uint32_t k = executor_.batchWanted(executor_.budget() - done, secondsPerPixelSample_);
        if (options_.readPixelsAfterPass) k = samplesForGeometricGrowth(k, done);
        if (const std::uint32_t first = executor_.firstCalibration(); first > 0)
            k = std::min(k, nextCalibrationPoint(done, first) - done);
        if (options_.checkpoint && options_.checkpointSeconds > 0.0) {
            const double sinceCheckpoint = secondsBetween(lastCheckpoint_, Clock::now());
            k = samplesWithinTime(k, active, secondsPerPixelSample_,
                                  options_.checkpointSeconds - sinceCheckpoint);
        }
        if (!(options_.timeLimitSeconds > 0.0)) return k;
        return samplesWithinTime(k, active, secondsPerPixelSample_,
                                 options_.timeLimitSeconds - elapsed());
    }

    // False once nothing is left to sample.
    bool runBatch() {
        const std::uint32_t k = nextBatch();
        const Clock::time_point begin = Clock::now();
        const std::uint64_t samples = executor_.runBatch(k);
        if (samples > 0)
            secondsPerPixelSample_ = secondsBetween(begin, Clock::now()) / double(samples);
        ++batches_;
        const bool more =
            executor_.samplesDone() < executor_.budget() && executor_.activePixels() > 0;
        if (more && isCalibrationPoint(executor_.samplesDone(), executor_.firstCalibration()))
            calibrate();
        return more;
    }

    // Adaptive sampling's variance scale from the image's two halves so far (batch_policy.h).
    void calibrate() {
        const RenderSnapshot pixels = executor_.snapshot();
        executor_.setVarianceScale(quantizedVarianceScale(varianceScaleFromHalves(pixels.output)));
    }

    // One look at the pixels when the observer wants the image; its time and the observer's
    // own are counted, so that an observer can leave them out of its timings.
    bool observe() {
        if (!options_.afterPass) return false;
        const Clock::time_point begin = Clock::now();
        const double beginCpu = processCpuSeconds();
        PassFigures figures;
        figures.pass = batches_;
        figures.samplesPerPixel = executor_.samplesDone();
        figures.activePixels = std::uint32_t(executor_.activePixels());
        figures.seconds = secondsBetween(start_, begin);
        figures.renderSeconds = figures.seconds - observerSeconds_;
        figures.cpuSeconds = beginCpu - startCpu_ - observerCpuSeconds_;
        RenderSnapshot pixels;
        const RenderOutput* shown = nullptr;
        if (options_.readPixelsAfterPass) {
            pixels = executor_.snapshot();
            shown = &pixels.output;
            for (const PixelRecord& record : pixels.records)
                figures.samplesTaken += record.samplesTaken;
        }
        const bool stop = options_.afterPass(figures, shown);
        observerSeconds_ += secondsBetween(begin, Clock::now());
        observerCpuSeconds_ += processCpuSeconds() - beginCpu;
        return stop;
    }

    // The pixels and features at a batch end, handed to the caller, who writes them.
    void checkpointIfDue() {
        if (!options_.checkpoint || !(options_.checkpointSeconds > 0.0)) return;
        if (secondsBetween(lastCheckpoint_, Clock::now()) < options_.checkpointSeconds) return;
        options_.checkpoint(executor_.snapshot().records, executor_.features());
        lastCheckpoint_ = Clock::now();
    }

    RenderExecutor& executor_;
    const RenderRunOptions& options_;
    Clock::time_point start_;
    Clock::time_point lastCheckpoint_;
    double startCpu_ = 0.0;
    double secondsPerPixelSample_ = 0.0; // the last batch's rate, for the caps
    double observerSeconds_ = 0.0;       // spent in readbacks and observer calls
    double observerCpuSeconds_ = 0.0;
    std::uint32_t batches_ = 0;
};

} // namespace

RenderRunResult runRender(RenderExecutor& executor, const RenderRunOptions& options) {
    return RenderDriver(executor, options).run();
}

} // namespace vkpt
