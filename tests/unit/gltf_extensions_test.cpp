// gltf_extensions_test.cpp — the loader's scene model beyond triangles, on the generated files of
// scenes/loader: decoded textures and their samplers, TEXCOORD_0 per triangle,
// KHR_texture_transform, KHR_materials_specular, KHR_lights_punctual, KHR_implicit_shapes
// spheres, KHR_materials_transmission, KHR_materials_ior and KHR_materials_volume, and recentring
// with spheres and lights.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/captured_load.h"
#include "prepare/gpu_materials.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_textures.h"
#include "scene/scene_features.h"

namespace vkpt::gltf_extensions_test {
namespace {

const std::string kLoaderDir = VKPT_SCENES_DIR "/loader/";

constexpr float kTolerance = 1e-6f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = kTolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "component x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "component y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "component z";
}

void expectNear(const glm::vec2& actual, const glm::vec2& expected, float tolerance = kTolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "component u";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "component v";
}

void expectMatrix(const glm::mat3& actual, const glm::mat3& expected) {
    for (int column = 0; column < 3; ++column) {
        SCOPED_TRACE("column " + std::to_string(column));
        expectNear(actual[column], expected[column], 1e-6f);
    }
}

// Loads `file` from scenes/loader, with stderr captured into `notes` when given.
Scene load(const std::string& file, std::string* notes = nullptr) {
    return test::loadCapturingNotes(kLoaderDir + file, notes);
}

// The 3 x 2 image of generate_loader_scenes.py (TEXTURE_ROWS) as packed RGBA8, R in the low
// byte: row 0 red, green, blue; row 1 yellow α 128, cyan α 64, (10, 20, 30) α 40.
const std::vector<std::uint32_t> kTexels = {0xFF0000FFu, 0xFF00FF00u, 0xFFFF0000u,
                                            0x8000FFFFu, 0x40FFFF00u, 0x281E140Au};

void expectTheTestImage(const SceneImage& image) {
    EXPECT_EQ(image.width, 3u);
    EXPECT_EQ(image.height, 2u);
    EXPECT_EQ(image.texels, kTexels);
}

// The texture coordinates of triangle t, in the order of its corners.
std::vector<glm::vec2> texcoordsOf(const Scene& scene, std::size_t t) {
    return {scene.texcoords[3 * t], scene.texcoords[3 * t + 1], scene.texcoords[3 * t + 2]};
}

void expectTexcoords(const Scene& scene, std::size_t t, const std::vector<glm::vec2>& expected) {
    const std::vector<glm::vec2> actual = texcoordsOf(scene, t);
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE("triangle " + std::to_string(t) + ", corner " + std::to_string(i));
        expectNear(actual[i], expected[i]);
    }
}

// --- Textures ------------------------------------------------------------------------------

TEST(GltfTextures, DecodesTheUsedImageOnceWithTexelsInFileOrder) {
    std::string notes;
    const Scene scene = load("textured.gltf", &notes);
    // Two textures share image 0; image 1 (not a PNG) belongs to a texture no material uses and
    // is neither decoded nor reported.
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].name, "texels");
    expectTheTestImage(scene.images[0]);
    EXPECT_EQ(notes, "");
}

TEST(GltfTextures, ReadsSamplersAndTheirDefaults) {
    const Scene scene = load("textured.gltf");
    ASSERT_EQ(scene.textures.size(), 2u);
    const SceneTexture& sampled = scene.textures[0]; // CLAMP_TO_EDGE, MIRRORED_REPEAT, NEAREST
    EXPECT_EQ(sampled.image, 0);
    EXPECT_EQ(sampled.wrapS, TextureWrap::ClampToEdge);
    EXPECT_EQ(sampled.wrapT, TextureWrap::MirroredRepeat);
    EXPECT_TRUE(sampled.nearest);
    const SceneTexture& plain = scene.textures[1]; // no sampler: REPEAT, bilinear
    EXPECT_EQ(plain.image, 0);
    EXPECT_EQ(plain.wrapS, TextureWrap::Repeat);
    EXPECT_EQ(plain.wrapT, TextureWrap::Repeat);
    EXPECT_FALSE(plain.nearest);
}

TEST(GltfTextures, MaterialsReferenceTheirTexturesWithoutTransform) {
    const Scene scene = load("textured.gltf");
    ASSERT_EQ(scene.materials.size(), 2u);
    const SceneMaterial& textured = scene.materials[0];
    EXPECT_EQ(textured.baseColorTexture.texture, 0);
    EXPECT_EQ(textured.metallicRoughnessTexture.texture, 1);
    EXPECT_EQ(textured.emissiveTexture.texture, -1);
    expectMatrix(textured.baseColorTexture.transform, glm::mat3(1.0f));
    const SceneMaterial& plain = scene.materials[1];
    EXPECT_EQ(plain.baseColorTexture.texture, -1);
    EXPECT_EQ(plain.metallicRoughnessTexture.texture, -1);
    EXPECT_EQ(plain.emissiveTexture.texture, -1);
}

