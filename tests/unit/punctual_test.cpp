// punctual_test.cpp — KHR_lights_punctual lights of shared/punctual.h: the inverse square law,
// the range window, the spot cone falloff and directional lights.
#include <cmath>

#include <gtest/gtest.h>

#include "shared/punctual.h"

namespace vkpt::punctual_test {
namespace {

using glm::vec3;

gpu::Emitter pointLight(vec3 position, vec3 intensity, float range = 0.0f) {
    gpu::Emitter e{};
    e.kind = EMITTER_POINT;
    e.position = position;
    e.intensity = intensity;
    e.range = range;
    return e;
}

// A spot at the origin shining down −Y with cones of cos 0.9 (inner) and 0.7 (outer).
gpu::Emitter spotLight() {
    gpu::Emitter e = pointLight(vec3(0.0f), vec3(100.0f));
    e.kind = EMITTER_SPOT;
    e.direction = vec3(0.0f, -1.0f, 0.0f);
    e.cosInnerCone = 0.9f;
    e.cosOuterCone = 0.7f;
    return e;
}

// A receiver at distance 10 from the origin whose direction from the spot axis has cosine c.
vec3 receiverAtCosine(float c) {
    return 10.0f * vec3(std::sqrt(1.0f - c * c), -c, 0.0f);
}

TEST(PunctualLight, PointFollowsTheInverseSquareLaw) {
    gpu::Emitter light = pointLight(vec3(1.0f, 2.0f, 3.0f), vec3(4.0f, 8.0f, 12.0f));
    for (float d : {0.5f, 2.0f, 10.0f, 1e4f}) {
        gpu::PunctualIncidence in =
            gpu::punctualIncidence(light, light.position - vec3(0.0f, 0.0f, d));
        ASSERT_TRUE(in.valid);
        EXPECT_FLOAT_EQ(in.distance, d);
        EXPECT_NEAR(in.direction.z, 1.0f, 1e-6f);
        EXPECT_NEAR(glm::length(in.direction), 1.0f, 1e-6f);
        EXPECT_FLOAT_EQ(in.irradiance.x, 4.0f / (d * d));
        EXPECT_FLOAT_EQ(in.irradiance.z, 12.0f / (d * d));
    }
}

// The extension's window clamp(1 − (d/range)⁴, 0, 1) / d².
TEST(PunctualLight, RangeWindowsTheInverseSquareLaw) {
    gpu::Emitter light = pointLight(vec3(0.0f), vec3(1.0f), 10.0f);
    auto irradianceAt = [&](float d) {
        return gpu::punctualIncidence(light, vec3(d, 0.0f, 0.0f)).irradiance.x;
    };
    EXPECT_NEAR(irradianceAt(1e-2f) * 1e-4f, 1.0f, 1e-6f);         // near the light: ≈ 1/d²
    EXPECT_FLOAT_EQ(irradianceAt(5.0f), (1.0f - 0.0625f) / 25.0f); // half range: 1 − 1/16
    EXPECT_EQ(irradianceAt(10.0f), 0.0f);                          // at range
    EXPECT_EQ(irradianceAt(12.0f), 0.0f);                          // beyond
    EXPECT_FALSE(gpu::punctualIncidence(light, vec3(12.0f, 0.0f, 0.0f)).valid);
    EXPECT_FALSE(gpu::punctualIncidence(light, vec3(10.0f, 0.0f, 0.0f)).valid);
    light.range = 0.0f; // unlimited
    EXPECT_FLOAT_EQ(irradianceAt(12.0f), 1.0f / 144.0f);
    EXPECT_EQ(gpu::punctualRangeWindow(3.0f, 0.0f), 1.0f);
}

// The extension's reference falloff: ((cos − cos outer)/(cos inner − cos outer))², clamped.
TEST(PunctualLight, SpotFallsOffBetweenItsCones) {
    gpu::Emitter light = spotLight();
    auto irradianceAt = [&](float c) {
        return gpu::punctualIncidence(light, receiverAtCosine(c)).irradiance.x;
    };
    EXPECT_FLOAT_EQ(irradianceAt(1.0f), 1.0f);     // on the axis: 100 / 10²
    EXPECT_FLOAT_EQ(irradianceAt(0.95f), 1.0f);    // inside the inner cone
    EXPECT_NEAR(irradianceAt(0.8f), 0.25f, 1e-5f); // half way in cosine: (1/2)²
    EXPECT_NEAR(irradianceAt(0.75f), 0.0625f, 1e-5f);
    EXPECT_NEAR(irradianceAt(0.7f), 0.0f, 1e-5f); // at the outer cone
    EXPECT_EQ(irradianceAt(0.5f), 0.0f);          // outside
    EXPECT_FALSE(gpu::punctualIncidence(light, receiverAtCosine(0.5f)).valid);
    EXPECT_FALSE(gpu::punctualIncidence(light, vec3(0.0f, 5.0f, 0.0f)).valid); // behind
    gpu::PunctualIncidence in = gpu::punctualIncidence(light, receiverAtCosine(0.8f));
    EXPECT_TRUE(in.valid);
    EXPECT_FLOAT_EQ(in.distance, 10.0f);
    EXPECT_NEAR(glm::dot(in.direction, -glm::normalize(receiverAtCosine(0.8f))), 1.0f, 1e-6f);
}

TEST(PunctualLight, SpotWithEqualConesIsAHardEdgedCone) {
    gpu::Emitter light = spotLight();
    light.cosInnerCone = 0.8f;
    light.cosOuterCone = 0.8f; // the 0.001 floor keeps the division finite
    EXPECT_FLOAT_EQ(gpu::punctualIncidence(light, receiverAtCosine(0.85f)).irradiance.x, 1.0f);
    EXPECT_EQ(gpu::punctualIncidence(light, receiverAtCosine(0.75f)).irradiance.x, 0.0f);
}

TEST(PunctualLight, DirectionalDeliversItsIlluminanceEverywhere) {
    gpu::Emitter light{};
    light.kind = EMITTER_DIRECTIONAL;
    light.direction = glm::normalize(vec3(1.0f, -2.0f, 0.5f));
    light.intensity = vec3(3.0f, 2.0f, 1.0f);
    for (vec3 receiver : {vec3(0.0f), vec3(1e6f, -3.0f, 7.0f)}) {
        gpu::PunctualIncidence in = gpu::punctualIncidence(light, receiver);
        ASSERT_TRUE(in.valid);
        EXPECT_EQ(in.direction, -light.direction);
        EXPECT_EQ(in.distance, VKPT_FAR);
        EXPECT_EQ(in.irradiance, light.intensity);
    }
}

TEST(PunctualLight, ReceiverAtTheLightOrOtherKindsAreInvalid) {
    gpu::Emitter light = pointLight(vec3(1.0f), vec3(1.0f));
    gpu::PunctualIncidence in = gpu::punctualIncidence(light, vec3(1.0f));
    EXPECT_FALSE(in.valid);
    EXPECT_EQ(in.irradiance, vec3(0.0f));
    EXPECT_TRUE(std::isfinite(in.direction.x) && std::isfinite(in.distance));
    for (std::uint32_t kind : {EMITTER_TRIANGLE, EMITTER_SPHERE, EMITTER_ENVIRONMENT}) {
        light.kind = kind;
        EXPECT_FALSE(gpu::punctualIncidence(light, vec3(0.0f)).valid);
    }
}

} // namespace
} // namespace vkpt::punctual_test
