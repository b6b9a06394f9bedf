// furnace_test.cpp — the white furnace: inside a closed surface of albedo a emitting E, the
// radiance with at most D scattering events is exactly E·(1 − a^(D+1)) / (1 − a) everywhere.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/reference_render.h"
#include "../support/render_checks.h"

namespace vkpt {
namespace {

using test::expectFurnaceMean;
using test::furnaceParameters;
using test::FurnaceParameters;
using test::furnaceRadiance;

class Furnace : public ::testing::TestWithParam<const char*> {};

TEST_P(Furnace, DepthZeroSeesExactlyTheEmission) {
    test::LoadedTestScene furnace = test::loadTestScene(GetParam());
    FurnaceParameters p = furnaceParameters(furnace.scene);
    RenderSettings settings = test::testSettings(16, 4);
    settings.maxDepth = 0;
    RenderOutput output = test::renderTestScene(furnace, settings);
    for (const glm::vec3& pixel : output.image.pixels)
        ASSERT_NEAR(gpu::luminance(pixel), p.emission, 1e-6f);
}

TEST_P(Furnace, EachDepthGivesTheGeometricSeries) {
    test::LoadedTestScene furnace = test::loadTestScene(GetParam());
    FurnaceParameters p = furnaceParameters(furnace.scene);
    for (std::uint32_t depth : {1u, 2u, 5u}) {
        RenderSettings settings = test::testSettings(16, 16);
        settings.maxDepth = depth;
        expectFurnaceMean(test::renderTestScene(furnace, settings), furnaceRadiance(p, depth),
                          "max depth " + std::to_string(depth));
    }
}

// Depth 64 with Russian roulette: the truncated tail a^65 is far below the noise, so the
// value is E / (1 − a); roulette must not bias it.
TEST_P(Furnace, DeepPathsWithRussianRouletteGiveTheClosedForm) {
    test::LoadedTestScene furnace = test::loadTestScene(GetParam());
    FurnaceParameters p = furnaceParameters(furnace.scene);
    RenderSettings settings = test::testSettings(16, 32);
    settings.maxDepth = 64;
    expectFurnaceMean(test::renderTestScene(furnace, settings), p.emission / (1.0 - p.albedo),
                      "max depth 64");
}

INSTANTIATE_TEST_SUITE_P(InwardAndDoubleSided, Furnace,
                         ::testing::Values("furnace.gltf", "test/furnace-double-sided.gltf"));

} // namespace
} // namespace vkpt
