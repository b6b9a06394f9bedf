// executor_render_test.cpp — whole renders checked on their own terms, one test body run on each
// executor (tests/support/render_executors.h: vkpt-ref, and vkpt on lavapipe): the white
// furnace's closed form at each depth, the Cornell box's light, energy, colours and path-filter
// additivity, independent direct estimators converging to the same image, scenes without
// lights, mirror symmetry, the normals integrator, and adaptive sampling's savings and error
// promise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../support/reference_render.h"
#include "../support/render_checks.h"
#include "../support/render_executors.h"
#include "image/image_compare.h"
#include "shared/adaptive.h"
#include "shared/sampling.h"

namespace vkpt::test::executor_render_test {
namespace {

// The inward-facing furnace and the double-sided one (emission from both faces).
const char* const kFurnaces[] = {"furnace.gltf", "test/furnace-double-sided.gltf"};

template <typename Executor> class Furnace : public Executor {};
TYPED_TEST_SUITE(Furnace, Executors);

TYPED_TEST(Furnace, DepthZeroSeesExactlyTheEmission) {
    for (const char* scene : kFurnaces) {
        SCOPED_TRACE(scene);
        LoadedTestScene furnace = loadTestScene(scene);
        FurnaceParameters p = furnaceParameters(furnace.scene);
        RenderSettings settings = testSettings(16, 4);
        settings.maxDepth = 0;
        RenderOutput output = this->render(furnace, settings);
        for (const glm::vec3& pixel : output.image.pixels)
            ASSERT_NEAR(gpu::luminance(pixel), p.emission, 1e-6f);
    }
}

TYPED_TEST(Furnace, EachDepthGivesTheGeometricSeries) {
    for (const char* scene : kFurnaces) {
        SCOPED_TRACE(scene);
        LoadedTestScene furnace = loadTestScene(scene);
        FurnaceParameters p = furnaceParameters(furnace.scene);
        for (std::uint32_t depth : {1u, 2u, 5u}) {
            RenderSettings settings = testSettings(16, 16);
            settings.maxDepth = depth;
            expectFurnaceMean(this->render(furnace, settings), furnaceRadiance(p, depth),
                              "max depth " + std::to_string(depth));
        }
    }
}

// Depth 64 with Russian roulette: the truncated tail a^65 is far below the noise, so the value
// is E / (1 − a); roulette must not bias it. On the device depth 64 takes more than one
// submission per pass (32 bounces each).
TYPED_TEST(Furnace, DeepPathsWithRussianRouletteGiveTheClosedForm) {
    for (const char* scene : kFurnaces) {
        SCOPED_TRACE(scene);
        LoadedTestScene furnace = loadTestScene(scene);
        FurnaceParameters p = furnaceParameters(furnace.scene);
        RenderSettings settings = testSettings(16, 32);
        settings.maxDepth = 64;
        expectFurnaceMean(this->render(furnace, settings), p.emission / (1.0 - p.albedo),
                          "max depth 64");
    }
}

template <typename Executor> class CornellBox : public Executor {};
TYPED_TEST_SUITE(CornellBox, Executors);

// Depth 0 shows emitters only: each pixel black or covered (partly, at edges) by the light,
// never brighter than it.
TYPED_TEST(CornellBox, DepthZeroShowsOnlyTheLight) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(32, 8);
    settings.maxDepth = 0;
    RenderOutput output = this->render(box, settings);
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
TYPED_TEST(CornellBox, IsFiniteEnergyPlausibleAndRedOnTheLeft) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    expectCornellBoxPlausible(this->render(box, testSettings(32, 16)), box.scene);
}

// The two filters split the paths by scattering count. At one seed their images add up to the
// full one up to float rounding (the same paths, each contribution kept by exactly one).
TYPED_TEST(CornellBox, DirectOnlyPlusIndirectOnlyEqualsTheFullPathAtOneSeed) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(24, 8);
    RenderOutput full = this->render(box, settings);
    settings.pathFilter = PathFilter::DirectOnly;
    RenderOutput direct = this->render(box, settings);
    settings.pathFilter = PathFilter::IndirectOnly;
    RenderOutput indirect = this->render(box, settings);
    for (std::size_t i = 0; i < full.image.pixels.size(); ++i) {
        glm::vec3 sum = direct.image.pixels[i] + indirect.image.pixels[i];
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(sum[c], full.image.pixels[i][c], 1e-4f * full.image.pixels[i][c] + 1e-6f)
                << "pixel " << i;
    }
}