TEST(GltfTextures, ReadsTexcoordsPerTriangleCornerInEveryLayout) {
    const Scene scene = load("textured.gltf");
    ASSERT_EQ(scene.triangleCount(), 5u);
    ASSERT_EQ(scene.texcoords.size(), 3 * scene.triangleCount());
    // The quad's two triangles, corners 0 1 2 and 0 2 3 (float).
    expectTexcoords(scene, 0, {{0, 0}, {1, 0}, {1, 1}});
    expectTexcoords(scene, 1, {{0, 0}, {1, 1}, {0, 1}});
    // No TEXCOORD_0: (0, 0).
    expectTexcoords(scene, 2, {{0, 0}, {0, 0}, {0, 0}});
    // Normalized UNSIGNED_BYTE (255, 0), (0, 255), (51, 102): c / 255.
    expectTexcoords(scene, 3, {{1, 0}, {0, 1}, {0.2f, 0.4f}});
    // Normalized UNSIGNED_SHORT (65535, 13107), (0, 0), (32768, 65535): c / 65535.
    expectTexcoords(scene, 4, {{1, 0.2f}, {0, 0}, {32768.0f / 65535.0f, 1}});
}

TEST(GltfTextures, ReadsAnImageFromAGlbBufferView) {
    const Scene scene = load("textured.glb");
    ASSERT_EQ(scene.images.size(), 1u);
    expectTheTestImage(scene.images[0]);
    ASSERT_EQ(scene.textures.size(), 1u);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].baseColorTexture.texture, 0);
    EXPECT_EQ(scene.materials[0].emissiveTexture.texture, 0);
    ASSERT_EQ(scene.texcoords.size(), 6u);
    expectTexcoords(scene, 1, {{0, 0}, {1, 1}, {0, 1}});
}

TEST(GltfTextures, SceneWithoutTexturesHasNoTexcoords) {
    for (const char* file : {"indices_u16.gltf", "materials.gltf", "lights.gltf", "spheres.gltf"}) {
        SCOPED_TRACE(file);
        const Scene scene = load(file);
        EXPECT_TRUE(scene.texcoords.empty());
        EXPECT_TRUE(scene.textures.empty());
        EXPECT_TRUE(scene.images.empty());
    }
}

// --- KHR_texture_transform -----------------------------------------------------------------

TEST(GltfTextureTransform, ComposesTranslationRotationScale) {
    // offset (0.5, 0.25), rotation π/2, scale (2, 3): u' = 3v + 0.5, v' = -2u + 0.25.
    const glm::mat3 m =
        gltf::textureTransformMatrix({0.5, 0.25}, std::numbers::pi / 2.0, {2.0, 3.0});
    expectMatrix(m, glm::mat3(0, -2, 0, 3, 0, 0, 0.5f, 0.25f, 1));
}

TEST(GltfTextureTransform, ExampleOfTheExtensionSelectsTheLowerLeftQuadrant) {
    // KHR_texture_transform's README: offset [0, 1], rotation π/2, scale [0.5, 0.5] "utilizes
    // only the lower left quadrant of the source image" (v points down the image).
    const glm::mat3 m =
        gltf::textureTransformMatrix({0.0, 1.0}, std::numbers::pi / 2.0, {0.5, 0.5});
    for (const glm::vec2 uv : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1),
                               glm::vec2(0.5f, 0.5f)}) {
        const glm::vec3 moved = m * glm::vec3(uv, 1.0f);
        EXPECT_GE(moved.x, -1e-6f);
        EXPECT_LE(moved.x, 0.5f + 1e-6f);
        EXPECT_GE(moved.y, 0.5f - 1e-6f);
        EXPECT_LE(moved.y, 1.0f + 1e-6f);
    }
    // The quad's centre goes to the quadrant's centre.
    expectNear(glm::vec2(m * glm::vec3(0.5f, 0.5f, 1.0f)), {0.25f, 0.75f});
}

