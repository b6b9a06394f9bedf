// wavefront_render_test.cpp — whole renders with vkpt checked on their own terms, as the
// reference's are in tests/render: the white furnace's closed form at each depth, the Cornell
// box's light, energy and colours, adaptive sampling's savings and error promise, path-filter
// additivity, scenes without lights, and the direct estimators converging to the same image.
#include <cmath>

#include "../support/render_checks.h"
#include "image/image_compare.h"
#include "shared/adaptive.h"
#include "shared/sampling.h"
#include "wavefront_test_support.h"

namespace vkpt::test {
namespace {

class WavefrontFurnace : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(WavefrontFurnace, DepthZeroSeesExactlyTheEmission) {
    LoadedTestScene furnace = loadTestScene(GetParam());
    FurnaceParameters p = furnaceParameters(furnace.scene);
    RenderSettings settings = testSettings(16, 4);
    settings.maxDepth = 0;
    RenderOutput output = renderOnDevice(context(), furnace, settings);
    for (const glm::vec3& pixel : output.image.pixels)
        ASSERT_NEAR(gpu::luminance(pixel), p.emission, 1e-6f);
}

TEST_P(WavefrontFurnace, EachDepthGivesTheGeometricSeries) {
    LoadedTestScene furnace = loadTestScene(GetParam());
    FurnaceParameters p = furnaceParameters(furnace.scene);
    for (std::uint32_t depth : {1u, 2u, 5u}) {
        RenderSettings settings = testSettings(16, 16);
        settings.maxDepth = depth;
        expectFurnaceMean(renderOnDevice(context(), furnace, settings), furnaceRadiance(p, depth),
                          "max depth " + std::to_string(depth));
    }
}

// Depth 64 takes more than one submission per pass (32 bounces each); Russian roulette must
// not bias the closed form E / (1 − a).
TEST_P(WavefrontFurnace, DeepPathsWithRussianRouletteGiveTheClosedForm) {
    LoadedTestScene furnace = loadTestScene(GetParam());
    FurnaceParameters p = furnaceParameters(furnace.scene);
    RenderSettings settings = testSettings(16, 32);
    settings.maxDepth = 64;
    expectFurnaceMean(renderOnDevice(context(), furnace, settings), p.emission / (1.0 - p.albedo),
                      "max depth 64");
}

INSTANTIATE_TEST_SUITE_P(InwardAndDoubleSided, WavefrontFurnace,
                         ::testing::Values("furnace.gltf", "test/furnace-double-sided.gltf"));

class WavefrontCornellBox : public GpuTest {};

TEST_F(WavefrontCornellBox, DepthZeroShowsOnlyTheLight) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(32, 8);
    settings.maxDepth = 0;
    RenderOutput output = renderOnDevice(context(), box, settings);
    float light = maxEmittedLuminance(box.scene);
    int lit = 0;
    for (const glm::vec3& p : output.image.pixels) {
        ASSERT_LE(gpu::luminance(p), light * (1.0f + 1e-5f));
        lit += gpu::luminance(p) > 0.0f;
    }
    EXPECT_GT(lit, 0) << "the light must be visible from the camera";
    EXPECT_LT(lit, int(output.image.pixels.size()) / 10) << "the light is small";
}

// No pixel of reflected light can exceed Le·ρ/(1 − ρ) on average; red wall left, green right.
TEST_F(WavefrontCornellBox, IsFiniteEnergyPlausibleAndRedOnTheLeft) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    expectCornellBoxPlausible(renderOnDevice(context(), box, testSettings(32, 16)), box.scene);
}

// The two filters split the paths by scattering count: at one seed their images add up to the
// full one up to float rounding (the same paths, each contribution kept by exactly one).
TEST_F(WavefrontCornellBox, DirectOnlyPlusIndirectOnlyEqualsTheFullPath) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(24, 8);
    RenderOutput full = renderOnDevice(context(), box, settings);
    settings.pathFilter = PathFilter::DirectOnly;
    RenderOutput direct = renderOnDevice(context(), box, settings);
    settings.pathFilter = PathFilter::IndirectOnly;
    RenderOutput indirect = renderOnDevice(context(), box, settings);
    for (std::size_t i = 0; i < full.image.pixels.size(); ++i) {
        glm::vec3 sum = direct.image.pixels[i] + indirect.image.pixels[i];
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(sum[c], full.image.pixels[i][c], 1e-4f * full.image.pixels[i][c] + 1e-6f)
                << "pixel " << i;
    }
}

