// cpu_denoiser.cpp — the denoiser's iterations over rows on every core (cpu_denoiser.h).
#include "cpu_denoiser.h"

#include <algorithm>
#include <functional>
#include <thread>

#include "common/errors.h"
#include "shared/denoise_filter.h"

namespace vkpt {

namespace {

// Runs rowWork(y) for every y in [0, height), rows dealt out in turn to `threads` threads.
void forEachRow(std::uint32_t height, unsigned threads,
                const std::function<void(std::uint32_t)>& rowWork) {
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t)
        workers.emplace_back([&, t] {
            for (std::uint32_t y = t; y < height; y += threads)
                rowWork(y);
        });
    for (std::thread& worker : workers)
        worker.join();
}

} // namespace

std::vector<glm::vec3> CpuDenoiser::denoise(const std::vector<gpu::DenoisePixel>& pixels,
                                            std::uint32_t width, std::uint32_t height,
                                            const DenoiseSettings& settings) {
    VKPT_ASSERT(pixels.size() == std::size_t(width) * height, "one input per pixel");
    VKPT_ASSERT(settings.iterations > 0, "at least one iteration");
    const unsigned threads =
        std::max(1u, std::min(threads_ ? threads_ : std::thread::hardware_concurrency(), height));
    std::vector<gpu::DenoiseValue> current(pixels.size());
    std::vector<gpu::DenoiseValue> next(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i)
        current[i] = gpu::demodulatedPixel(pixels[i]);
    // The iterations, then the last pass that only chooses (denoiseParams, step 0).
    for (std::uint32_t iteration = 0; iteration <= settings.iterations; ++iteration) {
        const gpu::DenoiseParams params = denoiseParams(settings, width, height, iteration);
        const gpu::DenoiseSource source{pixels.data(), current.data()};
        forEachRow(height, threads, [&](std::uint32_t y) {
            for (std::uint32_t x = 0; x < width; ++x)
                next[std::size_t(y) * width + x] = gpu::filterPixel(source, x, y, params);
        });
        std::swap(current, next);
    }
    std::vector<glm::vec3> radiance(pixels.size());
    for (std::size_t i = 0; i < pixels.size(); ++i)
        radiance[i] = gpu::modulatedRadiance(pixels[i], current[i]);
    return radiance;
}

} // namespace vkpt
