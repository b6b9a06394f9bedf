// glass_render_test.cpp — glass and volumes against closed forms, one test body run on each
// executor (tests/support/render_executors.h: vkpt-ref, and vkpt on lavapipe): a lossless glass
// ball in a uniform environment shows exactly the environment, and an absorbing slab transmits
// e^(−σ·length) along every camera ray.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../support/render_executors.h"
#include "common/sampler_setup.h"
#include "shared/camera.h"
#include "shared/ray_offset.h"

namespace vkpt::test::glass_render_test {
namespace {

const glm::vec3 kEnvironment(0.5f, 1.0f, 2.0f);

LoadedTestScene loadInUniformEnvironment(const std::string& relative) {
    test::TestSceneOptions options;
    options.environment.radiance = kEnvironment;
    return loadTestScene(relative, options);
}

template <typename Executor> class Glass : public Executor {};
TYPED_TEST_SUITE(Glass, Executors);

// Smooth glass of ior 1.5 (the loader's default) in a uniform environment of radiance L:
// every path that enters the ball leaves it, each crossing weighted (1 − F)/η² in and η²(1 − F')
// out with the reflections between them chosen with probability F (weight 1), so every sample
// is L times a product of factors that are 1 up to float rounding. Russian roulette would
// divide by a survival probability below 1 inside the ball (throughput 1/η²), so it starts at
// the depth limit; 256 scattering events leave a path inside the ball only if it reflected
// 255 times in a row, which even at F = 0.9 has probability 0.9^255 ≈ 2e-12. Every pixel is
// then L within 1e-5 relative (about 80 float ulps).
TYPED_TEST(Glass, LosslessBallShowsExactlyTheUniformEnvironment) {
    LoadedTestScene ball = loadInUniformEnvironment("test/features/glass-ball.gltf");
    RenderSettings settings = testSettings(32, 8);
    settings.maxDepth = 256;
    settings.rrStartDepth = 256;
    const Image image = this->render(ball, settings).image;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(image.pixels[i][c], kEnvironment[c], 1e-5f * kEnvironment[c])
                << "pixel " << i % image.width << ", " << i / image.width;
}

// The slab of scenes/test/features/absorbing-slab.gltf: ior 1 (no refraction, no reflection),
// front face z = 0, back face z = −0.5, |x|, |y| ≤ 1 (wider than the view), attenuation colour
// c after distance 0.25, so σ = −ln(c)/0.25.
constexpr float kSlabThickness = 0.5f;
const glm::vec3 kSlabColour(0.8f, 0.5f, 0.2f);
constexpr float kSlabDistance = 0.25f;
constexpr float kSlabCoordinateScale = 1.0f; // its largest vertex coordinate

// Each camera ray crosses the slab along 0.5/|d.z| and then sees L: the sample is
// L·e^(−σ·0.5/|d.z|), and the pixel the mean of its samples, each recomputed here from the
// shared camera and random numbers. The renderers measure the length between the ray's origin,
// offset 64 float epsilons of the coordinate scale into the slab (shared/ray_offset.h), and
// the back face, so the optical depth differs by at most σ·offset/|d.z|: that, plus 1e-5 for
// exp and the float sums, bounds the relative difference of every pixel.
TYPED_TEST(Glass, AbsorbingSlabTransmitsTheBeerLambertFraction) {
    LoadedTestScene slab = loadInUniformEnvironment("test/features/absorbing-slab.gltf");
    RenderSettings settings = testSettings(16, 4);
    settings.seed = 9;
    const gpu::Camera camera = testCamera(slab, settings);
    glm::dvec3 sigma;
    for (int c = 0; c < 3; ++c)
        sigma[c] = -std::log(double(kSlabColour[c])) / double(kSlabDistance);
    const double offset =
        double(RAY_OFFSET_EPSILONS) * double(FLOAT_EPSILON) * kSlabCoordinateScale;
    const Image image = this->render(slab, settings).image;
    // The camera samples the renderers drew (shared/sampler.h).
    const std::uint32_t setup = samplerSetupFor(settings, settings.width, settings.height);
    for (std::uint32_t y = 0; y < settings.height; ++y)
        for (std::uint32_t x = 0; x < settings.width; ++x) {
            const std::uint32_t pixel = y * settings.width + x;
            glm::dvec3 expected(0.0);
            double smallestCos = 1.0;
            for (std::uint32_t s = 0; s < settings.samplesPerPixel; ++s) {
                glm::vec4 u = gpu::sampleFloats(setup, settings.width, settings.seed, pixel, s, 0,
                                                DIM_CAMERA);
                glm::vec3 d =
                    gpu::cameraRayDirection(camera, glm::vec2(float(x) + u.x, float(y) + u.y));
                const double cosine = std::abs(double(d.z)) / double(glm::length(d));
                smallestCos = std::min(smallestCos, cosine);
                for (int c = 0; c < 3; ++c)
                    expected[c] += double(kEnvironment[c]) *
                                   std::exp(-sigma[c] * double(kSlabThickness) / cosine);
            }
            expected /= double(settings.samplesPerPixel);
            for (int c = 0; c < 3; ++c) {
                const double tolerance = sigma[c] * offset / smallestCos + 1e-5;
                const double value = double(image.at(x, y)[c]);
                EXPECT_NEAR(value / expected[c], 1.0, tolerance)
                    << "pixel " << x << ", " << y << ", channel " << c;
            }
        }
}

} // namespace
} // namespace vkpt::test::glass_render_test
