// scene_features_test.cpp — analyseScene on the generated loader scenes and on scenes built here:
// only what a triangle or sphere uses counts, emitters are counted as light sampling lists
// them, and the kernel switches follow the features.
#include <string>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "scene/scene_features.h"

namespace vkpt::scene_features_test {
namespace {

const std::string kLoaderDir = VKPT_SCENES_DIR "/loader/";

SceneFeatures featuresOf(const std::string& file) {
    LoadOptions quiet; // the loader's notes are tested elsewhere
    quiet.warnUnsupportedExtensions = false;
    testing::internal::CaptureStderr();
    Scene scene;
    try {
        scene = loadGltfScene(kLoaderDir + file, quiet);
    } catch (...) {
        testing::internal::GetCapturedStderr();
        throw;
    }
    testing::internal::GetCapturedStderr();
    return analyseScene(scene);
}

// The kinds of SceneFeatures as one comparable string, so that a test names them all.
std::string kinds(const SceneFeatures& f) {
    std::string text;
    const std::pair<bool, const char*> flags[] = {
        {f.diffuseMaterials, "diffuse"},
        {f.metallicRoughnessMaterials, "mr"},
        {f.baseColorTextures, "baseColorTex"},
        {f.metallicRoughnessTextures, "mrTex"},
        {f.emissiveTextures, "emissiveTex"},
        {f.normalTextures, "normalTex"},
        {f.transmissionTextures, "transmissionTex"},
        {f.clearcoatMaterials, "clearcoat"},
        {f.sheenMaterials, "sheen"},
        {f.clearcoatTextures, "clearcoatTex"},
        {f.sheenTextures, "sheenTex"},
        {f.specularTextures, "specularTex"},
        {f.alphaMask, "mask"},
        {f.doubleSided, "doubleSided"},
        {f.transmission, "transmission"},
        {f.triangles, "triangles"},
        {f.spheres, "spheres"},
        {f.emissiveTriangles, "emissiveTriangles"},
        {f.emissiveSpheres, "emissiveSpheres"},
        {f.pointLights, "point"},
        {f.spotLights, "spot"},
        {f.directionalLights, "directional"},
        {f.environment, "environment"},
        {f.environmentMap, "environmentMap"},
    };
    for (const auto& [on, name] : flags)
        if (on) text += std::string(text.empty() ? "" : " ") + name;
    return text + " | " + std::to_string(f.emitterCount);
}

// --- The generated loader scenes -----------------------------------------------------------

TEST(SceneFeatures, OfTheLoaderScenes) {
    EXPECT_EQ(kinds(featuresOf("indices_u16.gltf")), "mr triangles | 0");
    // Material "factors" is MASK and double-sided; "emissive" emits from one triangle.
    EXPECT_EQ(kinds(featuresOf("materials.gltf")),
              "mr mask doubleSided triangles emissiveTriangles | 1");
    EXPECT_EQ(kinds(featuresOf("textured.gltf")), "mr baseColorTex mrTex triangles | 0");
    EXPECT_EQ(kinds(featuresOf("textured.glb")),
              "mr baseColorTex emissiveTex triangles emissiveTriangles | 2");
    EXPECT_EQ(kinds(featuresOf("texture_transform.gltf")),
              "mr baseColorTex emissiveTex triangles emissiveTriangles | 2");
    // Metallic 0 alone is not Lambertian: the core specular layer stays (specular 1).
    EXPECT_EQ(kinds(featuresOf("spheres.gltf")), "mr triangles spheres emissiveSpheres | 1");
    // KHR_materials_transmission (with a texture), _ior and _volume.
    EXPECT_EQ(kinds(featuresOf("glass.gltf")), "mr transmissionTex transmission triangles | 0");
    EXPECT_EQ(kinds(featuresOf("lights.gltf")), "mr triangles point spot directional | 3");
    // KHR_materials_specular textures count on the GGX material only.
    EXPECT_EQ(kinds(featuresOf("specular.gltf")), "diffuse mr specularTex triangles | 0");
}

// --- Scenes built here ---------------------------------------------------------------------

SceneMaterial lambertian(glm::vec3 emission = glm::vec3(0.0f)) {
    SceneMaterial material;
    material.metallic = 0.0f;
    material.specular = 0.0f;
    material.emission = emission;
    return material;
}

void addTriangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, std::uint32_t material) {
    for (const glm::vec3& p : {a, b, c}) {
        scene.positions.push_back(p);
        scene.normals.push_back({0, 0, 1});
    }
    scene.materialIndices.push_back(material);
}

TEST(SceneFeatures, IgnoreMaterialsNoPrimitiveUses) {
    Scene scene;
    scene.materials = {lambertian()};
    SceneMaterial unused; // metallic-roughness, textured, masked, double-sided, emitting
    unused.baseColorTexture.texture = 0;
    unused.emissiveTexture.texture = 0;
    unused.alphaMode = AlphaMode::Mask;
    unused.doubleSided = true;
    unused.emission = glm::vec3(1.0f);
    scene.materials.push_back(unused);
    addTriangle(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0);
    EXPECT_EQ(kinds(analyseScene(scene)), "diffuse triangles | 0");
}

TEST(SceneFeatures, CountEachEmittingSurfaceOnceAsLightSamplingDoes) {
    Scene scene;
    scene.materials = {lambertian(glm::vec3(1.0f)), lambertian(glm::vec3(2.0f)), lambertian()};
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    addTriangle(scene, a, b, c, 0);
    addTriangle(scene, a, b, c, 0);                  // a repeat: the same surface
    addTriangle(scene, b, c, a, 0);                  // the same corners from another start
    addTriangle(scene, a, c, b, 0);                  // the other winding: a second surface
    addTriangle(scene, a, b, c, 1);                  // another material: a third
    addTriangle(scene, a, b, c, 2);                  // does not emit
    addTriangle(scene, a, b, glm::vec3(2, 0, 0), 0); // no area: never sampled
    scene.spheres.push_back({{0, 0, 5}, 1.0f, 0});
    scene.spheres.push_back({{0, 0, 9}, 1.0f, 2}); // does not emit
    const SceneFeatures features = analyseScene(scene);
    EXPECT_EQ(kinds(features), "diffuse triangles spheres emissiveTriangles emissiveSpheres | 4");
    EXPECT_TRUE(features.emitterCdf());
}

TEST(SceneFeatures, CountLightsThatShineAndTheEnvironment) {
    Scene scene;
    scene.materials = {lambertian()};
    addTriangle(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0);
    SceneLight spot;
    spot.kind = LightKind::Spot;
    scene.lights.push_back(spot);
    SceneLight black; // a directional light of intensity 0: a kind present, nothing to sample
    black.kind = LightKind::Directional;
    black.intensity = glm::vec3(0.0f);
    scene.lights.push_back(black);
    EXPECT_EQ(kinds(analyseScene(scene)), "diffuse triangles spot directional | 1");
    EXPECT_FALSE(analyseScene(scene).emitterCdf());

    scene.environment.radiance = glm::vec3(0.5f);
    EXPECT_EQ(kinds(analyseScene(scene)), "diffuse triangles spot directional environment | 2");
    scene.environment.width = 4;
    scene.environment.height = 2;
    scene.environment.texels.assign(8, glm::vec3(1.0f));
    EXPECT_EQ(kinds(analyseScene(scene)),
              "diffuse triangles spot directional environment environmentMap | 2");
    EXPECT_TRUE(analyseScene(scene).emitterCdf());
}

TEST(SceneFeatures, MapToTheKernelSpecialisationConstants) {
    SceneFeatures f;
    EXPECT_EQ(f.kernelFeatures(), (std::array<bool, FEATURE_COUNT>{}));
    const auto only = [](int feature) {
        std::array<bool, FEATURE_COUNT> on{};
        on[static_cast<std::size_t>(feature)] = true;
        return on;
    };
    f = {};
    f.metallicRoughnessMaterials = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_METALLIC_ROUGHNESS));
    f = {};
    f.emissiveTextures = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_TEXTURES));
    f = {};
    f.alphaMask = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_ALPHA_MASK));
    f = {};
    f.spheres = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_SPHERES));
    f = {};
    f.spotLights = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_PUNCTUAL_LIGHTS));
    f = {};
    f.environment = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_ENVIRONMENT));
    f = {};
    f.environmentMap = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_ENVIRONMENT_MAP));
    f = {};
    f.emitterCount = 2;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_EMITTER_CDF));
    f = {};
    f.doubleSided = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_DOUBLE_SIDED));
    f = {};
    f.transmission = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_TRANSMISSION));
    f = {};
    f.clearcoatMaterials = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_CLEARCOAT));
    f = {};
    f.sheenMaterials = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_SHEEN));
    f = {};
    f.transmissionTextures = true;
    EXPECT_EQ(f.kernelFeatures(), only(FEATURE_TEXTURES));
    // Specular textures are textures (their coordinates) and a switch of their own.
    f = {};
    f.specularTextures = true;
    std::array<bool, FEATURE_COUNT> specular = only(FEATURE_SPECULAR_TEXTURES);
    specular[FEATURE_TEXTURES] = true;
    EXPECT_EQ(f.kernelFeatures(), specular);
    // Kinds that need no kernel switch of their own.
    f = {};
    f.diffuseMaterials = f.triangles = f.emissiveTriangles = f.emissiveSpheres = true;
    f.emitterCount = 1;
    EXPECT_EQ(f.kernelFeatures(), (std::array<bool, FEATURE_COUNT>{}));
}

