// adaptive_edges_test.cpp — adaptive sampling where its rule meets its edges, with the same
// answers (sample counts per pixel) from vkpt-ref and vkpt: black pixels stop at the minimum
// count, a tolerance of 1e-4 spends the whole budget, a tolerance of 1 stops at the minimum, and
// a pixel whose first batch is all zero but which has a rare bright path is protected by the
// minimum count (and only by it: a minimum of one batch lets that batch stop it, as defined).
#include <gtest/gtest.h>

#include "extremes_support.h"

namespace vkpt::adaptive_edges_test {
namespace {

// A lit floor in the lower half of the view, nothing (black) in the upper half.
Scene floorAndVoid() {
    Scene scene;
    std::uint32_t white = test::addMaterial(scene, glm::vec3(0.7f));
    std::uint32_t light = test::addMaterial(scene, glm::vec3(0.0f), glm::vec3(20.0f));
    test::addHorizontalGrid(scene, glm::vec2(-4.0f), glm::vec2(4.0f), 0.0f, true, 1, white);
    test::addQuad(scene, {-0.2f, 1.0f, -0.2f}, {0.2f, 1.0f, -0.2f}, {0.2f, 1.0f, 0.2f},
                  {-0.2f, 1.0f, 0.2f}, light);
    scene.cameras.push_back(test::lookAt(glm::vec3(0.0f, 0.5f, 2.0f), glm::vec3(0.0f, 0.5f, 0.0f),
                                         glm::vec3(0.0f, 1.0f, 0.0f), 50.0f));
    return scene;
}

RenderSettings adaptiveSettings(std::uint32_t spp, float tolerance, std::uint32_t batch,
                                std::uint32_t minSamples, std::uint32_t size = 16) {
    RenderSettings settings = test::testSettings(size, spp);
    settings.adaptive.enabled = true;
    settings.adaptive.batchSize = batch;
    settings.adaptive.tolerance = tolerance;
    settings.adaptive.minSamples = minSamples;
    return settings;
}

// Both renderers take the same samples in every pixel (docs/wavefront.md) and stay finite.
void expectSameSampleCounts(const test::BothRenders& r) {
    EXPECT_TRUE(test::outputIsFinite(r.cpu));
    EXPECT_TRUE(test::outputIsFinite(r.gpu));
    std::size_t differing = 0;
    for (std::size_t i = 0; i < r.cpu.sampleCounts.size(); ++i)
        differing += r.cpu.sampleCounts[i] != r.gpu.sampleCounts[i];
    EXPECT_EQ(differing, 0u) << "pixels whose sample counts differ between vkpt-ref and vkpt";
}

struct PixelCounts {
    std::size_t black = 0, lit = 0;
    std::size_t blackAtMinimum = 0, litAtMinimum = 0, litAtBudget = 0, belowMinimum = 0;
};

PixelCounts classify(const RenderOutput& out, std::uint32_t minSamples, std::uint32_t spp) {
    PixelCounts c;
    for (std::size_t i = 0; i < out.image.pixels.size(); ++i) {
        const std::uint32_t n = out.sampleCounts[i];
        const bool black = out.image.pixels[i] == glm::vec3(0.0f);
        (black ? c.black : c.lit) += 1;
        if (black) c.blackAtMinimum += n == minSamples;
        if (!black) c.litAtMinimum += n == minSamples;
        if (!black) c.litAtBudget += n == spp;
        c.belowMinimum += n < minSamples;
    }
    return c;
}

class AdaptiveEdges : public test::GpuTest {};

TEST_F(AdaptiveEdges, BlackPixelsStopAtTheMinimumCount) {
    RenderSettings settings = adaptiveSettings(1024, 0.05f, 16, 64);
    test::BothRenders r =
        test::renderBoth(context(), test::prepareTestScene(floorAndVoid()), settings);
    expectSameSampleCounts(r);
    PixelCounts c = classify(r.cpu, 64, 1024);
    ASSERT_GT(c.black, 0u);
    ASSERT_GT(c.lit, 0u);
    EXPECT_EQ(c.blackAtMinimum, c.black);
    EXPECT_EQ(c.belowMinimum, 0u);
}

TEST_F(AdaptiveEdges, ToleranceOfOneInTenThousandSpendsTheWholeBudget) {
    RenderSettings settings = adaptiveSettings(256, 1e-4f, 16, 64);
    test::BothRenders r =
        test::renderBoth(context(), test::prepareTestScene(floorAndVoid()), settings);
    expectSameSampleCounts(r);
    PixelCounts c = classify(r.cpu, 64, 256);
    EXPECT_EQ(c.litAtBudget, c.lit);
    EXPECT_EQ(c.blackAtMinimum, c.black) << "the dark floor still stops black pixels";
}

TEST_F(AdaptiveEdges, ToleranceOfOneStopsAtTheMinimumCount) {
    RenderSettings settings = adaptiveSettings(1024, 1.0f, 16, 64);
    test::BothRenders r =
        test::renderBoth(context(), test::prepareTestScene(floorAndVoid()), settings);
    expectSameSampleCounts(r);
    PixelCounts c = classify(r.cpu, 64, 1024);
    EXPECT_EQ(c.belowMinimum, 0u);
    EXPECT_GE(double(c.litAtMinimum), 0.9 * double(c.lit));
}

// One pixel looking at the void with a small light covering about 2 % of its view: a camera
// sample finds the light rarely.
Scene rareLight() {
    Scene scene;
    std::uint32_t light = test::addMaterial(scene, glm::vec3(0.0f), glm::vec3(50.0f));
    const float h = 0.0125f; // half side: (2h)² against the view's (2·tan 5°)² ≈ 2 %
    test::addQuad(scene, {-h, -h, -1.0f}, {h, -h, -1.0f}, {h, h, -1.0f}, {-h, h, -1.0f}, light);
    scene.cameras.push_back(test::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f),
                                         glm::vec3(0.0f, 1.0f, 0.0f), 10.0f));
    return scene;
}

