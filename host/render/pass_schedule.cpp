// pass_schedule.cpp — samples per pass and chunk sizes.
#include "render/pass_schedule.h"

#include <algorithm>

#include "common/errors.h"

namespace vkpt {

namespace {

std::uint32_t divideRoundingUp(std::uint32_t a, std::uint32_t b) {
    return a / b + (a % b != 0 ? 1u : 0u);
}

// The first sample count above `done` after which the reference tests a pixel: a multiple of
// the batch, and at least the minimum count.
std::uint64_t nextTestPoint(const ScheduleInputs& in) {
    std::uint64_t first = std::max<std::uint64_t>(in.samplesDone + 1, in.adaptiveMinSamples);
    std::uint64_t batch = in.adaptiveBatch;
    return (first + batch - 1) / batch * batch;
}

} // namespace

std::uint32_t samplesForPass(const ScheduleInputs& in) {
    VKPT_ASSERT(in.samplesDone < in.samplesPerPixel && in.activePixels > 0 && in.slotCount > 0,
                "a pass needs samples left, active pixels and slots");
    const std::uint32_t remaining = in.samplesPerPixel - in.samplesDone;
    const std::uint32_t fit =
        std::min({remaining, std::max(1u, in.slotCount / in.activePixels), kMaxSamplesPerPass});
    if (!in.adaptive) return fit;
    const std::uint64_t firstTest = nextTestPoint(in) - in.samplesDone;
    if (firstTest > fit) return fit; // no test inside this pass: fill the slots
    const std::uint32_t busy = std::min(fit, divideRoundingUp(in.slotCount / 4, in.activePixels));
    const std::uint64_t batch = in.adaptiveBatch;
    const std::uint64_t wanted = busy > firstTest ? (busy - firstTest + batch - 1) / batch : 0;
    const std::uint64_t possible = (fit - firstTest) / batch;
    return static_cast<std::uint32_t>(firstTest + std::min(wanted, possible) * batch);
}

std::uint32_t pixelsPerChunk(std::uint32_t activePixels, std::uint32_t samplesPerPass,
                             std::uint32_t slotCount) {
    VKPT_ASSERT(samplesPerPass > 0 && samplesPerPass <= slotCount, "k samples must fit the slots");
    return std::min(activePixels, slotCount / samplesPerPass);
}

} // namespace vkpt
