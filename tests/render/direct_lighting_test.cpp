// direct_lighting_test.cpp — independent estimators of the same direct lighting must agree:
// CS184's hemisphere and light sampling, and the path tracer limited to one bounce (MIS).
#include <gtest/gtest.h>

#include "../support/reference_render.h"
#include "../support/render_checks.h"
#include "image/image_compare.h"

namespace vkpt {
namespace {


TEST(DirectLighting, HemisphereAndLightSamplingConvergeToTheSameImage) {
    test::LoadedTestScene scene = test::loadTestScene("test/quad-light-floor.gltf");
    // Hemisphere sampling finds the light rarely: at the floor's far corners a uniform
    // direction hits it about 1 time in 70. A pixel's variance estimate is only trustworthy
    // with some dozens of hits (with a handful, a low count also shrinks the estimated
    // variance and inflates |z|), so 128 samples × 16 directions give ≥ 25 hits everywhere.
    RenderSettings settings = test::testSettings(16, 128);
    settings.integrator = Integrator::Direct;
    settings.lightSamples = 16;
    settings.lightSampling = LightSampling::Light;
    RenderOutput light = test::renderTestScene(scene, settings);
    settings.lightSampling = LightSampling::Hemisphere;
    settings.seed = 1;
    RenderOutput hemisphere = test::renderTestScene(scene, settings);
    test::expectSameImage(light, hemisphere, "light vs hemisphere sampling");
}

TEST(DirectLighting, PathTracerAtDepthOneMatchesTheDirectIntegrator) {
    test::LoadedTestScene scene = test::loadTestScene("cornell-box.gltf");
    RenderSettings settings = test::testSettings(24, 32);
    settings.maxDepth = 1;
    RenderOutput path = test::renderTestScene(scene, settings);
    settings.integrator = Integrator::Direct;
    settings.seed = 1;
    RenderOutput direct = test::renderTestScene(scene, settings);
    test::expectSameImage(path, direct, "path depth 1 vs direct");
}

TEST(DirectLighting, MoreLightSamplesReduceVariance) {
    test::LoadedTestScene scene = test::loadTestScene("test/quad-light-floor.gltf");
    RenderSettings settings = test::testSettings(16, 16);
    settings.integrator = Integrator::Direct;
    MeanEstimate one = meanLuminance(test::renderTestScene(scene, settings));
    settings.lightSamples = 16;
    MeanEstimate many = meanLuminance(test::renderTestScene(scene, settings));
    EXPECT_LT(many.standardError, one.standardError);
    EXPECT_NEAR(one.mean, many.mean, 4.42 * std::hypot(one.standardError, many.standardError));
}

} // namespace
} // namespace vkpt
