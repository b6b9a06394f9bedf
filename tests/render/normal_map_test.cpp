// normal_map_test.cpp — normal-mapped surfaces in a white furnace (vkpt-ref): a white plane
// under a constant environment of radiance 1 reflects exactly 1 with its own normals and at
// most 1 with any shading normal, since a lobe about a normal above the surface integrates to
// at most 1 over the hemisphere above it and light sampling rejects directions below. The
// mapped surface must not gain energy (within 3 standard errors) and must never be black where
// the unmapped one is lit (shared/normal_mapping.h bends normals that face away from the view).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "../support/reference_render.h"
#include "image/image_compare.h"
#include "scene/tangents.h"
#include "shared/sampling.h"

namespace vkpt::normal_map_test {
namespace {

// Steep bumps: the tangent-space normal of the height field 0.5·sin(x)·sin(y) with a slope of
// up to 2.5, so that many texels tilt by 60–70° and some face away from grazing views.
SceneImage steepBumps() {
    constexpr std::uint32_t kSize = 16;
    SceneImage image;
    image.name = "steep bumps";
    image.width = image.height = kSize;
    const float k = 2.0f * 3.14159265f / float(kSize);
    for (std::uint32_t y = 0; y < kSize; ++y)
        for (std::uint32_t x = 0; x < kSize; ++x) {
            const float fx = k * (float(x) + 0.5f);
            const float fy = k * (float(y) + 0.5f);
            const glm::vec3 n = glm::normalize(glm::vec3(-2.5f * std::cos(fx) * std::sin(fy),
                                                         2.5f * std::sin(fx) * std::cos(fy), 1.0f));
            const glm::uvec3 c = glm::uvec3(glm::round((n * 0.5f + 0.5f) * 255.0f));
            image.texels.push_back(c.x | (c.y << 8) | (c.z << 16) | (255u << 24));
        }
    return image;
}

// A 20 × 20 white floor facing +Y, its texture repeated ten times across, seen from height 1
// looking 45° down (every camera ray meets it), under the environment of radiance 1.
test::LoadedTestScene furnaceFloor(bool metal, bool normalMapped) {
    Scene scene;
    scene.sourcePath = "normal-mapped furnace floor";
    SceneMaterial material;
    material.baseColor = glm::vec4(1.0f);
    material.metallic = metal ? 1.0f : 0.0f;
    material.specular = metal ? 1.0f : 0.0f; // diffuse: the Lambertian kind
    material.roughness = 0.3f;
    if (normalMapped) {
        scene.images.push_back(steepBumps());
        scene.textures.push_back(SceneTexture{});
        material.normalTexture.texture = 0;
    }
    scene.materials.push_back(material);
    const glm::vec3 p[4] = {{-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}};
    const glm::vec2 uv[4] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    for (int i : {0, 1, 2, 0, 2, 3}) {
        scene.positions.push_back(p[i]);
        scene.normals.emplace_back(0, 1, 0);
        scene.texcoords.push_back(uv[i]);
    }
    scene.materialIndices = {0, 0};
    if (normalMapped)
        scene.tangents = generateTangents(scene.positions, scene.normals, scene.texcoords);
    SceneCamera camera;
    camera.position = {0, 1, 0};
    camera.forward = glm::normalize(glm::vec3(0, -1, -1));
    camera.up = glm::normalize(glm::vec3(0, 1, -1));
    camera.yfov = 0.7f; // 40°: the top row looks 25° below the horizon
    scene.cameras.push_back(camera);
    scene.environment.radiance = glm::vec3(1.0f);
    test::LoadedTestScene loaded{std::move(scene), {}};
    loaded.prepared = prepareScene(loaded.scene);
    return loaded;
}

RenderOutput renderFloor(bool metal, bool normalMapped) {
    RenderSettings settings = test::testSettings(32, 64);
    settings.maxDepth = 16;
    return test::renderTestScene(furnaceFloor(metal, normalMapped), settings);
}

class NormalMappedFurnace : public testing::TestWithParam<bool> {};

TEST_P(NormalMappedFurnace, GainsNoEnergyAndIsNeverBlackWhereTheFlatSurfaceIsLit) {
    const bool metal = GetParam();
    const RenderOutput flat = renderFloor(metal, false);
    const RenderOutput mapped = renderFloor(metal, true);
    const MeanEstimate flatMean = meanLuminance(flat);
    const MeanEstimate mappedMean = meanLuminance(mapped);
    std::printf("white %s floor in the furnace: flat %.4f ± %.4f, normal-mapped %.4f ± %.4f\n",
                metal ? "metal" : "diffuse", flatMean.mean, flatMean.standardError, mappedMean.mean,
                mappedMean.standardError);
    // The Lambertian white floor reflects the environment exactly; rough metal loses some.
    if (!metal) {
        EXPECT_NEAR(flatMean.mean, 1.0, 3.0 * flatMean.standardError + 1e-5);
    }
    // One-sided 3σ: a gain of energy would show as a mean above 1.
    EXPECT_LE(mappedMean.mean, 1.0 + 3.0 * mappedMean.standardError + 1e-5);
    std::size_t black = 0;
    for (std::size_t i = 0; i < flat.image.pixels.size(); ++i) {
        const float lit = gpu::luminance(flat.image.pixels[i]);
        if (lit > 0.0f && !(gpu::luminance(mapped.image.pixels[i]) > 0.0f)) ++black;
    }
    EXPECT_EQ(black, 0u) << "pixels black with the normal map but lit without it";
}

INSTANTIATE_TEST_SUITE_P(DiffuseAndMetal, NormalMappedFurnace, testing::Values(false, true),
                         [](const testing::TestParamInfo<bool>& test) {
                             return std::string(test.param ? "RoughMetal" : "Lambertian");
                         });

} // namespace
} // namespace vkpt::normal_map_test
