// extremes_support.h — what the numerical-extremes tests share: scenes built in memory (quads,
// boxes, cameras), both renderers on the same scene and settings, and the checks every extreme
// case makes: nothing non-finite in the output, and the device agreeing with the reference.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../image/wavefront_test_support.h"
#include "../support/scene_builder.h"
#include "image/image_compare.h"
#include "scene/camera.h"

namespace vkpt::test {

// Scenes in memory: tests/support/scene_builder.h.

inline SceneCamera lookAt(glm::vec3 position, glm::vec3 target, glm::vec3 up, float yfovDegrees) {
    SceneCamera camera;
    camera.name = "test camera";
    camera.position = position;
    camera.forward = glm::normalize(target - position);
    camera.up = glm::normalize(up - glm::dot(up, camera.forward) * camera.forward);
    camera.yfov = glm::radians(yfovDegrees);
    return camera;
}

// The scene with its BVH flattened for its first camera, as vkpt and vkpt-ref prepare it.
inline LoadedTestScene prepareTestScene(const Scene& scene) {
    return {scene, prepareScene(scene)};
}

inline const Scene& cornellBoxScene() {
    static const Scene scene = loadTestScene("cornell-box.gltf").scene;
    return scene;
}

// ---------------------------------------------------------------------------------------------
// Checks

// No NaN or infinity in the image or in the statistics a render reports per pixel, and the
// Welford M2 never negative.
inline ::testing::AssertionResult outputIsFinite(const RenderOutput& output) {
    for (std::size_t i = 0; i < output.image.pixels.size(); ++i) {
        const glm::vec3& p = output.image.pixels[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return ::testing::AssertionFailure() << "pixel " << i << " is not finite";
        if (!std::isfinite(output.luminanceMean[i]) || !std::isfinite(output.luminanceM2[i]))
            return ::testing::AssertionFailure() << "pixel " << i << ": a statistic is not finite";
        if (output.luminanceM2[i] < 0.0f)
            return ::testing::AssertionFailure() << "pixel " << i << ": M2 is negative";
    }
    return ::testing::AssertionSuccess();
}

// The device's render at the reference's seed agrees pixel by pixel (docs/wavefront.md's bound).
inline ::testing::AssertionResult devicesAgree(const RenderOutput& gpu, const RenderOutput& cpu) {
    SameSeedAgreement agreement = compareSameSeed(gpu, cpu);
    if (agreement.fraction() >= 0.99) return ::testing::AssertionSuccess() << agreement.summary();
    return ::testing::AssertionFailure() << agreement.summary();
}

inline ::testing::AssertionResult sameWithinNoise(const RenderOutput& a, const RenderOutput& b,
                                                  const std::string& what) {
    ZTestResult z = zTestPerPixel(a, b, 0.01);
    if (z.passed) return ::testing::AssertionSuccess() << what << ": " << z.summary;
    return ::testing::AssertionFailure() << what << ": " << z.summary;
}

// Both renderers on one scene: the reference, then the device at the same settings.
struct BothRenders {
    RenderOutput cpu;
    RenderOutput gpu;
    RenderStats cpuStats;
    RenderStats gpuStats;
};

inline BothRenders renderBoth(GpuContext& context, const LoadedTestScene& scene,
                              const RenderSettings& settings) {
    BothRenders r;
    r.cpu = renderTestScene(scene, settings, &r.cpuStats);
    r.gpu = renderOnDevice(context, scene, settings, &r.gpuStats);
    return r;
}

} // namespace vkpt::test
