// batch_policy.cpp — the caps on a render's next batch (batch_policy.h).
#include "driver/batch_policy.h"

#include <algorithm>
#include <bit>
#include <cmath>

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

std::uint32_t firstCalibrationPoint(std::uint32_t minSamples) {
    return std::max(minSamples / 2, kFirstCalibrationSamples);
}

std::uint32_t nextCalibrationPoint(std::uint32_t samplesDone, std::uint32_t first) {
    std::uint64_t point = first;
    while (point <= samplesDone)
        point *= 2;
    return std::uint32_t(std::min<std::uint64_t>(point, UINT32_MAX));
}

bool isCalibrationPoint(std::uint32_t samplesDone, std::uint32_t first) {
    return first > 0 && samplesDone >= first && samplesDone % first == 0 &&
           std::has_single_bit(samplesDone / first);
}

float quantizedVarianceScale(double scale) {
    return float(std::round(scale * 64.0) / 64.0);
}

} // namespace vkpt
