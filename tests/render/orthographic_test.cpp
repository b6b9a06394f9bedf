// orthographic_test.cpp — orthographic cameras (vkpt-ref): a parallel projection shows a
// unit square facing the camera as exactly the pixels its world extent covers at
// ymag / (height / 2) world units per pixel, whatever its distance, with the image's aspect
// setting the horizontal extent (docs/conventions.md).
#include <gtest/gtest.h>

#include <string>

#include "../support/reference_render.h"
#include "../support/scene_builder.h"

namespace vkpt::orthographic_test {
namespace {

// An emitting unit square centred on the axis at depth `z`, facing +Z, seen by an orthographic
// camera at z = 5 looking down −Z with ymag 1.
test::LoadedTestScene squareScene(float z) {
    Scene scene;
    scene.sourcePath = "orthographic square";
    const std::uint32_t light = test::addMaterial(scene, glm::vec3(0.0f), glm::vec3(1.0f));
    test::addQuad(scene, {-0.5f, -0.5f, z}, {0.5f, -0.5f, z}, {0.5f, 0.5f, z}, {-0.5f, 0.5f, z},
                  light);
    SceneCamera camera;
    camera.position = {0, 0, 5};
    camera.projection = CameraProjection::Orthographic;
    camera.ymag = 1.0f;
    camera.xmag = 1.0f;
    scene.cameras.push_back(camera);
    test::LoadedTestScene loaded{std::move(scene), {}};
    loaded.prepared = prepareScene(loaded.scene);
    return loaded;
}

RenderOutput renderSquare(float z, std::uint32_t width, std::uint32_t height) {
    RenderSettings settings = test::testSettings(height, 16);
    settings.width = width;
    settings.maxDepth = 0; // the emitter alone: a pixel's value is the square's coverage
    return test::renderTestScene(squareScene(z), settings);
}

// The square spans [-0.5, 0.5]² in world units: with the half-height of 1 over height / 2
// pixels, that is the central height / 2 rows and as many columns, edges on pixel boundaries,
// so every pixel is fully covered (1) or not at all (0).
void expectSquareCoverage(const RenderOutput& output, std::uint32_t width, std::uint32_t height,
                          const std::string& what) {
    const std::uint32_t side = height / 2;
    const std::uint32_t x0 = (width - side) / 2;
    const std::uint32_t y0 = (height - side) / 2;
    std::size_t wrong = 0;
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const bool inside = x >= x0 && x < x0 + side && y >= y0 && y < y0 + side;
            const float value = output.image.pixels[std::size_t(y) * width + x].x;
            if (std::abs(value - (inside ? 1.0f : 0.0f)) > 1e-6f) ++wrong;
        }
    EXPECT_EQ(wrong, 0u) << what << ": pixels whose coverage is not the square's";
}

TEST(OrthographicCamera, ASquareCoversExactlyItsExtentAtAnyDistance) {
    for (float z : {0.0f, -3.0f, 4.5f})
        expectSquareCoverage(renderSquare(z, 64, 64), 64, 64, "z = " + std::to_string(z));
}

TEST(OrthographicCamera, TheImagesAspectSetsTheHorizontalExtent) {
    // 96 × 64: the view is 3 × 2 world units, so the square is still 32 pixels wide.
    expectSquareCoverage(renderSquare(0.0f, 96, 64), 96, 64, "96 x 64");
}

} // namespace
} // namespace vkpt::orthographic_test
