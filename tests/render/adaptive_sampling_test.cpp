// adaptive_sampling_test.cpp — the per-pixel stopping rule in whole renders: it saves
// samples, stops black pixels at the minimum count and keeps its error promise.
#include <gtest/gtest.h>

#include <algorithm>

#include "../support/reference_render.h"
#include "../support/render_checks.h"
#include "shared/adaptive.h"
#include "shared/sampling.h"

namespace vkpt {
namespace {

RenderSettings adaptiveSettings(std::uint32_t size, std::uint32_t spp, float tolerance) {
    RenderSettings settings = test::testSettings(size, spp);
    settings.adaptive.enabled = true;
    settings.adaptive.batchSize = 16;
    settings.adaptive.minSamples = 32;
    settings.adaptive.tolerance = tolerance;
    return settings;
}

TEST(AdaptiveSampling, BlackPixelsStopAtTheMinimumCount) {
    test::LoadedTestScene scene = test::loadTestScene("test/single-triangle.gltf");
    RenderSettings settings = adaptiveSettings(16, 256, 0.05f);
    RenderOutput output = test::renderTestScene(scene, settings);
    int black = 0;
    for (std::size_t i = 0; i < output.image.pixels.size(); ++i) {
        if (output.image.pixels[i] != glm::vec3(0.0f)) continue;
        ++black;
        EXPECT_EQ(output.sampleCounts[i], settings.adaptive.minSamples) << "pixel " << i;
    }
    EXPECT_GT(black, 0);
}

TEST(AdaptiveSampling, NoPixelStopsBeforeTheMinimumOrExceedsTheBudget) {
    test::LoadedTestScene scene = test::loadTestScene("cornell-box.gltf");
    RenderSettings settings = adaptiveSettings(16, 128, 0.5f);
    RenderStats stats;
    RenderOutput output = test::renderTestScene(scene, settings, &stats);
    for (std::uint32_t count : output.sampleCounts) {
        EXPECT_GE(count, settings.adaptive.minSamples);
        EXPECT_LE(count, settings.samplesPerPixel);
        EXPECT_TRUE(count % settings.adaptive.batchSize == 0 || count == settings.samplesPerPixel);
    }
    EXPECT_LT(stats.samplesTaken, stats.uniformBudget) << "a loose tolerance must save samples";
}

// Pixels that stopped early keep their error promise against a 2048-spp render.
TEST(AdaptiveSampling, StoppedPixelsKeepTheirErrorPromise) {
    test::LoadedTestScene scene = test::loadTestScene("cornell-box.gltf");
    const float tolerance = 0.2f;
    RenderSettings settings = adaptiveSettings(16, 512, tolerance);
    RenderOutput adaptive = test::renderTestScene(scene, settings);
    RenderSettings referenceSettings = test::testSettings(16, 2048);
    referenceSettings.seed = 99;
    RenderOutput reference = test::renderTestScene(scene, referenceSettings);
    test::expectAdaptivePromiseKept(adaptive, reference, settings.samplesPerPixel, tolerance);
}

} // namespace
} // namespace vkpt
