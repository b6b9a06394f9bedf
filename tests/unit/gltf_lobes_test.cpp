// gltf_lobes_test.cpp — the loader's reading of KHR_materials_diffuse_transmission and
// KHR_materials_dispersion (scenes/test/lobes), the features they switch on, and the
// materialLobes records made of them; a scene without them gets neither feature nor records.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/captured_load.h"
#include "prepare/gpu_materials.h"
#include "prepare/prepared_scene.h"
#include "scene/scene_features.h"

namespace vkpt::gltf_lobes_test {
namespace {

TEST(GltfLobes, ReadsDiffuseTransmissionFactorColourAndTextures) {
    std::string notes;
    const Scene scene = test::loadCapturingNotes(VKPT_SCENES_DIR "/test/lobes/leaf.gltf", &notes);
    EXPECT_EQ(notes, "");
    const SceneMaterial& leaf = scene.materials.at(1);
    EXPECT_EQ(leaf.diffuseTransmission, 0.6f);
    EXPECT_EQ(leaf.diffuseTransmissionColor, glm::vec3(0.7f, 0.95f, 0.3f));
    EXPECT_GE(leaf.diffuseTransmissionTexture.texture, 0);
    EXPECT_LT(leaf.diffuseTransmissionColorTexture.texture, 0);
    EXPECT_TRUE(leaf.hasDiffuseTransmission());
    EXPECT_FALSE(leaf.isDiffuseOnly());
    const SceneFeatures features = analyseScene(scene);
    EXPECT_TRUE(features.diffuseTransmission);
    EXPECT_TRUE(features.diffuseTransmissionTextures);
    EXPECT_FALSE(features.dispersion);
    EXPECT_TRUE(features.kernelFeatures()[FEATURE_DIFFUSE_TRANSMISSION]);
    const std::vector<gpu::MaterialLobes> lobes = makeGpuMaterialLobes(scene.materials);
    ASSERT_EQ(lobes.size(), scene.materials.size());
    EXPECT_EQ(lobes[1].diffuseTransmission, 0.6f);
    EXPECT_EQ(lobes[1].diffuseTransmissionTexture.texture,
              std::uint32_t(leaf.diffuseTransmissionTexture.texture));
    EXPECT_EQ(lobes[1].diffuseTransmissionColorTexture.texture, NO_TEXTURE);
    EXPECT_EQ(lobes[0].diffuseTransmission, 0.0f);
    EXPECT_EQ(prepareScene(scene, {}).materialLobes.size(), scene.materials.size());
}

TEST(GltfLobes, ReadsDispersionOfGlassThatBoundsAVolume) {
    std::string notes;
    const Scene scene = test::loadCapturingNotes(VKPT_SCENES_DIR "/test/lobes/prism.gltf", &notes);
    EXPECT_EQ(notes, "");
    const SceneMaterial& flint = scene.materials.at(1);
    EXPECT_EQ(flint.dispersion, 4.0f);
    EXPECT_TRUE(flint.hasDispersion());
    const SceneFeatures features = analyseScene(scene);
    EXPECT_TRUE(features.dispersion);
    EXPECT_FALSE(features.diffuseTransmission);
    EXPECT_TRUE(features.kernelFeatures()[FEATURE_DISPERSION]);
    EXPECT_EQ(makeGpuMaterialLobes(scene.materials)[1].dispersion, 4.0f);
    // Thin-walled glass does not disperse: no feature, no wavelength.
    SceneMaterial thin = flint;
    thin.thickness = 0.0f;
    EXPECT_FALSE(thin.hasDispersion());
    EXPECT_EQ(makeGpuMaterialLobes({thin})[0].dispersion, 0.0f);
}

// The Cornell box has neither lobe: no feature, and no materialLobes records to upload.
TEST(GltfLobes, SceneWithoutTheLobesHasNoLobeRecords) {
    const Scene scene = test::loadCapturingNotes(VKPT_SCENES_DIR "/cornell-box.gltf", nullptr);
    const PreparedScene prepared = prepareScene(scene, {});
    EXPECT_FALSE(prepared.features.diffuseTransmission);
    EXPECT_FALSE(prepared.features.dispersion);
    EXPECT_TRUE(prepared.materialLobes.empty());
}

} // namespace
} // namespace vkpt::gltf_lobes_test
