// extremes_support.h — what the numerical-extremes tests share: scenes built in memory (quads,
// boxes, cameras), both renderers on the same scene and settings, and the checks every extreme
// case makes: nothing non-finite in the output, and the device agreeing with the reference.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../image/wavefront_test_support.h"
#include "image/image_compare.h"
#include "scene/camera.h"

namespace vkpt::test {

// ---------------------------------------------------------------------------------------------
// Scenes in memory

inline std::uint32_t addMaterial(Scene& scene, glm::vec3 albedo,
                                 glm::vec3 emission = glm::vec3(0.0f), bool doubleSided = false) {
    SceneMaterial material;
    material.name = "material " + std::to_string(scene.materials.size());
    material.baseColor = glm::vec4(albedo, 1.0f);
    material.emission = emission;
    material.metallic = 0.0f;
    material.doubleSided = doubleSided;
    scene.materials.push_back(material);
    return std::uint32_t(scene.materials.size() - 1);
}

// One triangle with flat shading normals; its front face is the counter-clockwise side.
inline void addTriangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c,
                        std::uint32_t material) {
    glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (glm::vec3 p : {a, b, c}) {
        scene.positions.push_back(p);
        scene.normals.push_back(n);
    }
    scene.materialIndices.push_back(material);
}

// A quad a b c d, counter-clockwise seen from its front.
inline void addQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
                    std::uint32_t material) {
    addTriangle(scene, a, b, c, material);
    addTriangle(scene, a, c, d, material);
}

// A horizontal rectangle at height y, facing up (+y) or down, split into cells × cells quads.
inline void addHorizontalGrid(Scene& scene, glm::vec2 lo, glm::vec2 hi, float y, bool facingUp,
                              int cells, std::uint32_t material) {
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            auto at = [&](int di, int dj) {
                float x = lo.x + (hi.x - lo.x) * float(i + di) / float(cells);
                float z = lo.y + (hi.y - lo.y) * float(j + dj) / float(cells);
                return glm::vec3(x, y, z);
            };
            if (facingUp) {
                addQuad(scene, at(0, 0), at(0, 1), at(1, 1), at(1, 0), material);
            } else {
                addQuad(scene, at(0, 0), at(1, 0), at(1, 1), at(0, 1), material);
            }
        }
}

// A closed axis-aligned box whose faces point outwards.
inline void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, std::uint32_t material) {
    glm::vec3 p[8];
    for (int i = 0; i < 8; ++i)
        p[i] = glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    addQuad(scene, p[0], p[4], p[6], p[2], material); // -x
    addQuad(scene, p[1], p[3], p[7], p[5], material); // +x
    addQuad(scene, p[0], p[1], p[5], p[4], material); // -y
    addQuad(scene, p[2], p[6], p[7], p[3], material); // +y
    addQuad(scene, p[0], p[2], p[3], p[1], material); // -z
    addQuad(scene, p[4], p[5], p[7], p[6], material); // +z
}

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
    return {scene, prepareScene(scene, {{}, scene.cameras.at(0).forward})};
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
