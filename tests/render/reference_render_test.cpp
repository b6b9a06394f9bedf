// reference_render_test.cpp — what holds of vkpt-ref alone: the same image on any number of
// threads. What holds for either executor is tested once for both in executor_render_test.cpp.
#include <gtest/gtest.h>

#include "../support/reference_render.h"

namespace vkpt::reference_render_test {
namespace {

TEST(ReferenceRender, SameSeedGivesTheSameImageOnOneAndTwoThreads) {
    test::LoadedTestScene box = test::loadTestScene("cornell-box.gltf");
    RenderSettings settings = test::testSettings(24, 4);
    settings.seed = 11;
    settings.threads = 1;
    RenderOutput one = test::renderTestScene(box, settings);
    settings.threads = 2;
    RenderOutput two = test::renderTestScene(box, settings);
    ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
    for (std::size_t i = 0; i < one.image.pixels.size(); ++i)
        ASSERT_EQ(one.image.pixels[i], two.image.pixels[i]) << "pixel " << i;
    settings.seed = 12;
    RenderOutput other = test::renderTestScene(box, settings);
    EXPECT_NE(one.image.pixels, other.image.pixels) << "a new seed must give new noise";
}

} // namespace
} // namespace vkpt::reference_render_test
