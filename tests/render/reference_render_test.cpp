// reference_render_test.cpp — whole-image properties of vkpt-ref: determinism, energy
// plausibility on the Cornell box, symmetry, emitting sides and path-filter additivity.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/reference_render.h"
#include "../support/render_checks.h"
#include "image/image_compare.h"
#include "shared/sampling.h"

namespace vkpt {
namespace {

TEST(ReferenceRender, SameSeedGivesTheSameImageOnOneAndTwoThreads) {
    test::LoadedTestScene box = test::loadTestScene("cornell-box.gltf");
    RenderSettings settings = test::testSettings(24, 4);
    settings.seed = 11;
    settings.threads = 1;
    RenderOutput one = test::renderTestScene(box, settings);
    settings.threads = 2;
    RenderOutput two = test::renderTestScene(box, settings);
    ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
    for (std::size_t i = 0; i < one.image.pixels.size(); ++i)
        ASSERT_EQ(one.image.pixels[i], two.image.pixels[i]) << "pixel " << i;
    settings.seed = 12;
    RenderOutput other = test::renderTestScene(box, settings);
    EXPECT_NE(one.image.pixels, other.image.pixels) << "a new seed must give new noise";
}

// With at most one scattering event... none: depth 0 shows emitters only, each pixel either
// black or covered (partly, at edges) by the light, never brighter than it.
TEST(ReferenceRender, CornellBoxAtDepthZeroShowsOnlyTheLight) {
    test::LoadedTestScene box = test::loadTestScene("cornell-box.gltf");
    RenderSettings settings = test::testSettings(32, 8);
    settings.maxDepth = 0;
    RenderOutput output = test::renderTestScene(box, settings);
    float light = test::maxEmittedLuminance(box.scene);
    int lit = 0;
    for (const glm::vec3& p : output.image.pixels) {
        ASSERT_LE(gpu::luminance(p), light * (1.0f + 1e-5f));
        lit += gpu::luminance(p) > 0.0f;
    }
    EXPECT_GT(lit, 0) << "the light must be visible from the camera";
    EXPECT_LT(lit, int(output.image.pixels.size()) / 10) << "the light is small";
}

TEST(ReferenceRender, CornellBoxIsFiniteEnergyPlausibleAndRedOnTheLeft) {
    test::LoadedTestScene box = test::loadTestScene("cornell-box.gltf");
    test::expectCornellBoxPlausible(test::renderTestScene(box, test::testSettings(32, 16)),
                                    box.scene);
}

// The symmetric box mirrored about its vertical centre line: the left half and the mirrored
// right half are independent estimates of the same values, compared by the per-pixel z-test.
TEST(ReferenceRender, MirrorSymmetricSceneRendersMirrorSymmetric) {
    test::LoadedTestScene box = test::loadTestScene("test/symmetric-box.gltf");
    const std::uint32_t size = 32;
    RenderOutput output = test::renderTestScene(box, test::testSettings(size, 32));
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

// Direct-only and indirect-only split the paths by scattering count, so their means add up to
// the full render's, within 4.42 combined standard errors (two-sided p = 1e-5).
TEST(ReferenceRender, DirectOnlyPlusIndirectOnlyEqualsTheFullPath) {
    test::LoadedTestScene box = test::loadTestScene("cornell-box.gltf");
    RenderSettings settings = test::testSettings(24, 16);
    MeanEstimate full = meanLuminance(test::renderTestScene(box, settings));
    settings.pathFilter = PathFilter::DirectOnly;
    settings.seed = 1;
    MeanEstimate direct = meanLuminance(test::renderTestScene(box, settings));
    settings.pathFilter = PathFilter::IndirectOnly;
    settings.seed = 2;
    MeanEstimate indirect = meanLuminance(test::renderTestScene(box, settings));
    double se = std::sqrt(full.standardError * full.standardError +
                          direct.standardError * direct.standardError +
                          indirect.standardError * indirect.standardError);
    EXPECT_NEAR(direct.mean + indirect.mean, full.mean, 4.42 * se);
    EXPECT_GT(indirect.mean, 0.0) << "the Cornell box has indirect light";
}

TEST(ReferenceRender, SceneWithoutLightsIsBlack) {
    test::LoadedTestScene dark = test::loadTestScene("test/no-lights.gltf");
    EXPECT_TRUE(dark.prepared.emitters.empty());
    RenderOutput output = test::renderTestScene(dark, test::testSettings(8, 2));
    for (const glm::vec3& p : output.image.pixels)
        ASSERT_EQ(p, glm::vec3(0.0f));
}

TEST(ReferenceRender, NormalsIntegratorMapsUnitNormalsIntoTheUnitCube) {
    test::LoadedTestScene box = test::loadTestScene("cornell-box.gltf");
    RenderSettings settings = test::testSettings(16, 1);
    settings.integrator = Integrator::Normals;
    RenderOutput output = test::renderTestScene(box, settings);
    int hits = 0;
    for (const glm::vec3& p : output.image.pixels) {
        if (p == glm::vec3(0.0f)) continue;
        ++hits;
        EXPECT_NEAR(glm::length(2.0f * p - 1.0f), 1.0f, 1e-4f);
    }
    EXPECT_GT(hits, 200);
}

} // namespace
} // namespace vkpt
