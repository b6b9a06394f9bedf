// furnace_test.cpp — the white furnace: inside a closed surface of albedo a emitting E, the
// radiance with at most D scattering events is exactly E·(1 − a^(D+1)) / (1 − a) everywhere.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/reference_render.h"
#include "image/image_compare.h"
#include "shared/sampling.h"

namespace vkpt {
namespace {

struct FurnaceParameters {
    float emission;
    float albedo;
};

FurnaceParameters furnaceParameters(const Scene& scene) {
    const SceneMaterial& m = scene.materials.at(0);
    return {gpu::luminance(m.emission), gpu::luminance(glm::vec3(m.baseColor))};
}

double furnaceRadiance(const FurnaceParameters& p, std::uint32_t maxDepth) {
    double a = p.albedo;
    return p.emission * (1.0 - std::pow(a, double(maxDepth) + 1.0)) / (1.0 - a);
}

// The image mean must lie within 4.42 standard errors (two-sided p = 1e-5) of the analytic
// value, the standard error coming from the render's own per-pixel variances, plus a float
// rounding allowance of 1e-5 relative.
void expectFurnaceMean(const RenderOutput& output, double expected, const std::string& what) {
    MeanEstimate mean = meanLuminance(output);
    double bound = 4.42 * mean.standardError + 1e-5 * expected;
    EXPECT_NEAR(mean.mean, expected, bound) << what << ": standard error " << mean.standardError;
}

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