TEST(SceneFeatures, GeneralTurnsEverythingOnAndKeepsTheEmitterCount) {
    SceneFeatures used;
    used.diffuseMaterials = used.triangles = true;
    used.emitterCount = 1;
    const SceneFeatures general = generalFeatures(used);
    EXPECT_EQ(kinds(general),
              "diffuse mr baseColorTex mrTex emissiveTex normalTex transmissionTex clearcoat sheen "
              "clearcoatTex sheenTex specularTex mask doubleSided transmission triangles spheres "
              "emissiveTriangles emissiveSpheres point spot directional environment "
              "environmentMap | 1");
    EXPECT_TRUE(general.general);
    std::array<bool, FEATURE_COUNT> all{};
    all.fill(true);                  // the general layout reads a CDF even for one emitter
    all[FEATURE_INSTANCES] = false;  // a layout the scene has or not, kept from `used`
    all[FEATURE_LIGHT_TREE] = false; // a choice of the render, kept from `used`
    EXPECT_EQ(general.kernelFeatures(), all);
    EXPECT_FALSE(used.emitterCdf());
    used.instances = true;
    EXPECT_TRUE(generalFeatures(used).kernelFeatures()[FEATURE_INSTANCES]);
}

TEST(SceneFeatures, DescribeInOneLine) {
    SceneFeatures f;
    f.diffuseMaterials = f.metallicRoughnessMaterials = true;
    f.baseColorTextures = f.emissiveTextures = true;
    f.triangles = f.spheres = f.emissiveTriangles = true;
    f.pointLights = true;
    f.environment = true;
    f.emitterCount = 3;
    EXPECT_EQ(describeFeatures(f),
              "diffuse, metallic-roughness, textures (base colour, emissive), triangles, "
              "spheres, emissive triangles, point lights, environment colour, 3 emitters");
    SceneFeatures one;
    one.emitterCount = 1;
    one.environment = one.environmentMap = true;
    EXPECT_EQ(describeFeatures(one), "environment map, 1 emitter");
}

} // namespace
} // namespace vkpt::scene_features_test