// A seed whose first 8 samples all miss the light while some of the first 64 find it.
std::uint32_t seedWithAZeroFirstBatch(const test::LoadedTestScene& scene) {
    for (std::uint32_t seed = 0; seed < 100; ++seed) {
        RenderSettings first = test::testSettings(1, 8), more = test::testSettings(1, 64);
        first.seed = more.seed = seed;
        if (test::renderTestScene(scene, first).image.pixels[0] == glm::vec3(0.0f) &&
            test::renderTestScene(scene, more).image.pixels[0] != glm::vec3(0.0f))
            return seed;
    }
    ADD_FAILURE() << "no seed with a zero first batch and a later hit";
    return 0;
}

TEST_F(AdaptiveEdges, ZeroFirstBatchDoesNotStopAPixelTheMinimumProtects) {
    test::LoadedTestScene scene = test::prepareTestScene(rareLight());
    RenderSettings settings = adaptiveSettings(1024, 0.05f, 8, 64, 1);
    settings.seed = seedWithAZeroFirstBatch(scene);
    test::BothRenders r = test::renderBoth(context(), scene, settings);
    expectSameSampleCounts(r);
    EXPECT_GE(r.cpu.sampleCounts[0], 64u);
    EXPECT_GT(r.cpu.image.pixels[0].x, 0.0f) << "the rare light was found";
    EXPECT_GT(r.gpu.image.pixels[0].x, 0.0f);
}

// Defined, not protected: with a minimum of one batch, a batch of zeros has zero variance and
// stops the pixel at once. The minimum count is the guard against rare paths.
TEST_F(AdaptiveEdges, MinimumOfOneBatchLetsAZeroBatchStopThePixel) {
    test::LoadedTestScene scene = test::prepareTestScene(rareLight());
    RenderSettings settings = adaptiveSettings(1024, 0.05f, 8, 8, 1);
    settings.seed = seedWithAZeroFirstBatch(scene);
    test::BothRenders r = test::renderBoth(context(), scene, settings);
    expectSameSampleCounts(r);
    EXPECT_EQ(r.cpu.sampleCounts[0], 8u);
    EXPECT_EQ(r.cpu.image.pixels[0], glm::vec3(0.0f));
}

} // namespace
} // namespace vkpt::adaptive_edges_test
