// direct_lighting_test.cpp — vkpt-ref's direct lighting: light and hemisphere sampling agree
// under a textured emitter, and more light samples reduce the variance. The comparisons of
// independent estimators that hold for either executor are in executor_render_test.cpp.
#include <gtest/gtest.h>

#include "../image/feature_scenes.h"
#include "../support/reference_render.h"
#include "../support/render_checks.h"
#include "image/image_compare.h"

namespace vkpt::direct_lighting_test {
namespace {

// A 3 × 3 ceiling light over the floor whose emissive texture is lit on about half of it, in
// a pattern that changes along both texture axes, and a small plain light on the wall: light
// sampling must read the texture at the point it samples on the ceiling exactly as a
// hemisphere direction that hits it does, and choose between two emitters by the CDF.
Scene halfLitCeilingScene() {
    namespace fs = test::feature_scenes;
    Scene scene = fs::cornerWithMaterials();
    const int halfLit = fs::addTexture(
        scene, 8, 8,
        [](std::uint32_t x, std::uint32_t y) {
            return (x < 4) != (y < 3) ? glm::uvec4(255, 230, 200, 255) : glm::uvec4(0, 0, 0, 255);
        },
        true);
    const std::uint32_t ceiling = fs::addMaterial(scene, {glm::vec3(0.0f), glm::vec3(1.5f)});
    scene.materials[ceiling].emissiveTexture.texture = halfLit;
    const std::uint32_t lamp = fs::addMaterial(scene, {glm::vec3(0.0f), glm::vec3(4.0f)});
    // Faces down, above every wall point the camera sees and half a unit from the wall, so
    // that hemisphere sampling finds the lit half from every visible point often enough for
    // the per-pixel variances to be trusted (a grazing view of it leaves pixels with a
    // handful of hits and an underestimated variance).
    fs::addQuad(scene, {-1.5f, 3.5f, -1.5f}, {1.5f, 3.5f, -1.5f}, {1.5f, 3.5f, 1.5f},
                {-1.5f, 3.5f, 1.5f}, ceiling);
    fs::addQuad(scene, {-1.6f, 0.4f, -1.99f}, {-1.0f, 0.4f, -1.99f}, {-1.0f, 1.0f, -1.99f},
                {-1.6f, 1.0f, -1.99f}, lamp);
    return scene;
}

TEST(DirectLighting, TexturedEmittersLightAndHemisphereSamplingAgree) {
    test::LoadedTestScene scene = test::feature_scenes::prepareTestScene(halfLitCeilingScene());
    ASSERT_EQ(scene.prepared.emitters.size(), 4u);
    RenderSettings settings = test::testSettings(16, 128);
    settings.lightSamples = 16;
    test::LightAndHemisphere both = test::renderLightAndHemisphere(scene, settings);
    test::expectSameImage(both.light, both.hemisphere,
                          "light vs hemisphere sampling, textured emitter");
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
} // namespace vkpt::direct_lighting_test
