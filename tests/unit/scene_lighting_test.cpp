// scene_lighting_test.cpp — when a scene counts as unlit and gets the built-in studio
// (prepare/scene_lighting.h), what an emissive texture counts for, and the studio's map against
// its analytic function.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../support/scene_builder.h"
#include "common/math_constants.h"
#include "prepare/environment_map.h"
#include "prepare/scene_lighting.h"
#include "prepare/studio_environment.h"
#include "scene/gltf_loader.h"
#include "shared/environment.h"
#include "shared/sampling.h"

namespace vkpt::scene_lighting_test {
namespace {

using test::addMaterial;
using test::addQuad;

// A 2 × 2 floor of the given material, facing up, at y = 0.
Scene floorScene(glm::vec3 emission = glm::vec3(0.0f)) {
    Scene scene;
    const std::uint32_t material = addMaterial(scene, glm::vec3(0.5f), emission);
    addQuad(scene, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, material);
    return scene;
}

// An emissive texture of side × side texels on the floor's material, uv (0, 0)–(1, 1) across the
// floor; texel (x, y) white where lit(x, y), black elsewhere.
template <typename Lit> void addEmissiveTexture(Scene& scene, std::uint32_t side, Lit lit) {
    SceneImage image;
    image.width = image.height = side;
    for (std::uint32_t y = 0; y < side; ++y)
        for (std::uint32_t x = 0; x < side; ++x)
            image.texels.push_back(lit(x, y) ? 0xffffffffu : 0xff000000u);
    scene.images.push_back(image);
    scene.textures.push_back({0, TextureWrap::Repeat, TextureWrap::Repeat, false});
    scene.materials[0].emissiveTexture.texture = 0;
    scene.materials[0].emission = glm::vec3(1.0f);
    const glm::vec2 corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i : {0, 1, 2, 0, 2, 3})
        scene.texcoords.push_back(corner[i]);
}

TEST(SceneLighting, ASceneWithoutLightsGetsTheStudio) {
    Scene scene = floorScene();
    const LightingDecision decision = applyDefaultLighting(scene, {});
    EXPECT_TRUE(decision.useStudio);
    EXPECT_EQ(decision.measure.emittedPower, 0.0);
    EXPECT_EQ(scene.environment.sourcePath, kStudioName);
    EXPECT_EQ(scene.environment.width, kStudioWidth);
}

TEST(SceneLighting, AnEnvironmentGivenOrTheOptionOffOrNormalsKeepTheSceneAsItIs) {
    for (int i = 0; i < 3; ++i) {
        LightingRequest request;
        request.environmentGiven = i == 0; // --env-color 0 0 0 included
        request.defaultLightAllowed = i != 1;
        request.lightMatters = i != 2;
        Scene scene = floorScene();
        EXPECT_FALSE(applyDefaultLighting(scene, request).useStudio) << "case " << i;
        EXPECT_FALSE(scene.environment.present()) << "case " << i;
    }
}

TEST(SceneLighting, AnyPunctualLightIsLightEnough) {
    Scene scene = floorScene();
    SceneLight light;
    light.intensity = glm::vec3(1e-6f);
    scene.lights.push_back(light);
    const LightingDecision decision = decideSceneLighting(scene, {});
    EXPECT_EQ(decision.measure.punctualLights, 1u);
    EXPECT_FALSE(decision.useStudio);
}

TEST(SceneLighting, AnEmittersPowerIsPiTimesAreaTimesRadiance) {
    // The floor (area 4, one side) at radiance 1 (luminance 1): power 4π, far above the
    // negligible fraction of a studio over a sphere of radius √2.
    const LightingDecision decision = decideSceneLighting(floorScene(glm::vec3(1.0f)), {});
    EXPECT_NEAR(decision.measure.emittedPower, 4.0 * kPi, 1e-9);
    EXPECT_FALSE(decision.useStudio);
    // And a dim one, 10⁻⁶ of that radiance, counts as none.
    EXPECT_TRUE(decideSceneLighting(floorScene(glm::vec3(1e-6f)), {}).useStudio);
}

TEST(SceneLighting, AnEmissiveTextureCountsByWhatItEmitsNotByItsFactor) {
    Scene black = floorScene();
    addEmissiveTexture(black, 64, [](std::uint32_t, std::uint32_t) { return false; });
    const LightingDecision unlit = decideSceneLighting(black, {});
    EXPECT_EQ(unlit.measure.emittedPower, 0.0);
    EXPECT_TRUE(unlit.useStudio);

    // The right half white: half the factor's power, to within the 8 × 8 points' resolution.
    Scene half = floorScene();
    addEmissiveTexture(half, 64, [](std::uint32_t x, std::uint32_t) { return x >= 32; });
    const LightingDecision lit = decideSceneLighting(half, {});
    EXPECT_NEAR(lit.measure.emittedPower, 0.5 * 4.0 * kPi, 0.03 * 4.0 * kPi);
    EXPECT_FALSE(lit.useStudio);
}

TEST(SceneLighting, TheStudioPowerIsTheEnvironmentPowerOverTheBoundingSphere) {
    const Scene scene = floorScene();
    const double radius = std::sqrt(2.0);
    const EnvironmentDistribution studio =
        buildEnvironmentDistribution(makeStudioEnvironment(), radius);
    EXPECT_NEAR(decideSceneLighting(scene, {}).measure.studioPower, studio.power,
                1e-6 * studio.power); // the mean luminance is taken in float
}

TEST(StudioEnvironment, IsGreyAndBrightestAtItsKeyLight) {
    const SceneEnvironment studio = makeStudioEnvironment();
    ASSERT_EQ(studio.texels.size(), std::size_t(kStudioWidth) * kStudioHeight);
    std::size_t brightest = 0;
    for (std::size_t i = 0; i < studio.texels.size(); ++i) {
        const glm::vec3& t = studio.texels[i];
        ASSERT_TRUE(t.r == t.g && t.g == t.b && t.r > 0.0f) << "texel " << i;
        if (t.r > studio.texels[brightest].r) brightest = i;
    }
    const glm::vec2 uv((float(brightest % kStudioWidth) + 0.5f) / kStudioWidth,
                       (float(brightest / kStudioWidth) + 0.5f) / kStudioHeight);
    const glm::vec3 direction = gpu::equirectToDirection(uv);
    EXPECT_GT(glm::dot(direction, studioKeyDirection()), std::cos(12.0 * kPi / 180.0));
    EXPECT_GT(studioRadiance(studioKeyDirection()), 10.0f * studioRadiance({0, 1, 0}));
    EXPECT_GT(studioRadiance({0, 1, 0}), studioRadiance({1, 0, 0}));      // zenith over horizon
    EXPECT_GT(studioRadiance({1, 0.01f, 0}), studioRadiance({0, -1, 0})); // sky over floor
}

TEST(StudioEnvironment, ItsMeanLuminanceConstantIsTheMaps) {
    const EnvironmentDistribution map = buildEnvironmentDistribution(makeStudioEnvironment(), 1.0);
    EXPECT_NEAR(kStudioMeanLuminance, map.averageRadiance.x, 2e-7);
}

// The map's mean radiance (environment_map.h, exact texel solid angles) against a fine
// midpoint quadrature of the analytic function over the sphere.
TEST(StudioEnvironment, TheMapKeepsTheFunctionsMeanRadiance) {
    const EnvironmentDistribution map = buildEnvironmentDistribution(makeStudioEnvironment(), 1.0);
    const int thetaSteps = 2048, phiSteps = 4096;
    double sum = 0.0;
    for (int i = 0; i < thetaSteps; ++i) {
        const double theta = kPi * (i + 0.5) / thetaSteps;
        double row = 0.0;
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = 2.0 * kPi * (j + 0.5) / phiSteps;
            row += studioRadiance(glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                            std::sin(theta) * std::sin(phi)));
        }
        sum += row * std::sin(theta);
    }
    const double mean = sum * (kPi / thetaSteps) * (2.0 * kPi / phiSteps) / (4.0 * kPi);
    EXPECT_NEAR(map.averageRadiance.x, mean, 2e-3 * mean);
}

// The published assets the rule was chosen on (docs/scene-model.md, "Default lighting").
TEST(SceneLighting, SharedScenesAreLitOrNotAsMeasured) {
    const std::string shared = VKPT_SCENES_DIR "/../../shared/scenes/";
    if (!std::filesystem::exists(shared)) GTEST_SKIP() << shared << " is not present";
    const struct {
        const char* path;
        bool studio;
    } cases[] = {{"ToyCar/ToyCar.gltf", true},
                 {"DamagedHelmet/DamagedHelmet.glb", true},
                 {"Box/Box.glb", true},
                 {"EmissiveStrengthTest/EmissiveStrengthTest.glb", false},
                 {"CornellBox/cornellBox.gltf", false},
                 {"TransmissionTest/TransmissionTest.glb", false}};
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    for (const auto& c : cases) {
        const Scene scene = loadGltfScene(shared + c.path, options);
        const LightingDecision decision = decideSceneLighting(scene, {});
        EXPECT_EQ(decision.useStudio, c.studio)
            << c.path << ": " << describeLightingMeasure(decision.measure);
    }
}

} // namespace
} // namespace vkpt::scene_lighting_test
