// scene_model_test.cpp — the scene model's parts in whole renders by vkpt-ref, against closed
// forms where there are any (punctual lights in their units, a constant environment, emitting
// spheres, alpha MASK) and against an independent estimator where there are not (GGX
// materials and the environment map: light sampling vs hemisphere sampling, path tracing at
// depth 1 vs CS184's direct integrator). The device repeats these images in tests/image.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/reference_render.h"
#include "../support/render_checks.h"
#include "../support/scene_builder.h"
#include "common/math_constants.h"
#include "image/image_compare.h"
#include "prepare/environment_map.h"

namespace vkpt::scene_model_test {
namespace {

// A camera at height h looking straight down at the origin, with a narrow field of view so
// that the image's centre pixels see the floor right below it.
SceneCamera downwardCamera(float height, float yfovDegrees) {
    SceneCamera camera;
    camera.position = glm::vec3(0.0f, height, 0.0f);
    camera.forward = glm::vec3(0.0f, -1.0f, 0.0f);
    camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.yfov = glm::radians(yfovDegrees);
    return camera;
}

// A 20 × 20 m diffuse floor at y = 0 (albedo rho, facing up), seen from above.
Scene floorScene(float rho, float yfovDegrees = 1.0f) {
    Scene scene;
    std::uint32_t floor = test::addMaterial(scene, glm::vec3(rho));
    test::addHorizontalGrid(scene, {-10.0f, -10.0f}, {10.0f, 10.0f}, 0.0f, true, 1, floor);
    scene.cameras.push_back(downwardCamera(1.0f, yfovDegrees));
    return scene;
}

test::LoadedTestScene prepared(Scene scene) {
    test::LoadedTestScene loaded{std::move(scene), {}};
    loaded.prepared = prepareScene(loaded.scene);
    return loaded;
}

const glm::vec3& centrePixel(const RenderOutput& output) {
    return output.image.at(output.image.width / 2, output.image.height / 2);
}

RenderSettings directOnly(std::uint32_t size, std::uint32_t spp) {
    RenderSettings settings = test::testSettings(size, spp);
    settings.maxDepth = 1;
    return settings;
}

// A point light of I cd at height d over a floor of albedo ρ: the floor below it reflects
// L = (ρ/π)·I/d² (1 cd is radiant intensity 1 in image units). A delta light with one
// emitter gives the same value every sample, so the bound is float rounding plus the
// variation of cos θ/r² over the centre pixel of a 1° view (< 1e-4).
TEST(PunctualLights, PointLightFollowsTheInverseSquareLawInCandela) {
    Scene scene = floorScene(0.5f);
    SceneLight point;
    point.kind = LightKind::Point;
    point.position = glm::vec3(0.0f, 0.5f, 0.0f);
    point.intensity = glm::vec3(2.0f, 1.0f, 0.5f);
    scene.lights.push_back(point);
    RenderOutput output = test::renderTestScene(prepared(scene), directOnly(9, 4));
    glm::vec3 expected = 0.5f / kPiFloat * point.intensity / (0.5f * 0.5f);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(centrePixel(output)[c], expected[c], 2e-4f * expected[c]) << "channel " << c;
}

// Inside the inner cone a spot light is a point light; beyond the outer cone it is dark.
TEST(PunctualLights, SpotLightIsFullInsideItsInnerConeAndDarkOutsideItsOuterCone) {
    for (bool aimedAtCamera : {true, false}) {
        Scene scene = floorScene(0.5f);
        SceneLight spot;
        spot.kind = LightKind::Spot;
        spot.position = glm::vec3(0.0f, 0.5f, 0.0f);
        spot.intensity = glm::vec3(3.0f);
        spot.innerConeAngle = 0.3f;
        spot.outerConeAngle = 0.5f;
        // Straight down, or tilted 60° so that the point below lies outside the outer cone.
        float tilt = aimedAtCamera ? 0.0f : glm::radians(60.0f);
        spot.direction = glm::vec3(std::sin(tilt), -std::cos(tilt), 0.0f);
        scene.lights.push_back(spot);
        RenderOutput output = test::renderTestScene(prepared(scene), directOnly(9, 4));
        float expected = aimedAtCamera ? 0.5f / kPiFloat * 3.0f / 0.25f : 0.0f;
        EXPECT_NEAR(centrePixel(output).x, expected, 2e-4f * expected + 1e-7f)
            << (aimedAtCamera ? "inside the inner cone" : "outside the outer cone");
    }
}

// A directional light of E lux at 60° from the zenith: L = (ρ/π)·E·cos 60° everywhere.
TEST(PunctualLights, DirectionalLightGivesLambertsCosineLawInLux) {
    Scene scene = floorScene(0.8f, 40.0f);
    SceneLight sun;
    sun.kind = LightKind::Directional;
    sun.direction = glm::normalize(glm::vec3(std::sqrt(3.0f), -1.0f, 0.0f)); // 60° from down
    sun.intensity = glm::vec3(4.0f);
    scene.lights.push_back(sun);
    RenderOutput output = test::renderTestScene(prepared(scene), directOnly(8, 2));
    float expected = 0.8f / kPiFloat * 4.0f * 0.5f;
    for (const glm::vec3& pixel : output.image.pixels)
        ASSERT_NEAR(pixel.x, expected, 2e-5f * expected);
}

// A constant environment L over a floor that sees nothing else: the floor reflects ρ·L (its
// irradiance is π·L), estimated by light and BSDF samples under MIS; the bound is 4.42
// standard errors of the image mean (two-sided p = 1e-5) from the render's own variances.
// Rays that miss see L exactly.
TEST(Environment, ConstantEnvironmentLightsAFloorWithItsIrradiance) {
    Scene scene = floorScene(0.6f, 60.0f);
    scene.environment.radiance = glm::vec3(0.5f);
    RenderOutput output = test::renderTestScene(prepared(scene), directOnly(16, 64));
    MeanEstimate mean = meanLuminance(output);
    EXPECT_NEAR(mean.mean, 0.6 * 0.5, 4.42 * mean.standardError + 1e-6);

    Scene sky = floorScene(0.6f, 60.0f);
    sky.cameras[0].forward = glm::vec3(0.0f, 1.0f, 0.0f); // looking up, away from the floor
    sky.environment.radiance = glm::vec3(0.5f, 0.25f, 1.0f);
    for (const glm::vec3& pixel :
         test::renderTestScene(prepared(sky), directOnly(4, 2)).image.pixels)
        ASSERT_EQ(pixel, sky.environment.radiance);
}

// The environment map's importance sampling against uniform hemisphere directions: both
// estimate the same direct lighting, so their images agree in distribution.
TEST(Environment, MapImportanceSamplingAgreesWithHemisphereSampling) {
    test::LoadedTestScene scene;
    scene.scene = loadGltfScene(test::scenePath("test/features/environment.gltf"));
    scene.scene.environment =
        readEnvironmentMap(test::scenePath("test/features/sky.hdr"), glm::vec3(1.0f));
    scene.prepared = prepareScene(scene.scene);
    RenderSettings settings = test::testSettings(16, 64);
    settings.lightSamples = 8;
    test::LightAndHemisphere both = test::renderLightAndHemisphere(scene, settings);
    test::expectSameImage(both.light, both.hemisphere,
                          "environment map: light vs hemisphere sampling");
}

// GGX materials: light sampling alone (evaluateBsdf) and the path tracer at depth 1, whose
// BSDF samples (sampleBsdf's weights and pdfs) carry half of the MIS estimate, agree. (Uniform
// hemisphere directions are no check here: on the near-mirror blocks they find the light so
// rarely that a pixel's own variance estimate cannot be trusted.)
TEST(MetallicRoughness, LightSamplingAndBsdfSamplingAgree) {
    test::LoadedTestScene scene = test::loadTestScene("test/features/ggx.gltf");
    RenderSettings settings = test::testSettings(16, 64);
    settings.integrator = Integrator::Direct;
    settings.lightSamples = 8;
    RenderOutput light = test::renderTestScene(scene, settings);
    RenderSettings path = test::testSettings(16, 256);
    path.maxDepth = 1;
    path.seed = 2;
    test::expectSameImage(test::renderTestScene(scene, path), light, "GGX: path depth 1 vs direct");
}

// An emitting sphere seen directly: exactly its emission inside the silhouette, and the
// camera's central ray, aimed at the centre, hits it.
TEST(Spheres, EmittingSphereIsSeenWithItsRadiance) {
    Scene scene = floorScene(0.5f, 30.0f);
    std::uint32_t light = test::addMaterial(scene, glm::vec3(0.0f), glm::vec3(3.0f, 2.0f, 1.0f));
    scene.spheres.push_back({glm::vec3(0.0f, 0.5f, 0.0f), 0.1f, light});
    RenderSettings settings = test::testSettings(9, 2);
    settings.maxDepth = 0;
    RenderOutput output = test::renderTestScene(prepared(scene), settings);
    EXPECT_EQ(centrePixel(output), glm::vec3(3.0f, 2.0f, 1.0f));
    EXPECT_EQ(output.image.at(0, 0), glm::vec3(0.0f)) << "the corner sees the dark floor";
}

// alphaMode MASK: a screen whose alpha is below the cutoff lets camera and shadow rays
// through; at or above it, it blocks them.
TEST(AlphaMask, MaskedScreenLetsRaysThroughBelowTheCutoff) {
    for (float alpha : {0.2f, 0.8f}) {
        Scene scene = floorScene(0.5f);
        SceneLight point;
        point.position = glm::vec3(0.0f, 0.5f, 0.0f);
        point.intensity = glm::vec3(1.0f);
        scene.lights.push_back(point);
        std::uint32_t screen = test::addMaterial(scene, glm::vec3(0.0f));
        scene.materials[screen].baseColor.a = alpha;
        scene.materials[screen].alphaMode = AlphaMode::Mask;
        scene.materials[screen].doubleSided = true;
        // Between the light and the floor: blocks the light's shadow rays and the camera's view.
        test::addHorizontalGrid(scene, {-1.0f, -1.0f}, {1.0f, 1.0f}, 0.25f, true, 1, screen);
        RenderOutput output = test::renderTestScene(prepared(scene), directOnly(5, 2));
        float open = 0.5f / kPiFloat * 1.0f / 0.25f;
        EXPECT_NEAR(centrePixel(output).x, alpha < 0.5f ? open : 0.0f, 2e-4f * open)
            << "alpha " << alpha;
    }
}

// KHR_materials_unlit (scenes/loader/unlit.gltf): the camera sees only the orange quad, whose
// radiance is its base colour exactly at every depth, since it reflects nothing of what it
// receives (the blue quad 5 behind it lights its back face, which an unlit surface does not
// reflect). 5 × 5 pixels, 2 samples: every sample is the same exact value.
TEST(Unlit, SurfaceShowsItsBaseColourExactly) {
    test::LoadedTestScene scene = test::loadTestScene("loader/unlit.gltf");
    for (std::uint32_t depth : {0u, 16u}) {
        RenderSettings settings = test::testSettings(5, 2);
        settings.maxDepth = depth;
        const RenderOutput output = test::renderTestScene(scene, settings);
        for (const glm::vec3& pixel : output.image.pixels)
            ASSERT_EQ(pixel, glm::vec3(1.0f, 0.25f, 0.0f)) << "max depth " << depth;
    }
}

} // namespace
} // namespace vkpt::scene_model_test
