// radiance_range_test.cpp — emitted radiance from 1e-6 to 1e6 changes the image's scale and
// nothing else; a light 1e-4 the area of the Cornell light with the same power lights the room
// alike; emission at the top of the float range makes samples overflow, and both renderers
// discard and count those instead of poisoning pixels; --clamp limits every sample. Each case in
// vkpt-ref and vkpt.
#include <gtest/gtest.h>

#include <cfloat>
#include <cstdio>

#include "extremes_support.h"
#include "shared/sample_guard.h"
#include "shared/sampling.h"

namespace vkpt::radiance_range_test {
namespace {

RenderSettings settingsWithSeed(std::uint32_t seed, std::uint32_t spp = 64) {
    RenderSettings settings = test::testSettings(24, spp);
    settings.seed = seed;
    return settings;
}

const RenderOutput& cornellImage() {
    static const RenderOutput image =
        test::renderTestScene(test::prepareTestScene(test::cornellBoxScene()), settingsWithSeed(1));
    return image;
}

Scene withEmissionScaled(Scene scene, float factor) {
    for (SceneMaterial& m : scene.materials)
        m.emission *= factor;
    return scene;
}

// The render divided by `factor`, with its per-pixel statistics (M2 by factor²).
RenderOutput divided(RenderOutput output, double factor) {
    for (std::size_t i = 0; i < output.image.pixels.size(); ++i) {
        output.image.pixels[i] = glm::vec3(glm::dvec3(output.image.pixels[i]) / factor);
        output.luminanceMean[i] = float(double(output.luminanceMean[i]) / factor);
        output.luminanceM2[i] = float(double(output.luminanceM2[i]) / (factor * factor));
    }
    return output;
}

// ---------------------------------------------------------------------------------------------

class EmitterRange : public test::GpuTest, public ::testing::WithParamInterface<float> {};

TEST_P(EmitterRange, ImageScalesWithTheEmission) {
    const float k = GetParam();
    Scene scene = withEmissionScaled(test::cornellBoxScene(), k);
    test::BothRenders r =
        test::renderBoth(context(), test::prepareTestScene(scene), settingsWithSeed(2));
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        const char* who = out == &r.cpu ? "vkpt-ref" : "vkpt";
        EXPECT_TRUE(test::outputIsFinite(*out)) << who;
        EXPECT_TRUE(test::sameWithinNoise(divided(*out, double(k)), cornellImage(),
                                          std::string(who) + ", emission x" + std::to_string(k)));
    }
    EXPECT_EQ(r.cpuStats.nonFiniteSamples + r.gpuStats.nonFiniteSamples, 0u);
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

INSTANTIATE_TEST_SUITE_P(MicroToMega, EmitterRange, ::testing::Values(1e-6f, 1e-3f, 1e3f, 1e6f));

// ---------------------------------------------------------------------------------------------
// The Cornell light shrunk about its centre to 1 % of its width and depth (1e-4 of its area),
// 10^4 times as bright: the same power. Seen from inside the box looking down at the floor (not
// at the light itself, whose direct view is a needle in a haystack at 64 samples), the room is
// lit as by the light shrunk to 10 % (10^2 times as bright) within 1 %: both are points as far
// as the room is concerned. The full-size light differs from both by its near field (the tall
// block's top is 22 cm below the 13 cm light): 5 % in this view, measured.

Scene withShrunkLight(Scene scene, double shrink) {
    glm::dvec3 centre(0.0);
    std::size_t count = 0;
    for (std::size_t t = 0; t < scene.triangleCount(); ++t)
        if (scene.materials[scene.materialIndices[t]].emission != glm::vec3(0.0f))
            for (int k = 0; k < 3; ++k, ++count)
                centre += glm::dvec3(scene.positions[3 * t + k]);
    centre /= double(count);
    for (std::size_t t = 0; t < scene.triangleCount(); ++t)
        if (scene.materials[scene.materialIndices[t]].emission != glm::vec3(0.0f))
            for (int k = 0; k < 3; ++k) {
                glm::vec3& p = scene.positions[3 * t + k];
                p = glm::vec3(centre + shrink * (glm::dvec3(p) - centre));
            }
    for (SceneMaterial& m : scene.materials)
        m.emission *= float(1.0 / (shrink * shrink));
    return scene;
}

Scene withTinyLight(Scene scene) {
    return withShrunkLight(std::move(scene), 0.01);
}

Scene lookingAtTheFloor(Scene scene) {
    scene.cameras[0] = test::lookAt(glm::vec3(0.278f, 0.45f, 0.28f), glm::vec3(0.278f, 0.0f, 0.28f),
                                    glm::vec3(0.0f, 0.0f, 1.0f), 70.0f);
    return scene;
}

class TinyLight : public test::GpuTest {};

TEST_F(TinyLight, SamePowerLightsTheRoomAlike) {
    RenderSettings settings = settingsWithSeed(3);
    test::LoadedTestScene small =
        test::prepareTestScene(lookingAtTheFloor(withShrunkLight(test::cornellBoxScene(), 0.1)));
    test::LoadedTestScene tiny =
        test::prepareTestScene(lookingAtTheFloor(withTinyLight(test::cornellBoxScene())));
    ASSERT_NEAR(tiny.prepared.totalEmittedPower, small.prepared.totalEmittedPower,
                1e-3 * small.prepared.totalEmittedPower);
    RenderOutput reference = test::renderTestScene(small, settings);
    test::BothRenders r = test::renderBoth(context(), tiny, settings);
    const MeanEstimate expected = meanLuminance(reference);
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        EXPECT_TRUE(test::outputIsFinite(*out));
        MeanEstimate mean = meanLuminance(*out);
        EXPECT_NEAR(mean.mean, expected.mean,
                    0.01 * expected.mean +
                        5.0 * std::hypot(mean.standardError, expected.standardError))
            << (out == &r.cpu ? "vkpt-ref" : "vkpt");
    }
    EXPECT_EQ(r.cpuStats.nonFiniteSamples + r.gpuStats.nonFiniteSamples, 0u);
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

// Seen directly, the tiny light's samples carry 1.7e5: finite, accumulated, nothing discarded.
TEST_F(TinyLight, SeenDirectlyEveryOutputStaysFinite) {
    test::LoadedTestScene tiny = test::prepareTestScene(withTinyLight(test::cornellBoxScene()));
    test::BothRenders r = test::renderBoth(context(), tiny, settingsWithSeed(3, 16));
    EXPECT_TRUE(test::outputIsFinite(r.cpu));
    EXPECT_TRUE(test::outputIsFinite(r.gpu));
    EXPECT_EQ(r.cpuStats.nonFiniteSamples + r.gpuStats.nonFiniteSamples, 0u);
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

// ---------------------------------------------------------------------------------------------
// Emission of 3.3e38, just under the largest float, 3.4e38 (the loader accepts it: it is
// finite).

Scene withHugeEmission() {
    Scene scene = test::cornellBoxScene();
    for (SceneMaterial& m : scene.materials)
        if (m.emission != glm::vec3(0.0f)) m.emission = glm::vec3(3.3e38f);
    return scene;
}

class NonFiniteSamples : public test::GpuTest {};

// Seen directly (depth 0) every sample is finite: the pixels that see the light average 64
// samples of 3.3e38 to 3.3e38, a sum the device keeps in range by scaling it
// (ACCUMULATION_SCALE).
TEST_F(NonFiniteSamples, LargestFiniteSamplesAverageWithoutOverflow) {
    RenderSettings settings = settingsWithSeed(4);
    settings.maxDepth = 0;
    test::BothRenders r =
        test::renderBoth(context(), test::prepareTestScene(withHugeEmission()), settings);
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        EXPECT_TRUE(test::outputIsFinite(*out));
        std::uint32_t lightPixels = 0;
        for (const glm::vec3& p : out->image.pixels)
            lightPixels += p.x > 1e38f;
        EXPECT_GT(lightPixels, 0u) << "the light is in view";
    }
    EXPECT_EQ(r.cpuStats.nonFiniteSamples + r.gpuStats.nonFiniteSamples, 0u);
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
}

// With more bounces, a path that sees the light adds light samples to its 3.3e38 and overflows
// to infinity: those samples are discarded and counted by both renderers, and no pixel turns
// NaN or infinite.
TEST_F(NonFiniteSamples, OverflowingSamplesAreDiscardedAndCounted) {
    test::BothRenders r = test::renderBoth(context(), test::prepareTestScene(withHugeEmission()),
                                           settingsWithSeed(4, 16));
    EXPECT_TRUE(test::outputIsFinite(r.cpu));
    EXPECT_TRUE(test::outputIsFinite(r.gpu));
    EXPECT_GT(r.cpuStats.nonFiniteSamples, 0u);
    EXPECT_GT(r.gpuStats.nonFiniteSamples, 0u);
    // The same paths overflow on both, up to a path or two that rounds across the edge.
    EXPECT_NEAR(double(r.gpuStats.nonFiniteSamples), double(r.cpuStats.nonFiniteSamples),
                0.01 * double(r.cpuStats.nonFiniteSamples) + 2.0);
    std::printf("non-finite samples discarded: vkpt-ref %llu, vkpt %llu of %llu\n",
                (unsigned long long)r.cpuStats.nonFiniteSamples,
                (unsigned long long)r.gpuStats.nonFiniteSamples,
                (unsigned long long)r.cpuStats.samplesTaken);
}

// ---------------------------------------------------------------------------------------------
// --clamp X: each sample's largest component is limited to X before it is accumulated.

class Clamp : public test::GpuTest {};

TEST_F(Clamp, NoPixelExceedsTheLimitAndTheImageLosesEnergy) {
    RenderSettings settings = settingsWithSeed(5);
    settings.clamp = 1.0f;
    test::LoadedTestScene scene = test::prepareTestScene(test::cornellBoxScene());
    test::BothRenders r = test::renderBoth(context(), scene, settings);
    for (const RenderOutput* out : {&r.cpu, &r.gpu}) {
        EXPECT_TRUE(test::outputIsFinite(*out));
        float brightest = 0.0f;
        for (const glm::vec3& p : out->image.pixels)
            brightest = std::max(brightest, std::max(p.x, std::max(p.y, p.z)));
        EXPECT_LE(brightest, 1.0f + 1e-6f);
    }
    EXPECT_TRUE(test::devicesAgree(r.gpu, r.cpu));
    // Biased: the light (radiance 17) and its fireflies lose energy.
    EXPECT_LT(meanLuminance(r.cpu).mean, 0.5 * meanLuminance(cornellImage()).mean);
}

TEST_F(Clamp, IsOffByDefault) {
    EXPECT_EQ(RenderSettings{}.clamp, SAMPLE_CLAMP_OFF);
    EXPECT_EQ(gpu::clampSample(glm::vec3(1e30f, 2.0f, 0.0f), SAMPLE_CLAMP_OFF),
              glm::vec3(1e30f, 2.0f, 0.0f));
    EXPECT_EQ(gpu::clampSample(glm::vec3(4.0f, 2.0f, 1.0f), 2.0f), glm::vec3(2.0f, 1.0f, 0.5f));
}

} // namespace
} // namespace vkpt::radiance_range_test
