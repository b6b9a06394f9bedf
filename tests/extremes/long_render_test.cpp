// long_render_test.cpp — 2^20 samples in one pixel: a constant-radiance scene gives the
// constant to 1e-6 relative in both renderers (the reference sums in double, the device keeps a
// Kahan-compensated float sum), and the Welford variance stays finite and non-negative, also
// where a naive Σx² − nμ² would cancel to nonsense.
#include <gtest/gtest.h>

#include "extremes_support.h"
#include "shared/sampling.h"

namespace vkpt::long_render_test {
namespace {

// The camera inside a closed box that emits `emission` from both sides of every face and
// reflects `albedo`.
Scene glowingBox(glm::vec3 emission, float albedo) {
    Scene scene;
    std::uint32_t glow = test::addMaterial(scene, glm::vec3(albedo), emission, true);
    test::addBox(scene, glm::vec3(-1.0f), glm::vec3(1.0f), glow);
    scene.cameras.push_back(test::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f),
                                         glm::vec3(0.0f, 1.0f, 0.0f), 40.0f));
    return scene;
}

constexpr std::uint32_t kMillionSamples = 1u << 20;

// What a plain float running sum makes of n equal samples: the test's teeth.
float naiveFloatMean(float value, std::uint32_t n) {
    float sum = 0.0f;
    for (std::uint32_t i = 0; i < n; ++i)
        sum += value;
    return sum / float(n);
}

class LongRender : public test::GpuTest {};

TEST_F(LongRender, AMillionSamplesOfAConstantGiveTheConstant) {
    const glm::vec3 emission(0.3f, 0.7f, 0.1f);
    // A plain float sum misses by 4.9e-4 relative, 490 times the bound.
    ASSERT_GT(std::abs(naiveFloatMean(0.3f, kMillionSamples) - 0.3f), 100.0f * 1e-6f * 0.3f)
        << "a plain float sum would be accurate enough: the test would prove nothing";
    RenderSettings settings = test::testSettings(1, kMillionSamples);
    settings.maxDepth = 0; // every sample is the emission seen directly, exactly
    test::BothRenders r =
        test::renderBoth(context(), test::prepareTestScene(glowingBox(emission, 0.0f)), settings);
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        const char* who = out == &r.cpu ? "vkpt-ref" : "vkpt";
        EXPECT_EQ(out->sampleCounts[0], kMillionSamples) << who;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(out->image.pixels[0][c], emission[c], 1e-6f * emission[c])
                << who << " channel " << c;
        EXPECT_NEAR(out->luminanceMean[0], gpu::luminance(emission),
                    1e-6f * gpu::luminance(emission))
            << who;
        EXPECT_EQ(out->luminanceM2[0], 0.0f) << who << ": the samples do not vary";
    }
    EXPECT_EQ(r.cpuStats.samplesTaken, kMillionSamples);
    EXPECT_EQ(r.gpuStats.samplesTaken, kMillionSamples);
}

// Samples of about 1000 that vary by about 1 (a bright box of albedo 1e-3, one bounce): the
// mean of the squares and the square of the mean agree to 1e-6, so Σx² − nμ² in float would be
// rounding noise of either sign. Welford's M2 stays non-negative and the device's float M2
// matches the reference's double one.
TEST_F(LongRender, WelfordVarianceOfABrightLowNoisePixelIsAccurate) {
    RenderSettings settings = test::testSettings(1, 1u << 16);
    settings.maxDepth = 1;
    test::BothRenders r = test::renderBoth(
        context(), test::prepareTestScene(glowingBox(glm::vec3(1000.0f), 1e-3f)), settings);
    EXPECT_TRUE(test::outputIsFinite(r.cpu));
    EXPECT_TRUE(test::outputIsFinite(r.gpu));
    const double cpuVariance = double(r.cpu.luminanceM2[0]) / double(r.cpu.sampleCounts[0] - 1);
    const double gpuVariance = double(r.gpu.luminanceM2[0]) / double(r.gpu.sampleCounts[0] - 1);
    const double mean = double(r.cpu.luminanceMean[0]);
    ASSERT_GT(cpuVariance, 0.0);
    EXPECT_LT(cpuVariance, 1e-4 * mean * mean) << "the noise is small against the mean";
    EXPECT_NEAR(gpuVariance, cpuVariance, 0.01 * cpuVariance);
}

} // namespace
} // namespace vkpt::long_render_test
