// gltf_material_extensions_test.cpp — the loader's reading of material extensions beyond the
// layered BSDF's factors, on the generated files of scenes/loader: KHR_materials_unlit (the base
// colour as an emitter that reflects nothing), KHR_materials_variants (--variant) and
// KHR_materials_anisotropy (with scenes/test/features/anisotropy.gltf), and the Khronos samples
// of ../shared/scenes that use them.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/captured_load.h"
#include "common/errors.h"
#include "prepare/gpu_materials.h"
#include "scene/gltf_loader.h"
#include "scene/scene_features.h"

namespace vkpt::gltf_material_extensions_test {
namespace {

const std::string kLoaderDir = VKPT_SCENES_DIR "/loader/";
const std::string kSamplesDir = VKPT_SCENES_DIR "/../../shared/scenes/";

Scene loadWithVariant(const std::string& file, const std::string& variant,
                      std::string* notes = nullptr) {
    LoadOptions options;
    options.variant = variant;
    testing::internal::CaptureStderr();
    Scene scene;
    try {
        scene = loadGltfScene(kLoaderDir + file, options);
    } catch (...) {
        testing::internal::GetCapturedStderr();
        throw;
    }
    const std::string captured = testing::internal::GetCapturedStderr();
    if (notes != nullptr) *notes = captured;
    return scene;
}

// A Khronos sample loads with no line saying that something was ignored or is not supported.
void expectSampleLoadsWithoutNotes(const std::string& relative) {
    const std::string path = kSamplesDir + relative;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not present";
    std::string notes;
    test::loadCapturingNotes(path, &notes);
    EXPECT_EQ(notes.find("ignoring"), std::string::npos) << notes;
    EXPECT_EQ(notes.find("not supported"), std::string::npos) << notes;
}

// --- KHR_materials_unlit ---------------------------------------------------------------------

// The base colour becomes the emission (the texture moves to the emissive slot), the surface
// reflects nothing (a black Lambertian, so no GGX code is compiled for it), and what the
// extension says an unlit surface ignores (normal texture, KHR_materials_specular) is neither
// read nor reported.
TEST(GltfUnlit, BaseColourBecomesTheEmissionOfASurfaceThatReflectsNothing) {
    std::string notes;
    const Scene scene = loadWithVariant("unlit.gltf", "", &notes);
    EXPECT_EQ(notes, "");
    ASSERT_EQ(scene.materials.size(), 3u);
    const SceneMaterial& orange = scene.materials[0];
    EXPECT_TRUE(orange.unlit);
    EXPECT_EQ(orange.emission, glm::vec3(1.0f, 0.25f, 0.0f));
    EXPECT_LT(orange.emissiveTexture.texture, 0);
    EXPECT_EQ(orange.baseColor, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_TRUE(orange.isDiffuseOnly());
    EXPECT_FALSE(orange.hasNormalMap());
    EXPECT_FALSE(orange.doubleSided);
    const SceneMaterial& cutOut = scene.materials[1];
    EXPECT_EQ(cutOut.emission, glm::vec3(0.5f));
    EXPECT_GE(cutOut.emissiveTexture.texture, 0);
    // MASK: the texture's alpha still cuts the surface out, through the base colour slot.
    EXPECT_EQ(cutOut.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(cutOut.baseColorTexture.texture, cutOut.emissiveTexture.texture);
    EXPECT_EQ(glm::vec3(cutOut.baseColor), glm::vec3(0.0f));
    EXPECT_TRUE(scene.materials[2].doubleSided);
    const SceneFeatures features = analyseScene(scene);
    EXPECT_FALSE(features.metallicRoughnessMaterials);
    EXPECT_FALSE(features.normalTextures);
    EXPECT_TRUE(features.emissiveTriangles);
}

TEST(GltfUnlit, UnlitTestSampleLoads) {
    expectSampleLoadsWithoutNotes("UnlitTest/UnlitTest.glb");
}

// --- KHR_materials_variants ------------------------------------------------------------------

// Triangle 0 is the mapped primitive, triangle 1 the unmapped one.
std::vector<std::uint32_t> materialsUnder(const std::string& variant) {
    const Scene scene = loadWithVariant("variants.gltf", variant);
    return {scene.materialIndices.at(0), scene.materialIndices.at(1)};
}

TEST(GltfVariants, ListsTheVariantsAndShowsTheDefaultMaterialsUnlessOneIsChosen) {
    std::string notes;
    const Scene scene = loadWithVariant("variants.gltf", "", &notes);
    EXPECT_EQ(notes, "");
    EXPECT_EQ(scene.materialVariants, (std::vector<std::string>{"red", "green", "2"}));
    EXPECT_EQ(scene.materialVariant, -1);
    EXPECT_EQ(materialsUnder(""), (std::vector<std::uint32_t>{0, 0}));
}

// A name first, then an index: "2" is the variant named "2", "1" the second variant.
TEST(GltfVariants, ChoosesByNameOrIndexAndLeavesUnmappedPrimitivesAlone) {
    EXPECT_EQ(materialsUnder("red"), (std::vector<std::uint32_t>{1, 0}));
    EXPECT_EQ(materialsUnder("green"), (std::vector<std::uint32_t>{2, 0}));
    EXPECT_EQ(materialsUnder("2"), (std::vector<std::uint32_t>{2, 0}));
    EXPECT_EQ(materialsUnder("1"), (std::vector<std::uint32_t>{2, 0}));
    EXPECT_EQ(materialsUnder("0"), (std::vector<std::uint32_t>{1, 0}));
    EXPECT_EQ(loadWithVariant("variants.gltf", "green").materialVariant, 1);
}

void expectVariantRejected(const std::string& file, const std::string& variant,
                           const std::string& message) {
    try {
        loadWithVariant(file, variant);
        ADD_FAILURE() << variant << " was accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), kLoaderDir + file + ": " + message);
    }
}

TEST(GltfVariants, AnUnknownVariantIsOneLineListingTheFilesVariants) {
    expectVariantRejected("variants.gltf", "blue",
                          "--variant blue: no variant of that name or index (the file's: 0 'red', "
                          "1 'green', 2 '2')");
    expectVariantRejected("variants.gltf", "3",
                          "--variant 3: no variant of that name or index (the file's: 0 'red', "
                          "1 'green', 2 '2')");
    expectVariantRejected("glass.gltf", "red",
                          "--variant red: the file has no KHR_materials_variants");
}

TEST(GltfVariants, MaterialsVariantsShoeSampleLoadsEachVariant) {
    expectSampleLoadsWithoutNotes("MaterialsVariantsShoe/MaterialsVariantsShoe.gltf");
    const std::string path = kSamplesDir + "MaterialsVariantsShoe/MaterialsVariantsShoe.gltf";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not present";
    for (const char* variant : {"midnight", "beach", "street"}) {
        LoadOptions options;
        options.variant = variant;
        testing::internal::CaptureStderr();
        const Scene scene = loadGltfScene(path, options);
        testing::internal::GetCapturedStderr();
        ASSERT_GT(scene.triangleCount(), 0u);
        // The shoe's one primitive maps variant i to material i.
        EXPECT_EQ(scene.materialIndices[0], std::uint32_t(scene.materialVariant)) << variant;
    }
}

// --- KHR_materials_anisotropy --------------------------------------------------------------

// The brushed floor (stored tangents) and the textured block (generated tangents) of the
// feature scene: factors and texture read, tangent frames made for both, the feature and the
// device record's rotation as cosine and sine.
TEST(GltfAnisotropy, ReadsStrengthRotationAndTextureAndMakesTangents) {
    std::string notes;
    const Scene scene =
        test::loadCapturingNotes(VKPT_SCENES_DIR "/test/features/anisotropy.gltf", &notes);
    EXPECT_EQ(notes, "");
    const SceneMaterial& floor = scene.materials.at(1);
    EXPECT_EQ(floor.anisotropyStrength, 0.8f);
    EXPECT_EQ(floor.anisotropyRotation, 0.0f);
    EXPECT_TRUE(floor.hasAnisotropy());
    EXPECT_TRUE(floor.needsTangents());
    const SceneMaterial& block = scene.materials.at(2);
    EXPECT_EQ(block.anisotropyStrength, 1.0f);
    EXPECT_EQ(block.anisotropyRotation, 0.5f);
    EXPECT_GE(block.anisotropyTexture.texture, 0);
    ASSERT_EQ(scene.tangents.size(), scene.positions.size());
    for (std::size_t t = 0; t < scene.triangleCount(); ++t) {
        const bool anisotropic = scene.materials[scene.materialIndices[t]].hasAnisotropy();
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_EQ(scene.tangents[3 * t + k].w != 0.0f, anisotropic) << "triangle " << t;
    }
    const SceneFeatures features = analyseScene(scene);
    EXPECT_TRUE(features.anisotropy);
    EXPECT_TRUE(features.anisotropyTextures);
    EXPECT_TRUE(features.tangents());
    EXPECT_TRUE(features.kernelFeatures()[FEATURE_ANISOTROPY]);
    const std::vector<gpu::SpecularLobeParams> device = makeGpuSpecularLobes(scene.materials);
    EXPECT_EQ(device[2].anisotropyStrength, 1.0f);
    EXPECT_FLOAT_EQ(device[2].anisotropyRotationCos, std::cos(0.5f));
    EXPECT_FLOAT_EQ(device[2].anisotropyRotationSin, std::sin(0.5f));
    EXPECT_EQ(device[0].anisotropyStrength, 0.0f);
}

// --- KHR_materials_iridescence ------------------------------------------------------------

TEST(GltfIridescence, ReadsFactorIorThicknessRangeAndTextures) {
    std::string notes;
    const Scene scene =
        test::loadCapturingNotes(VKPT_SCENES_DIR "/test/features/iridescence.gltf", &notes);
    EXPECT_EQ(notes, "");
    const SceneMaterial& bubble = scene.materials.at(1);
    EXPECT_EQ(bubble.iridescence, 1.0f);
    EXPECT_EQ(bubble.iridescenceIor, 1.33f);
    EXPECT_EQ(bubble.iridescenceThicknessMinimum, 200.0f);
    EXPECT_EQ(bubble.iridescenceThicknessMaximum, 700.0f);
    EXPECT_GE(bubble.iridescenceThicknessTexture.texture, 0);
    EXPECT_TRUE(bubble.hasIridescence());
    const SceneMaterial& metal = scene.materials.at(2);
    EXPECT_EQ(metal.iridescence, 0.8f);
    EXPECT_EQ(metal.iridescenceThicknessMinimum, 100.0f); // the extension's default
    EXPECT_LT(metal.iridescenceTexture.texture, 0);
    const SceneFeatures features = analyseScene(scene);
    EXPECT_TRUE(features.iridescence);
    EXPECT_TRUE(features.iridescenceTextures);
    EXPECT_TRUE(features.kernelFeatures()[FEATURE_IRIDESCENCE]);
    const std::vector<gpu::SpecularLobeParams> device = makeGpuSpecularLobes(scene.materials);
    EXPECT_EQ(device[1].iridescence, 1.0f);
    EXPECT_EQ(device[1].iridescenceThicknessMaximum, 700.0f);
    EXPECT_EQ(device[0].iridescence, 0.0f);
}

// IridescenceSuzanne requires the extension: it was refused, and now loads with no note.
TEST(GltfIridescence, IridescenceSuzanneLoads) {
    expectSampleLoadsWithoutNotes("IridescenceSuzanne/IridescenceSuzanne.glb");
}

TEST(GltfAnisotropy, KhronosSamplesLoad) {
    expectSampleLoadsWithoutNotes("AnisotropyStrengthTest/AnisotropyStrengthTest.glb");
    expectSampleLoadsWithoutNotes("AnisotropyRotationTest/AnisotropyRotationTest.glb");
}

} // namespace
} // namespace vkpt::gltf_material_extensions_test
