// gltf_layers_test.cpp — the loader's KHR_materials_clearcoat and KHR_materials_sheen: factors,
// textures (with their channels' meaning kept for the shading code), the defaults, the feature
// switches a scene with layers turns on, the note for clearcoatNormalTexture (not supported),
// and the Khronos ToyCar, which uses both layers.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "../support/captured_load.h"
#include "../support/test_directory.h"
#include "scene/gltf_loader.h"
#include "scene/scene_features.h"

namespace vkpt::gltf_layers_test {
namespace {

const std::string kFeatureDir = VKPT_SCENES_DIR "/test/features/";
const std::string kToyCar = VKPT_SCENES_DIR "/../../shared/scenes/ToyCar/ToyCar.gltf";

Scene load(const std::string& path, std::string* notes = nullptr) {
    return test::loadCapturingNotes(path, notes);
}

const SceneMaterial& named(const Scene& scene, const std::string& name) {
    for (const SceneMaterial& m : scene.materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

TEST(GltfClearcoat, ReadsFactorsAndTextures) {
    std::string notes;
    const Scene scene = load(kFeatureDir + "clearcoat.gltf", &notes);
    const SceneMaterial& paint = named(scene, "coated red paint");
    EXPECT_FLOAT_EQ(paint.clearcoat, 1.0f);
    EXPECT_FLOAT_EQ(paint.clearcoatRoughness, 0.03f);
    EXPECT_LT(paint.clearcoatTexture.texture, 0);
    EXPECT_FALSE(paint.isDiffuseOnly());
    const SceneMaterial& metal = named(scene, "coated rough metal");
    EXPECT_FLOAT_EQ(metal.clearcoat, 0.8f);
    EXPECT_FLOAT_EQ(metal.clearcoatRoughness, 0.2f);
    const SceneMaterial& textured = named(scene, "textured coat");
    EXPECT_GE(textured.clearcoatTexture.texture, 0);
    EXPECT_EQ(textured.clearcoatRoughnessTexture.texture, textured.clearcoatTexture.texture);
    // A material without the extension has no layer.
    EXPECT_FALSE(named(scene, "grey").hasClearcoat());
    EXPECT_FALSE(named(scene, "grey").hasSheen());
    EXPECT_EQ(notes.find("KHR_materials_clearcoat"), std::string::npos) << notes;

    const SceneFeatures features = analyseScene(scene);
    EXPECT_TRUE(features.clearcoatMaterials);
    EXPECT_TRUE(features.clearcoatTextures);
    EXPECT_FALSE(features.sheenMaterials);
    EXPECT_TRUE(features.kernelFeatures()[FEATURE_CLEARCOAT]);
    EXPECT_FALSE(features.kernelFeatures()[FEATURE_SHEEN]);
}

TEST(GltfSheen, ReadsFactorsAndTextures) {
    const Scene scene = load(kFeatureDir + "sheen.gltf");
    const SceneMaterial& velvet = named(scene, "velvet");
    EXPECT_FLOAT_EQ(velvet.sheenColor.x, 0.9f);
    EXPECT_FLOAT_EQ(velvet.sheenColor.y, 0.4f);
    EXPECT_FLOAT_EQ(velvet.sheenColor.z, 0.8f);
    EXPECT_FLOAT_EQ(velvet.sheenRoughness, 0.3f);
    EXPECT_TRUE(velvet.hasSheen());
    EXPECT_FALSE(velvet.hasClearcoat());
    const SceneMaterial& woven = named(scene, "woven");
    EXPECT_GE(woven.sheenColorTexture.texture, 0);
    EXPECT_EQ(woven.sheenRoughnessTexture.texture, woven.sheenColorTexture.texture);

    const SceneFeatures features = analyseScene(scene);
    EXPECT_TRUE(features.sheenMaterials);
    EXPECT_TRUE(features.sheenTextures);
    EXPECT_FALSE(features.clearcoatMaterials);
    EXPECT_TRUE(features.kernelFeatures()[FEATURE_SHEEN]);
    EXPECT_TRUE(features.kernelFeatures()[FEATURE_TEXTURES]);
}

// A scene without layers keeps both switches off, so its kernels are those of before.
TEST(GltfLayers, SceneWithoutLayersLeavesTheirSwitchesOff) {
    const SceneFeatures features = analyseScene(load(kFeatureDir + "ggx.gltf"));
    EXPECT_FALSE(features.kernelFeatures()[FEATURE_CLEARCOAT]);
    EXPECT_FALSE(features.kernelFeatures()[FEATURE_SHEEN]);
}

class GltfLayersFile : public test::TestDirectory {
protected:
    GltfLayersFile() : TestDirectory("gltf_layers") {}

    // clearcoat.gltf with `from` replaced by `to`, written to the test's directory.
    std::string edited(const std::string& from, const std::string& to) {
        std::ifstream in(kFeatureDir + "clearcoat.gltf");
        std::stringstream text;
        text << in.rdbuf();
        std::string json = text.str();
        const std::size_t at = json.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        json.replace(at, from.size(), to);
        const std::string file = path("edited.gltf");
        std::ofstream(file) << json;
        return file;
    }
};

// clearcoatNormalTexture is a normalTextureInfo: read with its scale, and it makes the scene
// need tangent frames even where the base has no normal texture.
TEST_F(GltfLayersFile, ReadsTheClearcoatNormalTextureWithItsScale) {
    std::string notes;
    const std::string file = edited("\"clearcoatRoughnessFactor\": 0.03",
                                    "\"clearcoatRoughnessFactor\": 0.03, "
                                    "\"clearcoatNormalTexture\": {\"index\": 0, \"scale\": 0.5}");
    const Scene scene = load(file, &notes);
    const SceneMaterial& coated = named(scene, "coated red paint");
    EXPECT_FLOAT_EQ(coated.clearcoat, 1.0f);
    EXPECT_GE(coated.clearcoatNormalTexture.texture, 0);
    EXPECT_FLOAT_EQ(coated.clearcoatNormalScale, 0.5f);
    EXPECT_TRUE(coated.hasNormalMap());
    EXPECT_TRUE(analyseScene(scene).tangents());
    EXPECT_EQ(notes.find("clearcoatNormalTexture"), std::string::npos) << notes;
}

TEST_F(GltfLayersFile, RejectsAClearcoatFactorOutsideZeroToOne) {
    const std::string file = edited("\"clearcoatFactor\": 0.8", "\"clearcoatFactor\": 1.5");
    EXPECT_THROW(load(file), std::exception);
}

// The Khronos sample model: a clearcoated body (clearcoat 1, its strength in a texture), a
// sheen fabric and glass windows (KHR_materials_transmission); none of them is named as ignored.
TEST(GltfLayers, ToyCarLoadsWithClearcoatAndSheen) {
    if (!std::filesystem::exists(kToyCar)) GTEST_SKIP() << kToyCar << " is not present";
    std::string notes;
    const Scene scene = load(kToyCar, &notes);
    const SceneMaterial& body = named(scene, "ToyCar");
    EXPECT_FLOAT_EQ(body.clearcoat, 1.0f);
    EXPECT_GE(body.clearcoatTexture.texture, 0);
    const SceneMaterial& fabric = named(scene, "Fabric");
    EXPECT_TRUE(fabric.hasSheen());
    EXPECT_FLOAT_EQ(fabric.sheenRoughness, 0.5f);
    const SceneFeatures features = analyseScene(scene);
    EXPECT_TRUE(features.clearcoatMaterials);
    EXPECT_TRUE(features.sheenMaterials);
    EXPECT_EQ(notes.find("KHR_materials_clearcoat"), std::string::npos) << notes;
    EXPECT_EQ(notes.find("KHR_materials_sheen"), std::string::npos) << notes;
    EXPECT_EQ(notes.find("KHR_materials_transmission"), std::string::npos) << notes;
    EXPECT_GT(named(scene, "Glass").transmission, 0.0f);
}

} // namespace
} // namespace vkpt::gltf_layers_test
