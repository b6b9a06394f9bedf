// reference_render_test.cpp — whole-image properties of vkpt-ref alone: determinism over
// threads, mirror symmetry and the normals integrator. What holds for either executor is
// tested once for both in executor_render_test.cpp.
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
