// batch_policy.cpp — the caps on a render's next batch (batch_policy.h).
#include "driver/batch_policy.h"

#include <algorithm>

namespace vkpt {

std::uint32_t samplesForGeometricGrowth(std::uint32_t k, std::uint32_t samplesDone) {
    return std::min(k, std::max(1u, samplesDone / 4));
}

std::uint32_t samplesWithinTime(std::uint32_t k, std::uint64_t activePixels,
                                double secondsPerPixelSample, double secondsLeft) {
    if (!(secondsPerPixelSample > 0.0) || activePixels == 0) return k;
    const double fit = secondsLeft / (secondsPerPixelSample * double(activePixels));
    if (!(fit >= 1.0)) return std::min(k, 1u); // also NaN: never less than one sample
    return fit >= double(k) ? k : static_cast<std::uint32_t>(fit);
}

} // namespace vkpt
