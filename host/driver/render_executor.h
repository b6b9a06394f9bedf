// render_executor.h — what the render driver asks of an executor: where the render stands,
// the batch it would take next, to take a batch, and the pixels so far. The executor owns the
// scene on its device and its own schedule; the driver owns the loop around it.
#pragma once

#include <cstdint>
#include <vector>

#include "image/render_output.h"
#include "state/render_state.h"

namespace vkpt {

// The pixels at a batch end: the plan's crop as records (row-major) and the whole frame.
struct RenderSnapshot {
    std::vector<PixelRecord> records;
    RenderOutput output;
};

class RenderExecutor {
public:
    virtual ~RenderExecutor() = default;

    // Samples per pixel (of the plan's range) that every unfinished pixel has taken: the
    // budget once all are done.
    virtual std::uint32_t samplesDone() const = 0;
    // Samples per pixel of the plan's range.
    virtual std::uint32_t budget() const = 0;
    // Pixels that go on: not converged and short of the budget.
    virtual std::uint64_t activePixels() const = 0;
    // The batch (samples per active pixel, 1 to `left`) the executor would take next, before
    // the driver's caps; `secondsPerPixelSample` is the last batch's rate (0 before the first).
    virtual std::uint32_t batchWanted(std::uint32_t left, double secondsPerPixelSample) const = 0;
    // Takes `k` more samples for every active pixel; returns how many pixel samples it took
    // (fewer where adaptive sampling stopped pixels in the batch).
    virtual std::uint64_t runBatch(std::uint32_t k) = 0;
    virtual RenderSnapshot snapshot() = 0;
    // The crop's AOVs, row-major; none when the render records none.
    virtual std::vector<FeatureRecord> features() = 0;
    // The loop is over (the executor's progress display ends here).
    virtual void finish() {}
    // Adaptive sampling's first calibration point (batch_policy.h, firstCalibrationPoint), 0 for a
    // render without adaptive sampling.
    virtual std::uint32_t firstCalibration() const { return 0; }
    // The variance scale the adaptive stopping rule applies from the next batch on
    // (shared/adaptive.h); 1 until the driver sets it.
    virtual void setVarianceScale(float) {}
};

} // namespace vkpt
