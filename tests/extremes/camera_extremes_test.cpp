// camera_extremes_test.cpp — cameras and images at their limits, in both renderers: fields of
// view of 0.01° and 179°, 1×1 and 4096×1 images, a camera inside a closed block (an exactly
// black image: no light leaks through the seams where the block meets the floor) and a scene
// without lights (black; the command line says so once, tested in CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>

#include "extremes_support.h"

namespace vkpt::camera_extremes_test {
namespace {

Scene cornellWithCamera(const SceneCamera& camera) {
    Scene scene = test::cornellBoxScene();
    scene.cameras.at(0) = camera;
    return scene;
}

SceneCamera cornellCamera(float yfovDegrees) {
    SceneCamera camera = test::cornellBoxScene().cameras.at(0);
    camera.yfov = glm::radians(yfovDegrees);
    return camera;
}

RenderSettings sized(std::uint32_t width, std::uint32_t height, std::uint32_t spp,
                     std::uint32_t seed = 0) {
    RenderSettings settings = test::testSettings(1, spp);
    settings.width = width;
    settings.height = height;
    settings.seed = seed;
    return settings;
}

void expectFiniteAndAgreeing(const test::BothRenders& r) {
    EXPECT_TRUE(test::outputIsFinite(r.cpu));
    EXPECT_TRUE(test::outputIsFinite(r.gpu));
    EXPECT_EQ(r.cpuStats.nonFiniteSamples + r.gpuStats.nonFiniteSamples, 0u);
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

class CameraExtremes : public test::GpuTest {};

// At 0.01° all 8×8 pixels see the same 0.3 mm of the back wall, whose lighting varies slowly:
// the image's mean equals the mean of a 1° view of the same spot (within noise and 1 %).
TEST_F(CameraExtremes, HundredthOfADegreeSeesWhatANarrowViewSees) {
    test::BothRenders narrow =
        test::renderBoth(context(), test::prepareTestScene(cornellWithCamera(cornellCamera(0.01f))),
                         sized(8, 8, 256, 1));
    expectFiniteAndAgreeing(narrow);
    RenderOutput wider = test::renderTestScene(
        test::prepareTestScene(cornellWithCamera(cornellCamera(1.0f))), sized(8, 8, 256, 2));
    const MeanEstimate expected = meanLuminance(wider);
    for (const RenderOutput* out : {&narrow.cpu, &narrow.gpu}) {
        MeanEstimate mean = meanLuminance(*out);
        EXPECT_NEAR(mean.mean, expected.mean,
                    0.01 * expected.mean +
                        5.0 * std::hypot(mean.standardError, expected.standardError));
    }
}

// 179° from the middle of the room: rays almost sideways (tan 89.5° = 115 on the image plane)
// that meet every wall of the box.
TEST_F(CameraExtremes, HundredSeventyNineDegreesSeesTheWholeRoom) {
    SceneCamera camera =
        test::lookAt(glm::vec3(0.278f, 0.27f, 0.28f), glm::vec3(0.278f, 0.27f, 1.0f),
                     glm::vec3(0.0f, 1.0f, 0.0f), 179.0f);
    test::BothRenders r = test::renderBoth(
        context(), test::prepareTestScene(cornellWithCamera(camera)), sized(32, 32, 16));
    expectFiniteAndAgreeing(r);
    std::size_t black = 0;
    for (const glm::vec3& p : r.cpu.image.pixels)
        black += p == glm::vec3(0.0f);
    EXPECT_LT(black, r.cpu.image.pixels.size() / 10) << "the room surrounds the camera";
}

// One pixel covers the whole view: its expected value is the mean of any image of that view.
TEST_F(CameraExtremes, OnePixelImageIsTheMeanOfTheView) {
    test::LoadedTestScene scene = test::prepareTestScene(test::cornellBoxScene());
    test::BothRenders one = test::renderBoth(context(), scene, sized(1, 1, 4096, 1));
    expectFiniteAndAgreeing(one);
    RenderOutput image = test::renderTestScene(scene, sized(24, 24, 64, 2));
    const MeanEstimate expected = meanLuminance(image);
    for (const RenderOutput* out : {&one.cpu, &one.gpu}) {
        MeanEstimate pixel = meanLuminance(*out);
        EXPECT_NEAR(pixel.mean, expected.mean,
                    5.0 * std::hypot(pixel.standardError, expected.standardError));
    }
}

// 4096×1: the image's width sets the horizontal field of view, here almost 180°.
TEST_F(CameraExtremes, FourThousandNinetySixByOneImage) {
    test::BothRenders r = test::renderBoth(
        context(), test::prepareTestScene(test::cornellBoxScene()), sized(4096, 1, 4));
    expectFiniteAndAgreeing(r);
    EXPECT_EQ(r.cpu.image.pixels.size(), 4096u);
    EXPECT_GT(meanLuminance(r.cpu).mean, 0.0);
}

// Inside the tall block, which stands open-bottomed on the floor: its walls and the floor
// enclose the camera, so not one path may find light. Any leak through the seams shows.
TEST_F(CameraExtremes, CameraInsideAClosedBlockSeesExactlyBlack) {
    // The tall block's top corners are the only vertices between 0.2 and 0.34 high (the short
    // block ends at 0.165, the room's walls at 0 and 0.549); the block spans y = 0 to 0.33.
    Bounds top;
    for (const glm::vec3& p : test::cornellBoxScene().positions)
        if (p.y > 0.2f && p.y < 0.34f) {
            top.min = glm::min(top.min, p);
            top.max = glm::max(top.max, p);
        }
    ASSERT_LT(top.min.x, top.max.x);
    glm::vec3 centre = 0.5f * (top.min + top.max);
    centre.y = 0.5f * top.max.y;
    for (glm::vec3 look : {glm::vec3(0.0f, -1.0f, 0.01f), glm::vec3(1.0f, 0.0f, 0.0f)}) {
        Scene scene = cornellWithCamera(
            test::lookAt(centre, centre + look, glm::vec3(0.0f, 0.0f, 1.0f), 120.0f));
        // The block's faces point out, and a camera ray passes the back of a single-sided
        // surface (docs/scene-model.md, "Sides"): two-sided, the walls stop every ray, so
        // what this checks is the seams.
        for (SceneMaterial& material : scene.materials)
            material.doubleSided = true;
        test::BothRenders r =
            test::renderBoth(context(), test::prepareTestScene(scene), sized(16, 16, 64));
        for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
            std::size_t lit = 0;
            for (const glm::vec3& p : out->image.pixels)
                lit += p != glm::vec3(0.0f);
            EXPECT_EQ(lit, 0u) << (out == &r.cpu ? "vkpt-ref" : "vkpt");
        }
    }
}

TEST_F(CameraExtremes, SceneWithoutLightsIsBlack) {
    test::LoadedTestScene scene = test::loadTestScene("test/no-lights.gltf");
    ASSERT_TRUE(scene.prepared.emitters.empty());
    test::BothRenders r = test::renderBoth(context(), scene, sized(16, 16, 8));
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        EXPECT_TRUE(test::outputIsFinite(*out));
        for (const glm::vec3& p : out->image.pixels)
            EXPECT_EQ(p, glm::vec3(0.0f));
    }
}

} // namespace
} // namespace vkpt::camera_extremes_test
