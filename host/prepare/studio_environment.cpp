// studio_environment.cpp — the built-in studio: a sky gradient, a floor, a soft key light.
#include "prepare/studio_environment.h"

#include <algorithm>
#include <cmath>

#include "common/math_constants.h"
#include "shared/environment.h"

namespace vkpt {

namespace {

constexpr float kHorizonRadiance = 0.6f;
constexpr float kZenithRadiance = 1.0f;
constexpr float kFloorRadiance = 0.25f;
constexpr float kHorizonHalfWidth = 2.0f * kPiFloat / 180.0f; // the floor–sky blend, ± this
constexpr float kKeyRadiance = 16.0f;
constexpr float kKeyRadius = 12.0f * kPiFloat / 180.0f;
constexpr float kKeyEdge =
    4.0f * kPiFloat / 180.0f; // the key fades out over this, centred on its rim
constexpr float kKeyElevation = 50.0f * kPiFloat / 180.0f;
constexpr int kSamplesPerSide = 4; // per texel, per axis

float smoothStep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// The sky above the horizon, the floor below, blended across a band of elevations.
float backgroundRadiance(float elevation) {
    const float sky = kHorizonRadiance +
                      (kZenithRadiance - kHorizonRadiance) * std::max(std::sin(elevation), 0.0f);
    const float skyWeight = smoothStep(-kHorizonHalfWidth, kHorizonHalfWidth, elevation);
    return kFloorRadiance + (sky - kFloorRadiance) * skyWeight;
}

float keyRadiance(const glm::vec3& d) {
    const float cosAngle = std::clamp(glm::dot(d, studioKeyDirection()), -1.0f, 1.0f);
    const float angle = std::acos(cosAngle);
    return kKeyRadiance *
           (1.0f - smoothStep(kKeyRadius - 0.5f * kKeyEdge, kKeyRadius + 0.5f * kKeyEdge, angle));
}

} // namespace

glm::vec3 studioKeyDirection() {
    // Azimuth halfway between −X and +Z.
    const float horizontal = std::cos(kKeyElevation);
    return {-horizontal * std::sqrt(0.5f), std::sin(kKeyElevation), horizontal * std::sqrt(0.5f)};
}

float studioRadiance(const glm::vec3& d) {
    const float elevation = std::asin(std::clamp(d.y, -1.0f, 1.0f));
    return backgroundRadiance(elevation) + keyRadiance(d);
}

SceneEnvironment makeStudioEnvironment() {
    SceneEnvironment environment;
    environment.radiance = glm::vec3(1.0f);
    environment.width = kStudioWidth;
    environment.height = kStudioHeight;
    environment.sourcePath = kStudioName;
    environment.texels.resize(std::size_t(kStudioWidth) * kStudioHeight);
    const float step = 1.0f / float(kSamplesPerSide);
    for (std::uint32_t row = 0; row < kStudioHeight; ++row)
        for (std::uint32_t column = 0; column < kStudioWidth; ++column) {
            float sum = 0.0f;
            for (int j = 0; j < kSamplesPerSide; ++j)
                for (int i = 0; i < kSamplesPerSide; ++i) {
                    const glm::vec2 uv((float(column) + (float(i) + 0.5f) * step) / kStudioWidth,
                                       (float(row) + (float(j) + 0.5f) * step) / kStudioHeight);
                    sum += studioRadiance(gpu::equirectToDirection(uv));
                }
            const float mean = sum / float(kSamplesPerSide * kSamplesPerSide);
            environment.texels[std::size_t(row) * kStudioWidth + column] = glm::vec3(mean);
        }
    return environment;
}

} // namespace vkpt
