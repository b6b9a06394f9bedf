// denoise_kernel_test.cpp — vkpt's denoiser kernels give the CPU loop's image: the same shared
// functions (shared/denoise_filter.h) on the same input, equal up to the device's float rounding
// (exp and pow may differ in the last bits). 37×23 pixels: odd sides exercise the borders and a
// partial workgroup; random guides, noise levels, misses, pixels without halves and a firefly
// reach every branch.
#include "denoise/cpu_denoiser.h"
#include "gpu_test_support.h"
#include "render/device_denoiser.h"

#include <cmath>
#include <random>

namespace vkpt::test::denoise_kernel_test {
namespace {

std::vector<gpu::DenoisePixel> randomPixels(std::uint32_t width, std::uint32_t height) {
    std::mt19937 random(20261129u);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<gpu::DenoisePixel> pixels(std::size_t(width) * height);
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        gpu::DenoisePixel& p = pixels[i];
        const bool miss = unit(random) < 0.1f;
        const float region = (i % width) < width / 2 ? 1.0f : 0.3f;
        p.radiance = region * glm::vec3(unit(random), unit(random), unit(random));
        p.luminanceVariance = 0.01f * unit(random) * unit(random);
        p.albedo = miss ? glm::vec3(0.0f) : glm::vec3(unit(random), 0.5f, 0.2f);
        p.depth = miss ? INFINITY : 1.0f + 0.1f * unit(random);
        p.normal = miss ? glm::vec3(0.0f) : glm::normalize(glm::vec3(0.1f * unit(random), 0, 1));
        p.sampleCount = 16;
        p.halfA = p.radiance * (0.8f + 0.4f * unit(random));
        p.halfB = 2.0f * p.radiance - p.halfA;
        const bool oneHalf = unit(random) < 0.05f; // no half estimate: stays raw
        p.halfCountA = oneHalf ? 0.0f : 8.0f;
        p.halfCountB = oneHalf ? 16.0f : 8.0f;
    }
    gpu::DenoisePixel& firefly = pixels[width * (height / 2) + width / 2];
    firefly.radiance = glm::vec3(500.0f);
    firefly.halfA = glm::vec3(1000.0f) - firefly.halfB;
    return pixels;
}

class DenoiseKernel : public GpuTest {};

TEST_F(DenoiseKernel, DeviceEqualsCpu) {
    constexpr std::uint32_t kWidth = 37, kHeight = 23;
    const std::vector<gpu::DenoisePixel> pixels = randomPixels(kWidth, kHeight);
    const DenoiseSettings settings;
    DeviceDenoiser device(context());
    const std::vector<glm::vec3> onDevice = device.denoise(pixels, kWidth, kHeight, settings);
    const std::vector<glm::vec3> onCpu = CpuDenoiser(1).denoise(pixels, kWidth, kHeight, settings);
    ASSERT_EQ(onDevice.size(), onCpu.size());
    for (std::size_t i = 0; i < onCpu.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(onDevice[i][c], onCpu[i][c], 1e-4f * std::abs(onCpu[i][c]) + 1e-6f)
                << "pixel " << i << ", channel " << c;
}

} // namespace
} // namespace vkpt::test::denoise_kernel_test