// At independent seeds the means add up to the full render's, within 4.42 combined standard
// errors (two-sided p = 1e-5).
TYPED_TEST(CornellBox, DirectOnlyPlusIndirectOnlyEqualsTheFullPathInTheMean) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(24, 16);
    MeanEstimate full = meanLuminance(this->render(box, settings));
    settings.pathFilter = PathFilter::DirectOnly;
    settings.seed = 1;
    MeanEstimate direct = meanLuminance(this->render(box, settings));
    settings.pathFilter = PathFilter::IndirectOnly;
    settings.seed = 2;
    MeanEstimate indirect = meanLuminance(this->render(box, settings));
    double se = std::sqrt(full.standardError * full.standardError +
                          direct.standardError * direct.standardError +
                          indirect.standardError * indirect.standardError);
    EXPECT_NEAR(direct.mean + indirect.mean, full.mean, 4.42 * se);
    EXPECT_GT(indirect.mean, 0.0) << "the Cornell box has indirect light";
}

template <typename Executor> class DirectLighting : public Executor {};
TYPED_TEST_SUITE(DirectLighting, Executors);

// The path tracer limited to one bounce (MIS) and the direct integrator at another seed agree
// in distribution (expectSameImage: per-pixel test, family-wise α = 0.01).
TYPED_TEST(DirectLighting, PathTracerAtDepthOneMatchesTheDirectIntegrator) {
    LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(24, 32);
    settings.maxDepth = 1;
    RenderOutput path = this->render(scene, settings);
    settings.integrator = Integrator::Direct;
    settings.seed = 1;
    RenderOutput direct = this->render(scene, settings);
    expectSameImage(path, direct, "path depth 1 vs direct");
}

// CS184's two estimators of direct lighting: light sampling at seed 0, uniform hemisphere
// directions at seed 1. Hemisphere sampling finds the light rarely: at the floor's far corners
// a uniform direction hits it about 1 time in 70. A pixel's variance estimate is only
// trustworthy with some dozens of hits (with a handful, a low count also shrinks the estimated
// variance and inflates |z|), so 256 samples × 16 directions give ≥ 50 hits everywhere. (At 128
// samples, ≥ 25 hits, one seed in eight of the sampler's two-halves layout put a pixel at
// |z| = 5.1; at 256, twelve seeds in twelve pass.)
TYPED_TEST(DirectLighting, HemisphereAndLightSamplingConvergeToTheSameImage) {
    LoadedTestScene scene = loadTestScene("test/quad-light-floor.gltf");
    RenderSettings settings = testSettings(16, 256);
    settings.integrator = Integrator::Direct;
    settings.lightSamples = 16;
    settings.lightSampling = LightSampling::Light;
    RenderOutput light = this->render(scene, settings);
    settings.lightSampling = LightSampling::Hemisphere;
    settings.seed = 1;
    RenderOutput hemisphere = this->render(scene, settings);
    expectSameImage(light, hemisphere, "light vs hemisphere sampling");
}

template <typename Executor> class Scenes : public Executor {};
TYPED_TEST_SUITE(Scenes, Executors);

TYPED_TEST(Scenes, SceneWithoutLightsIsBlack) {
    LoadedTestScene dark = loadTestScene("test/no-lights.gltf");
    ASSERT_TRUE(dark.prepared.emitters.empty());
    RenderOutput output = this->render(dark, testSettings(8, 2));
    for (const glm::vec3& p : output.image.pixels)
        ASSERT_EQ(p, glm::vec3(0.0f));
}

// The symmetric box mirrored about its vertical centre line: the left half and the mirrored
// right half are independent estimates of the same values, compared by the per-pixel z-test.
TYPED_TEST(Scenes, MirrorSymmetricSceneRendersMirrorSymmetric) {
    LoadedTestScene box = loadTestScene("test/symmetric-box.gltf");
    const std::uint32_t size = 32;
    RenderOutput output = this->render(box, testSettings(size, 32));
    RenderOutput left, mirrored;
    for (RenderOutput* half : {&left, &mirrored}) {
        half->image = Image(size / 2, size);
        half->sampleCounts.resize(size / 2 * size);
        half->luminanceMean.resize(size / 2 * size);
        half->luminanceM2.resize(size / 2 * size);
    }
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size / 2; ++x) {
            std::size_t h = y * (size / 2) + x, a = y * size + x, b = y * size + (size - 1 - x);
            left.image.pixels[h] = output.image.pixels[a];
            mirrored.image.pixels[h] = output.image.pixels[b];
            left.sampleCounts[h] = output.sampleCounts[a];
            mirrored.sampleCounts[h] = output.sampleCounts[b];
            left.luminanceMean[h] = output.luminanceMean[a];
            mirrored.luminanceMean[h] = output.luminanceMean[b];
            left.luminanceM2[h] = output.luminanceM2[a];
            mirrored.luminanceM2[h] = output.luminanceM2[b];
        }
    ZTestResult z = zTestPerPixel(left, mirrored, 0.01);
    EXPECT_TRUE(z.passed) << z.summary;
}