TEST_F(WavefrontCornellBox, PathTracerAtDepthOneMatchesTheDirectIntegrator) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(24, 32);
    settings.maxDepth = 1;
    RenderOutput path = renderOnDevice(context(), box, settings);
    settings.integrator = Integrator::Direct;
    settings.seed = 1;
    RenderOutput direct = renderOnDevice(context(), box, settings);
    ZTestResult z = zTestPerPixel(path, direct, 0.01);
    EXPECT_TRUE(z.passed) << z.summary;
}

class WavefrontScenes : public GpuTest {};

TEST_F(WavefrontScenes, SceneWithoutLightsIsBlack) {
    LoadedTestScene dark = loadTestScene("test/no-lights.gltf");
    ASSERT_TRUE(dark.prepared.emitters.empty());
    RenderOutput output = renderOnDevice(context(), dark, testSettings(8, 2));
    for (const glm::vec3& p : output.image.pixels)
        ASSERT_EQ(p, glm::vec3(0.0f));
}

TEST_F(WavefrontScenes, HemisphereAndLightSamplingConvergeToTheSameImage) {
    LoadedTestScene scene = loadTestScene("test/quad-light-floor.gltf");
    RenderSettings settings = testSettings(16, 64); // 64 × 16 directions: tests/render's reasoning
    settings.integrator = Integrator::Direct;
    settings.lightSamples = 16;
    RenderOutput light = renderOnDevice(context(), scene, settings);
    settings.lightSampling = LightSampling::Hemisphere;
    settings.seed = 1;
    RenderOutput hemisphere = renderOnDevice(context(), scene, settings);
    ZTestResult z = zTestPerPixel(light, hemisphere, 0.01);
    EXPECT_TRUE(z.passed) << z.summary;
}

RenderSettings adaptiveSettings(std::uint32_t size, std::uint32_t spp, float tolerance) {
    RenderSettings settings = testSettings(size, spp);
    settings.adaptive = {true, 16, tolerance, 32};
    return settings;
}

class WavefrontAdaptive : public GpuTest {};

TEST_F(WavefrontAdaptive, BlackPixelsStopAtTheMinimumCount) {
    LoadedTestScene scene = loadTestScene("test/single-triangle.gltf");
    RenderSettings settings = adaptiveSettings(16, 256, 0.05f);
    RenderOutput output = renderOnDevice(context(), scene, settings);
    int black = 0;
    for (std::size_t i = 0; i < output.image.pixels.size(); ++i) {
        if (output.image.pixels[i] != glm::vec3(0.0f)) continue;
        ++black;
        EXPECT_EQ(output.sampleCounts[i], settings.adaptive.minSamples) << "pixel " << i;
    }
    EXPECT_GT(black, 0);
}

TEST_F(WavefrontAdaptive, NoPixelStopsBeforeTheMinimumOrExceedsTheBudget) {
    LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    RenderSettings settings = adaptiveSettings(16, 128, 0.5f);
    RenderStats stats;
    RenderOutput output = renderOnDevice(context(), scene, settings, &stats);
    for (std::uint32_t count : output.sampleCounts) {
        EXPECT_GE(count, settings.adaptive.minSamples);
        EXPECT_LE(count, settings.samplesPerPixel);
        EXPECT_TRUE(count % settings.adaptive.batchSize == 0 || count == settings.samplesPerPixel);
    }
    EXPECT_LT(stats.samplesTaken, stats.uniformBudget) << "a loose tolerance must save samples";
}

// Pixels that stopped early promised a 95 % interval of half-width tol·μ; against a far more
// converged render (the CPU reference at another seed), at least 90 % must lie within it.
TEST_F(WavefrontAdaptive, StoppedPixelsKeepTheirErrorPromise) {
    LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    const float tolerance = 0.2f;
    RenderSettings settings = adaptiveSettings(16, 512, tolerance);
    RenderStats stats;
    RenderOutput adaptive = renderOnDevice(context(), scene, settings, &stats);
    RenderSettings referenceSettings = testSettings(16, 2048);
    referenceSettings.seed = 99;
    RenderOutput reference = renderTestScene(scene, referenceSettings);
    std::printf("adaptive: %llu of %llu samples (%.1f %%)\n",
                (unsigned long long)stats.samplesTaken, (unsigned long long)stats.uniformBudget,
                100.0 * double(stats.samplesTaken) / double(stats.uniformBudget));
    EXPECT_LT(stats.samplesTaken, stats.uniformBudget);
    expectAdaptivePromiseKept(adaptive, reference, settings.samplesPerPixel, tolerance);
}

} // namespace
} // namespace vkpt::test