TEST(GltfTextureTransform, IsReadFromTheFileAndItsTexCoordOverrides) {
    std::string notes;
    const Scene scene = load("texture_transform.gltf", &notes);
    EXPECT_EQ(notes, ""); // KHR_texture_transform is supported
    // One external image file, one texture, used twice.
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].name, "texture_3x2.png");
    expectTheTestImage(scene.images[0]);
    ASSERT_EQ(scene.textures.size(), 1u);
    const SceneMaterial& material = scene.materials[0];
    // textureInfo.texCoord 1, the extension's texCoord 0: TEXCOORD_0, scaled by 4.
    EXPECT_EQ(material.baseColorTexture.texture, 0);
    expectMatrix(material.baseColorTexture.transform, glm::mat3(4, 0, 0, 0, 4, 0, 0, 0, 1));
    EXPECT_EQ(material.emissiveTexture.texture, 0);
    expectMatrix(material.emissiveTexture.transform, glm::mat3(0, -2, 0, 3, 0, 0, 0.5f, 0.25f, 1));
}

// --- KHR_materials_specular ----------------------------------------------------------------

TEST(GltfSpecular, ReadsFactorsAndTextures) {
    std::string notes;
    const Scene scene = load("specular.gltf", &notes);
    EXPECT_EQ(notes, "");
    ASSERT_EQ(scene.materials.size(), 3u);
    // A specular texture multiplies specularFactor 0: still the Lambertian kind.
    const SceneMaterial& lambert = scene.materials[0];
    EXPECT_EQ(lambert.specular, 0.0f);
    EXPECT_EQ(lambert.specularColor, glm::vec3(1.0f));
    EXPECT_GE(lambert.specularTexture.texture, 0);
    EXPECT_TRUE(lambert.isDiffuseOnly());
    EXPECT_FALSE(lambert.hasSpecularTextures());
    const SceneMaterial& tinted = scene.materials[1];
    EXPECT_EQ(tinted.specular, 0.5f);
    EXPECT_EQ(tinted.specularColor, glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_FALSE(tinted.isDiffuseOnly());
    EXPECT_TRUE(tinted.hasSpecularTextures());
    EXPECT_GE(tinted.specularTexture.texture, 0);
    EXPECT_GE(tinted.specularColorTexture.texture, 0);
    expectMatrix(tinted.specularColorTexture.transform,
                 gltf::textureTransformMatrix({0.5, 0.0}, 0.0, {1.0, 1.0}));
    const SceneMaterial& core = scene.materials[2]; // no extension: the core model
    EXPECT_EQ(core.specular, 1.0f);
    EXPECT_EQ(core.specularColor, glm::vec3(1.0f));
    EXPECT_FALSE(core.isDiffuseOnly());
    EXPECT_FALSE(core.hasSpecularTextures());
    const SceneFeatures features = analyseScene(scene);
    EXPECT_TRUE(features.specularTextures);
    EXPECT_TRUE(features.kernelFeatures()[FEATURE_SPECULAR_TEXTURES]);
    // The device's specular lobe record carries both slots.
    const std::vector<gpu::SpecularLobeParams> device = makeGpuSpecularLobes(scene.materials);
    EXPECT_EQ(device[1].specularTexture.texture, std::uint32_t(tinted.specularTexture.texture));
    EXPECT_EQ(device[1].specularColorTexture.texture,
              std::uint32_t(tinted.specularColorTexture.texture));
    EXPECT_EQ(device[2].specularTexture.texture, NO_TEXTURE);
}

// The Khronos sample whose textures were dropped loads with nothing reported ignored.
TEST(GltfSpecular, SpecularTestSampleLoadsItsTextures) {
    const std::string path = VKPT_SCENES_DIR "/../../shared/scenes/SpecularTest/SpecularTest.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not present";
    std::string notes;
    const Scene scene = test::loadCapturingNotes(path, &notes);
    EXPECT_EQ(notes.find("ignoring"), std::string::npos) << notes;
    EXPECT_TRUE(analyseScene(scene).specularTextures);
}

// --- KHR_materials_transmission, KHR_materials_ior, KHR_materials_volume ---------------------

TEST(GltfGlass, ReadsTransmissionIorAndVolumeAndNotesTheThicknessTexture) {
    std::string notes;
    const Scene scene = load("glass.gltf", &notes);
    ASSERT_EQ(scene.materials.size(), 3u);
    const SceneMaterial& water = scene.materials[0];
    EXPECT_EQ(water.transmission, 0.8f);
    EXPECT_GE(water.transmissionTexture.texture, 0);
    EXPECT_EQ(water.ior, 1.33f);
    EXPECT_EQ(water.thickness, 0.5f);
    EXPECT_EQ(water.attenuationColor, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_EQ(water.attenuationDistance, 2.0f);
    EXPECT_FALSE(water.isDiffuseOnly());
    EXPECT_TRUE(water.usesDielectricExtensions());
    const SceneMaterial& plain = scene.materials[1]; // the extensions' defaults
    EXPECT_EQ(plain.transmission, 0.0f);
    EXPECT_LT(plain.transmissionTexture.texture, 0);
    EXPECT_EQ(plain.ior, 1.5f);
    EXPECT_EQ(plain.thickness, 0.0f);
    EXPECT_EQ(plain.attenuationColor, glm::vec3(1.0f));
    EXPECT_TRUE(std::isinf(plain.attenuationDistance));
    EXPECT_FALSE(plain.usesDielectricExtensions());
    EXPECT_EQ(scene.materials[2].ior, 1.5f); // ior 0: "not a dielectric", the default
    EXPECT_EQ(notes, kLoaderDir + "glass.gltf: ignoring the KHR_materials_volume "
                                  "thicknessTexture of 1 material (a rasteriser's hint: the path "
                                  "tracer measures thickness on the mesh)\n");
}

// The device record: F0 from the ior in double (0.04f exactly at 1.5, so opaque materials
// shade as before the extension), and σ = −ln(attenuationColor)/attenuationDistance.
TEST(GltfGlass, DeviceMaterialHoldsF0AndTheAttenuationCoefficient) {
    const Scene scene = load("glass.gltf");
    const std::vector<gpu::Material> device = makeGpuMaterials(scene.materials);
    const gpu::Material& water = device[0];
    EXPECT_EQ(water.transmission, 0.8f);
    EXPECT_EQ(water.ior, 1.33f);
    EXPECT_NEAR(water.iorF0, (0.33 / 2.33) * (0.33 / 2.33), 1e-7);
    EXPECT_EQ(water.thickness, 0.5f);
    EXPECT_NEAR(water.attenuationCoefficient.x, std::log(2.0) / 2.0, 1e-7);
    EXPECT_NEAR(water.attenuationCoefficient.y, std::log(4.0) / 2.0, 1e-7);
    EXPECT_EQ(water.attenuationCoefficient.z, 0.0f);
    EXPECT_NE(water.transmissionTexture.texture, NO_TEXTURE);
    const gpu::Material& plain = device[1];
    EXPECT_EQ(plain.iorF0, 0.04f);
    EXPECT_EQ(plain.attenuationCoefficient, glm::vec3(0.0f));
    EXPECT_EQ(plain.transmissionTexture.texture, NO_TEXTURE);
}

// The Khronos sample that motivated the extensions loads with none of them reported ignored.
TEST(GltfGlass, TransmissionTestSampleLoadsWithoutIgnoringTheExtensions) {
    const std::string path = VKPT_SCENES_DIR "/../../shared/scenes/TransmissionTest/"
                                             "TransmissionTest.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not present";
    testing::internal::CaptureStderr();
    const Scene scene = loadGltfScene(path);
    const std::string notes = testing::internal::GetCapturedStderr();
    for (const char* extension :
         {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume"})
        EXPECT_EQ(notes.find(extension), std::string::npos) << notes;
    const bool anyTransmits = std::any_of(scene.materials.begin(), scene.materials.end(),
                                          [](const SceneMaterial& m) { return m.transmits(); });
    EXPECT_TRUE(anyTransmits);
}

// --- KHR_lights_punctual -------------------------------------------------------------------

TEST(GltfLights, PlacesPointSpotAndDirectionalLightsByTheirNodes) {
    std::string notes;
    const Scene scene = load("lights.gltf", &notes);
    EXPECT_EQ(notes, "");
    ASSERT_EQ(scene.lights.size(), 3u);

    const SceneLight& point = scene.lights[0];
    EXPECT_EQ(point.name, "bulb");
    EXPECT_EQ(point.kind, LightKind::Point);
    expectNear(point.position, {1, 2, 3});
    expectNear(point.intensity, {10, 5, 2.5f}); // colour (1, .5, .25) × 10
    EXPECT_EQ(point.range, 5.0f);

    const SceneLight& spot = scene.lights[1];
    EXPECT_EQ(spot.kind, LightKind::Spot);
    expectNear(spot.position, {0, -1, 0});
    expectNear(spot.direction, {0, 1, 0}); // -Z turned 90 degrees about +X
    expectNear(spot.intensity, glm::vec3(100));
    EXPECT_EQ(spot.range, 0.0f); // unlimited
    EXPECT_EQ(spot.innerConeAngle, 0.25f);
    EXPECT_EQ(spot.outerConeAngle, 0.5f);

    const SceneLight& sun = scene.lights[2];
    EXPECT_EQ(sun.kind, LightKind::Directional);
    expectNear(sun.direction, {-1, 0, 0}); // -Z turned 90 degrees about +Y; scale 5 removed
    EXPECT_NEAR(glm::length(sun.direction), 1.0f, 1e-6f);
    expectNear(sun.intensity, glm::vec3(2));
}

// --- Metadata ---------------------------------------------------------------------------------

// XMP metadata (KHR_xmp_json_ld, and KHR_xmp as TransmissionTest.glb names it) describes the asset,
// not the image: a load that does not read it leaves nothing out, so no note names it; an
// extension that does change the image still does.
TEST(GltfExtensionList, MetadataIsNotReportedAsIgnored) {
    EXPECT_EQ(gltf::ignoredExtensions({"KHR_xmp_json_ld", "KHR_xmp", "KHR_materials_ior"}),
              std::vector<std::string>{});
    EXPECT_EQ(gltf::ignoredExtensions({"KHR_xmp", "KHR_physics_rigid_bodies"}),
              std::vector<std::string>{"KHR_physics_rigid_bodies"});
}

// --- KHR_implicit_shapes spheres -----------------------------------------------------------

TEST(GltfSpheres, PlacesSpheresByNodeTransformWithTheirMaterials) {
    std::string notes;
    const Scene scene = load("spheres.gltf", &notes);
    ASSERT_EQ(scene.spheres.size(), 2u);
    // vkpt's own reference: radius 0.5 × scale 2 at (1, 2, 3), extras.vkpt_material 1.
    expectNear(scene.spheres[0].centre, {1, 2, 3});
    EXPECT_FLOAT_EQ(scene.spheres[0].radius, 1.0f);
    EXPECT_EQ(scene.spheres[0].material, 1u);
    // A mesh-less collider, rotated and scaled by -3 under a parent at z = -10.
    expectNear(scene.spheres[1].centre, {0, 0, -10});
    EXPECT_FLOAT_EQ(scene.spheres[1].radius, 1.5f);
    ASSERT_EQ(scene.materials.size(), 3u); // floor, glowing, then the default material
    EXPECT_EQ(scene.spheres[1].material, 2u);
    EXPECT_EQ(scene.materials[2].name, "glTF default material");
    // The collider on the floor's node (it has a mesh), the box collider and the zero-scale
    // sphere are not drawn; the floor is.
    EXPECT_EQ(scene.triangleCount(), 2u);
    EXPECT_EQ(notes, kLoaderDir + "spheres.gltf: ignoring unsupported extensions: "
                                  "KHR_physics_rigid_bodies\n");
}

TEST(GltfSpheres, ASceneOfSpheresAloneLoads) {
    const Scene scene = load("sphere_only.gltf");
    EXPECT_EQ(scene.triangleCount(), 0u);
    ASSERT_EQ(scene.spheres.size(), 1u);
    EXPECT_EQ(scene.spheres[0].centre, glm::vec3(0.0f));
    EXPECT_EQ(scene.spheres[0].radius, 0.5f);
    ASSERT_EQ(scene.materials.size(), 1u); // the glTF default material
    EXPECT_EQ(scene.spheres[0].material, 0u);
}

TEST(GltfSpheres, BoundsIncludeTheSpheres) {
    const Scene scene = load("spheres.gltf");
    const Bounds bounds = computeBounds(scene);
    expectNear(bounds.min, {-1.5f, -1.5f, -11.5f});
    expectNear(bounds.max, {2, 3, 4});
}

TEST(GltfSpheres, RecentringMovesTrianglesSpheresAndLightsAlike) {
    // The extent of triangle, sphere and light together is centred at (1e6 + 0.25, 1.25, 1.25).
    std::string notes;
    const Scene scene = load("far_away.gltf", &notes);
    EXPECT_EQ(scene.worldOrigin, glm::dvec3(1e6 + 0.25, 1.25, 1.25));
    ASSERT_EQ(scene.triangleCount(), 1u);
    expectNear(scene.positions[0], {-0.25f, -1.25f, -1.25f});
    ASSERT_EQ(scene.spheres.size(), 1u);
    expectNear(scene.spheres[0].centre, {-0.25f, -1.25f, 0.75f});
    EXPECT_EQ(scene.spheres[0].radius, 0.5f);
    ASSERT_EQ(scene.lights.size(), 1u);
    expectNear(scene.lights[0].position, {-0.25f, 1.75f, -1.25f});
    EXPECT_NE(notes.find("the scene is centred at (1e+06, 1.25, 1.25)"), std::string::npos)
        << notes;
}

} // namespace
} // namespace vkpt::gltf_extensions_test