TYPED_TEST(Scenes, NormalsIntegratorMapsUnitNormalsIntoTheUnitCube) {
    LoadedTestScene box = loadTestScene("cornell-box.gltf");
    RenderSettings settings = testSettings(16, 1);
    settings.integrator = Integrator::Normals;
    RenderOutput output = this->render(box, settings);
    int hits = 0;
    for (const glm::vec3& p : output.image.pixels) {
        if (p == glm::vec3(0.0f)) continue;
        ++hits;
        EXPECT_NEAR(glm::length(2.0f * p - 1.0f), 1.0f, 1e-4f);
    }
    EXPECT_GT(hits, 200);
}

template <typename Executor> class AdaptiveSampling : public Executor {};
TYPED_TEST_SUITE(AdaptiveSampling, Executors);

RenderSettings adaptiveSettings(std::uint32_t size, std::uint32_t spp, float tolerance) {
    RenderSettings settings = testSettings(size, spp);
    settings.adaptive.enabled = true;
    settings.adaptive.batchSize = 16;
    settings.adaptive.minSamples = 32;
    settings.adaptive.tolerance = tolerance;
    return settings;
}

TYPED_TEST(AdaptiveSampling, BlackPixelsStopAtTheMinimumCount) {
    LoadedTestScene scene = loadTestScene("test/single-triangle.gltf");
    RenderSettings settings = adaptiveSettings(16, 256, 0.05f);
    RenderOutput output = this->render(scene, settings);
    int black = 0;
    for (std::size_t i = 0; i < output.image.pixels.size(); ++i) {
        if (output.image.pixels[i] != glm::vec3(0.0f)) continue;
        ++black;
        EXPECT_EQ(output.sampleCounts[i], settings.adaptive.minSamples) << "pixel " << i;
    }
    EXPECT_GT(black, 0);
}

TYPED_TEST(AdaptiveSampling, NoPixelStopsBeforeTheMinimumOrExceedsTheBudget) {
    LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    RenderSettings settings = adaptiveSettings(16, 128, 0.5f);
    RenderStats stats;
    RenderOutput output = this->render(scene, settings, &stats);
    for (std::uint32_t count : output.sampleCounts) {
        EXPECT_GE(count, settings.adaptive.minSamples);
        EXPECT_LE(count, settings.samplesPerPixel);
        EXPECT_TRUE(count % settings.adaptive.batchSize == 0 || count == settings.samplesPerPixel);
    }
    EXPECT_LT(stats.samplesTaken, stats.uniformBudget) << "a loose tolerance must save samples";
}

// The truth for the error promise: the CPU reference at 2048 spp and another seed, rendered once
// for both executors.
const RenderOutput& convergedCornellBox(const LoadedTestScene& scene) {
    static const RenderOutput converged = [&scene] {
        RenderSettings settings = testSettings(16, 2048);
        settings.seed = 99;
        return renderTestScene(scene, settings);
    }();
    return converged;
}

// Pixels that stopped early promised a 95 % interval of half-width tol·μ; against the far more
// converged render, at least 90 % must lie within it (render_checks.h).
TYPED_TEST(AdaptiveSampling, StoppedPixelsKeepTheirErrorPromise) {
    LoadedTestScene scene = loadTestScene("cornell-box.gltf");
    const float tolerance = 0.2f;
    RenderSettings settings = adaptiveSettings(16, 512, tolerance);
    RenderStats stats;
    RenderOutput adaptive = this->render(scene, settings, &stats);
    std::printf("adaptive: %llu of %llu samples (%.1f %%)\n",
                (unsigned long long)stats.samplesTaken, (unsigned long long)stats.uniformBudget,
                100.0 * double(stats.samplesTaken) / double(stats.uniformBudget));
    EXPECT_LT(stats.samplesTaken, stats.uniformBudget);
    expectAdaptivePromiseKept(adaptive, convergedCornellBox(scene), settings.samplesPerPixel,
                              tolerance);
}

} // namespace
} // namespace vkpt::test::executor_render_test
