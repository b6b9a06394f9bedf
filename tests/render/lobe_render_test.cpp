// lobe_render_test.cpp — the lobes only some scenes compile, rendered whole, one test body per
// executor (tests/support/render_executors.h): light sampling through a leaf that transmits
// diffusely (KHR_materials_diffuse_transmission) gives the image BSDF sampling alone gives, and a
// lossless dispersive glass ball (KHR_materials_dispersion) in a uniform environment still shows
// the environment's colour on average: the wavelength weights keep a white path white.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/render_executors.h"
#include "image/image_compare.h"
#include "shared/sampling.h"

namespace vkpt::test {
namespace {

template <typename Executor> class LobeRenders : public Executor {};
TYPED_TEST_SUITE(LobeRenders, Executors);

// scenes/test/lobes/leaf.gltf: the leaf is lit only by the panel behind it. With light samples
// the panel is reached through the leaf by shadow rays from its far side, weighed by MIS against
// transmitted BSDF samples; with none, BSDF sampling alone finds it (weight 1). The two
// estimators have the same expectation only if light sampling through the wall is right (a
// shadow ray left on the near side, or a transmitted sample weighed as if light sampling could
// not reach it, would darken or brighten the leaf): a per-pixel z-test at different seeds,
// family-wise α = 0.01 (Šidák over the pixels). 16 × 16 pixels at 64 samples: the leaf covers a
// third of the image and BSDF sampling alone converges there at this count.
TYPED_TEST(LobeRenders, LightSamplingThroughALeafAgreesWithBsdfSamplingAlone) {
    LoadedTestScene leaf = loadTestScene("test/lobes/leaf.gltf");
    RenderSettings settings = testSettings(16, 64);
    settings.lightSamples = 2;
    settings.seed = 1;
    RenderOutput withLights = this->render(leaf, settings);
    settings.lightSamples = 0;
    settings.seed = 2;
    RenderOutput bsdfAlone = this->render(leaf, settings);
    ZTestResult z = zTestPerPixel(withLights, bsdfAlone, 0.01);
    std::printf("leaf, light sampling vs BSDF sampling alone: %s\n", z.summary.c_str());
    EXPECT_TRUE(z.passed) << z.summary;
    EXPECT_GT(meanLuminance(withLights).mean, 0.0);
}

const glm::vec3 kEnvironment(0.5f, 1.0f, 2.0f);

// scenes/test/features/glass-ball.gltf (smooth glass of ior 1.5, a lossless volume) made
// dispersive (dispersion 2): every path that meets the ball carries a wavelength and the weight
// w(λ), and every factor of its path is otherwise 1 (glass_render_test's lossless ball), so a
// sample is L·w(λ) and its expectation L because E[w] = 1 per channel. The image's mean
// luminance is that of L within 4 standard errors (from the pixels' own variances); and the
// image is not L everywhere, which it would be if no path took a wavelength. As
// glass_render_test: Russian roulette from the depth limit, 256 events. 32 × 32 pixels at 8
// samples: the ball covers most of the image.
TYPED_TEST(LobeRenders, DispersiveLosslessBallKeepsTheEnvironmentsColourOnAverage) {
    TestSceneOptions options;
    options.environment.radiance = kEnvironment;
    LoadedTestScene ball = loadTestScene("test/features/glass-ball.gltf", options);
    ASSERT_EQ(ball.scene.materials.size(), 1u);
    ball.scene.materials[0].dispersion = 2.0f;
    ball.prepared = prepareScene(ball.scene, {});
    ASSERT_TRUE(ball.prepared.features.dispersion);
    RenderSettings settings = testSettings(32, 8);
    settings.maxDepth = 256;
    settings.rrStartDepth = 256;
    settings.seed = 5;
    const RenderOutput output = this->render(ball, settings);
    const MeanEstimate mean = meanLuminance(output);
    const double expected = double(gpu::luminance(kEnvironment));
    std::printf("dispersive ball: mean luminance %.5f ± %.5f, environment %.5f\n", mean.mean,
                mean.standardError, expected);
    EXPECT_NEAR(mean.mean, expected, 4.0 * mean.standardError);
    int coloured = 0;
    for (const glm::vec3& p : output.image.pixels)
        coloured += std::abs(p.x - kEnvironment.x) > 1e-3f * kEnvironment.x;
    EXPECT_GT(coloured, 100) << "no path took a wavelength";
}

} // namespace
} // namespace vkpt::test
