// scale_and_distance_test.cpp — the Cornell box scaled from 1e-4 to 1e4 and moved up to 1e6
// from the origin renders the same image within noise in vkpt-ref (per-pixel Welch test,
// family alpha 0.01, against the box at scale 1 rendered with another seed).
#include <gtest/gtest.h>

#include <cmath>

#include "../support/reference_render.h"
#include "../support/scene_transforms.h"
#include "image/image_compare.h"

namespace vkpt {
namespace {

RenderOutput render(const Scene& scene, std::uint32_t seed) {
    test::LoadedTestScene loaded{scene, prepareScene(scene, {{}, scene.cameras.at(0).forward})};
    RenderSettings settings = test::testSettings(24, 64);
    settings.seed = seed;
    return test::renderTestScene(loaded, settings);
}

const Scene& cornellBox() {
    static const Scene scene = test::loadTestScene("cornell-box.gltf").scene;
    return scene;
}

const RenderOutput& unitScaleImage() {
    static const RenderOutput image = render(cornellBox(), 1);
    return image;
}

bool allFinite(const Image& image) {
    for (const glm::vec3& p : image.pixels)
        if (!std::isfinite(p.x + p.y + p.z)) return false;
    return true;
}

class Scale : public ::testing::TestWithParam<float> {};

TEST_P(Scale, ScaledCornellBoxRendersTheSameImage) {
    RenderOutput scaled = render(test::scaledScene(cornellBox(), GetParam()), 2);
    ASSERT_TRUE(allFinite(scaled.image));
    ZTestResult z = zTestPerPixel(scaled, unitScaleImage(), 0.01);
    EXPECT_TRUE(z.passed) << "scale " << GetParam() << ": " << z.summary;
}

INSTANTIATE_TEST_SUITE_P(FromMicroToKilo, Scale,
                         ::testing::Values(1e-4f, 1e-2f, 1e2f, 1e4f, 1e-8f, 1e8f));

class Distance : public ::testing::TestWithParam<float> {};

TEST_P(Distance, TranslatedCornellBoxRendersTheSameImage) {
    float d = GetParam();
    RenderOutput moved = render(test::translatedScene(cornellBox(), glm::vec3(d, -d, d)), 2);
    ASSERT_TRUE(allFinite(moved.image));
    ZTestResult z = zTestPerPixel(moved, unitScaleImage(), 0.01);
    EXPECT_TRUE(z.passed) << "distance " << d << ": " << z.summary;
}

INSTANTIATE_TEST_SUITE_P(UpToAMillion, Distance, ::testing::Values(1e3f, 1e4f, 1e5f, 1e6f));

} // namespace
} // namespace vkpt
