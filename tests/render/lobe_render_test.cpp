// lobe_render_test.cpp — the lobes only some scenes compile, rendered whole by vkpt-ref
// (tests/support/render_executors.h): light sampling through a leaf that transmits
// diffusely (KHR_materials_diffuse_transmission) gives the image BSDF sampling alone gives, and a
// lossless dispersive glass ball (KHR_materials_dispersion) in a uniform environment still shows
// the environment's colour on average: the wavelength weights keep a white path white.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../support/render_executors.h"
#include "image/image_compare.h"
#include "shared/sampling.h"

namespace vkpt::test::lobe_render_test {
namespace {

// vkpt-ref only: the device's images of these scenes equal the reference's at one seed
// (tests/image/lobe_same_seed_test.cpp), and a device instance would compile two more feature
// sets' pipelines (about 30 s each on lavapipe) to show it again.
template <typename Executor> class LobeRenders : public Executor {};
using ReferenceOnly = ::testing::Types<ReferenceExecutor>;
TYPED_TEST_SUITE(LobeRenders, ReferenceOnly);

// The mean luminance of the pixels in [first, last]² of a square image, with its standard error
// from the pixels' own variances of the mean (as meanLuminance does for the whole image).
MeanEstimate squareMeanLuminance(const RenderOutput& output, std::uint32_t first,
                                 std::uint32_t last) {
    double sum = 0.0, varianceSum = 0.0, pixels = 0.0;
    for (std::uint32_t y = first; y <= last; ++y)
        for (std::uint32_t x = first; x <= last; ++x) {
            const std::size_t i = std::size_t(y) * output.image.width + x;
            const double n = double(output.sampleCounts[i]);
            sum += double(output.luminanceMean[i]);
            varianceSum += std::max(0.0, double(output.luminanceM2[i])) / (n - 1.0) / n;
            pixels += 1.0;
        }
    return {sum / pixels, std::sqrt(varianceSum) / pixels};
}

// scenes/test/lobes/leaf.gltf: the leaf is lit only by the panel behind it. With light samples
// the panel is reached through the leaf by shadow rays from its far side, weighed by MIS against
// transmitted BSDF samples; with none, BSDF sampling alone finds it (weight 1). The two
// estimators have the same expectation only if light sampling through the wall is right (a
// shadow ray left on the near side, or a transmitted sample weighed as if light sampling could
// not reach it, would darken or brighten the leaf). Compared on the leaf's own pixels (the
// central 6 × 6 of 16 × 16, all inside it), whose means at different seeds agree within 4
// standard errors of their difference; the floor and walls around it, lit by light that
// crossed the leaf and found by BSDF sampling alone, carry fireflies that a per-pixel test
// would take for a difference. 64 samples: the leaf region's standard error is then about 2 %.
TYPED_TEST(LobeRenders, LightSamplingThroughALeafAgreesWithBsdfSamplingAlone) {
    LoadedTestScene leaf = loadTestScene("test/lobes/leaf.gltf");
    RenderSettings settings = testSettings(16, 64);
    settings.lightSamples = 2;
    settings.seed = 1;
    const MeanEstimate withLights = squareMeanLuminance(this->render(leaf, settings), 5, 10);
    settings.lightSamples = 0;
    settings.seed = 2;
    const MeanEstimate bsdfAlone = squareMeanLuminance(this->render(leaf, settings), 5, 10);
    const double sigma = std::hypot(withLights.standardError, bsdfAlone.standardError);
    std::printf("leaf: light sampling %.5f ± %.5f, BSDF sampling alone %.5f ± %.5f\n",
                withLights.mean, withLights.standardError, bsdfAlone.mean, bsdfAlone.standardError);
    EXPECT_GT(withLights.mean, 0.0);
    EXPECT_NEAR(withLights.mean, bsdfAlone.mean, 4.0 * sigma);
    // Light sampling through the wall is what makes the leaf converge: it halves the error.
    EXPECT_LT(withLights.standardError, 0.5 * bsdfAlone.standardError);
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

// The direct integrator lights dispersive glass at the path's wavelength, as the path tracer
// does (docs/integrator.md, "Dispersion"). The glass ball made rough (0.4) and strongly
// dispersive (dispersion 4, V_d = 5: n from 1.46 at 700 nm to 1.68 at 400 nm) in a blue
// environment: what the ball reflects of it is F(n(λ)) weighed by the blue response, whose
// wavelengths see n ≈ 1.6 (F0 0.053 against 0.040 at the d line's index). One scattering event,
// so that the path tracer (MIS of light and BSDF samples; a refracted sample ends inside the
// ball) and the direct integrator (light samples alone; the ball shadows what it would transmit)
// estimate the same light. Their mean luminance over the ball's central 8 × 8 pixels of 16 × 16
// agree within 4 standard errors of their difference. At 1024 samples those errors are 2.5 % and
// 3.6 %; the direct integrator that lit the glass at the d line's index gave 25 % less (0.00611
// against 0.00812, 9 standard errors), and now 0.00776 (1.1).
TYPED_TEST(LobeRenders, DirectAndPathIntegratorsLightDispersiveGlassAlike) {
    TestSceneOptions options;
    options.environment.radiance = glm::vec3(0.0f, 0.0f, 2.0f);
    LoadedTestScene ball = loadTestScene("test/features/glass-ball.gltf", options);
    ASSERT_EQ(ball.scene.materials.size(), 1u);
    ball.scene.materials[0].dispersion = 4.0f;
    ball.scene.materials[0].roughness = 0.4f;
    ball.prepared = prepareScene(ball.scene, {});
    ASSERT_TRUE(ball.prepared.features.dispersion);
    RenderSettings settings = testSettings(16, 1024);
    settings.maxDepth = 1;
    settings.seed = 7;
    const MeanEstimate path = squareMeanLuminance(this->render(ball, settings), 4, 11);
    settings.integrator = Integrator::Direct;
    settings.seed = 8;
    const MeanEstimate direct = squareMeanLuminance(this->render(ball, settings), 4, 11);
    std::printf("rough dispersive ball: path %.5f ± %.5f, direct %.5f ± %.5f\n", path.mean,
                path.standardError, direct.mean, direct.standardError);
    EXPECT_GT(direct.mean, 0.0);
    EXPECT_NEAR(path.mean, direct.mean, 4.0 * std::hypot(path.standardError, direct.standardError));
}

} // namespace
} // namespace vkpt::test::lobe_render_test
