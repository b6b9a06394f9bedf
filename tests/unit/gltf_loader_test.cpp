// gltf_loader_test.cpp — the glTF loader on small generated files (each way of storing geometry),
// on broken files (each must give one exact InputError line) and on the shared real scenes.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/errors.h"
#include "scene/gltf_loader.h"

namespace vkpt::gltf_loader_test {
namespace {

const std::string kLoaderDir = VKPT_SCENES_DIR "/loader/";
const std::string kInvalidDir = VKPT_SCENES_DIR "/invalid/";
const std::string kSharedScenesDir = VKPT_SCENES_DIR "/../../shared/scenes/";

constexpr float kTolerance = 1e-6f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = kTolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "component x";
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "component y";
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "component z";
}

// The corners of triangle t, in the order the scene stores them.
std::vector<glm::vec3> corners(const Scene& scene, std::size_t t) {
    return {scene.positions[3 * t], scene.positions[3 * t + 1], scene.positions[3 * t + 2]};
}

void expectTriangle(const Scene& scene, std::size_t t, const std::vector<glm::vec3>& expected) {
    const std::vector<glm::vec3> actual = corners(scene, t);
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE("triangle " + std::to_string(t) + ", corner " + std::to_string(i));
        expectNear(actual[i], expected[i]);
    }
}

// The side from which the corners run counter-clockwise: the triangle's front face.
glm::vec3 frontNormal(const Scene& scene, std::size_t t) {
    const std::vector<glm::vec3> p = corners(scene, t);
    return glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
}

void expectNormals(const Scene& scene, std::size_t t, const glm::vec3& expected) {
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE("triangle " + std::to_string(t) + ", corner " + std::to_string(i));
        expectNear(scene.normals[3 * t + i], expected);
    }
}

void expectSizesConsistent(const Scene& scene) {
    EXPECT_EQ(scene.positions.size(), 3 * scene.triangleCount());
    EXPECT_EQ(scene.normals.size(), 3 * scene.triangleCount());
    const bool normalMapped = std::any_of(scene.materials.begin(), scene.materials.end(),
                                          [](const SceneMaterial& m) { return m.hasNormalMap(); });
    EXPECT_EQ(scene.tangents.size(), normalMapped ? 3 * scene.triangleCount() : 0);
    for (std::uint32_t material : scene.materialIndices)
        EXPECT_LT(material, scene.materials.size());
}

// "indices_u8.gltf" -> "IndicesU8", a test name.
std::string camelCaseStem(const std::string& file) {
    std::string name;
    bool upper = true;
    for (char c : std::filesystem::path(file).stem().string()) {
        if (c == '_') {
            upper = true;
            continue;
        }
        name += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
        upper = false;
    }
    return name;
}

// --- Valid files: the unit quad stored in several ways -------------------------------------

class GltfLoaderQuad : public testing::TestWithParam<const char*> {};

TEST_P(GltfLoaderQuad, LoadsTheUnitQuadFacingPlusZ) {
    const Scene scene = loadGltfScene(kLoaderDir + GetParam());
    expectSizesConsistent(scene);
    ASSERT_EQ(scene.triangleCount(), 2u);
    expectTriangle(scene, 0, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    expectTriangle(scene, 1, {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    expectNear(frontNormal(scene, 0), {0, 0, 1});
    expectNear(frontNormal(scene, 1), {0, 0, 1});
    ASSERT_EQ(scene.materials.size(), 1u); // the glTF default material
    EXPECT_EQ(scene.materialIndices, (std::vector<std::uint32_t>{0, 0}));
}

INSTANTIATE_TEST_SUITE_P(IndexTypes, GltfLoaderQuad,
                         testing::Values("indices_u8.gltf", "indices_u16.gltf", "indices_u32.gltf",
                                         "non_indexed.gltf", "interleaved.gltf"),
                         [](const testing::TestParamInfo<const char*>& test) {
                             return camelCaseStem(test.param);
                         });

TEST(GltfLoader, KeepsGivenNormalsOfTheQuad) {
    const Scene scene = loadGltfScene(kLoaderDir + "indices_u16.gltf");
    expectNormals(scene, 0, {0, 0, 1});
    expectNormals(scene, 1, {0, 0, 1});
}

TEST(GltfLoader, ReadsASparseAccessorOverItsBufferView) {
    // The unit triangle's vertex 1 replaced by (2, 0, 0) (glTF 2.0, section 3.6.2.3).
    const Scene scene = loadGltfScene(kLoaderDir + "sparse.gltf");
    ASSERT_EQ(scene.triangleCount(), 1u);
    expectTriangle(scene, 0, {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}});
}

TEST(GltfLoader, ReadsInterleavedVerticesWithByteStride) {
    // Per vertex: position, normal, one padding float (1234.5); stride 28, normals at byte 12.
    const Scene scene = loadGltfScene(kLoaderDir + "interleaved.gltf");
    const glm::vec3 vertexNormals[4] = {
        {0, 0, 1}, {0, 0.6f, 0.8f}, {0.6f, 0, 0.8f}, {0.8f, 0, 0.6f}};
    const int quadIndices[6] = {0, 1, 2, 0, 2, 3};
    ASSERT_EQ(scene.normals.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) {
        SCOPED_TRACE("corner " + std::to_string(i));
        expectNear(scene.normals[i], vertexNormals[quadIndices[i]]);
    }
}

TEST(GltfLoader, GeneratesFlatNormalsWhenAbsent) {
    const Scene scene = loadGltfScene(kLoaderDir + "no_normals.gltf");
    ASSERT_EQ(scene.triangleCount(), 1u);
    expectNormals(scene, 0, glm::vec3(1.0f) / std::sqrt(3.0f));
}

TEST(GltfLoader, ReadsBinaryGlb) {
    const Scene scene = loadGltfScene(kLoaderDir + "binary.glb");
    ASSERT_EQ(scene.triangleCount(), 2u);
    expectTriangle(scene, 0, {{0, 0, -2}, {1, 0, -2}, {1, 1, -2}});
    expectTriangle(scene, 1, {{0, 0, -2}, {1, 1, -2}, {0, 1, -2}});
}

// --- Transforms ----------------------------------------------------------------------------

TEST(GltfLoader, MirroringTransformKeepsTheFrontFaceAndNormalsTogether) {
    // One triangle facing +Z: plain, mirrored in x (given normals), mirrored in z (flat normals).
    const Scene scene = loadGltfScene(kLoaderDir + "negative_scale.gltf");
    ASSERT_EQ(scene.triangleCount(), 3u);
    expectTriangle(scene, 0, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    expectTriangle(scene, 1, {{0, 0, 0}, {0, 1, 0}, {-1, 0, 0}}); // two corners swapped
    expectTriangle(scene, 2, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}});
    expectNear(frontNormal(scene, 1), {0, 0, 1}); // mirroring x leaves the front facing +Z
    expectNormals(scene, 1, {0, 0, 1});
    expectNear(frontNormal(scene, 2), {0, 0, -1}); // mirroring z turns the front to -Z
    expectNormals(scene, 2, {0, 0, -1});
}

TEST(GltfLoader, TrsAndMatrixGiveTheSameWorldPositions) {
    // translation (1, 2, 3), 90 degrees about +Y, scale 2: (x, y, z) -> (1 + 2z, 2 + 2y, 3 - 2x)
    const Scene scene = loadGltfScene(kLoaderDir + "transforms.gltf");
    ASSERT_EQ(scene.triangleCount(), 3u);
    expectTriangle(scene, 0, {{1, 2, 1}, {1, 4, 3}, {3, 2, 3}});
    expectTriangle(scene, 1, {{1, 2, 1}, {1, 4, 3}, {3, 2, 3}});
}

TEST(GltfLoader, AppliesTheChildTransformBeforeTheParents) {
    // child: 90 degrees about +Z, (x, y, z) -> (-y, x, z); parent: translation (10, 0, 0)
    const Scene scene = loadGltfScene(kLoaderDir + "transforms.gltf");
    ASSERT_EQ(scene.triangleCount(), 3u);
    expectTriangle(scene, 2, {{10, 1, 0}, {9, 0, 0}, {10, 0, 1}});
}

TEST(GltfLoader, LoadsTheSceneTheFileNamesAsDefault) {
    const Scene scene = loadGltfScene(kLoaderDir + "default_scene.gltf");
    ASSERT_EQ(scene.triangleCount(), 1u); // only scene 1's node, translated to z = 5
    expectTriangle(scene, 0, {{0, 0, 5}, {1, 0, 5}, {0, 1, 5}});
}

// --- Materials -----------------------------------------------------------------------------

TEST(GltfLoader, ReadsMaterialFactorsAndAddsTheDefaultMaterialLast) {
    const Scene scene = loadGltfScene(kLoaderDir + "materials.gltf");
    ASSERT_EQ(scene.materials.size(), 5u);
    EXPECT_EQ(scene.materialIndices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));

    const SceneMaterial& defaults = scene.materials[0];
    EXPECT_EQ(defaults.name, "defaults");
    EXPECT_EQ(defaults.baseColor, glm::vec4(1.0f));
    EXPECT_EQ(defaults.metallic, 1.0f);
    EXPECT_EQ(defaults.roughness, 1.0f);
    EXPECT_EQ(defaults.emission, glm::vec3(0.0f));
    EXPECT_FALSE(defaults.doubleSided);
    EXPECT_EQ(defaults.alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(defaults.alphaCutoff, 0.5f);

    const SceneMaterial& factors = scene.materials[1];
    EXPECT_EQ(factors.baseColor, glm::vec4(0.5f, 0.25f, 0.125f, 0.75f));
    EXPECT_EQ(factors.metallic, 0.25f);
    EXPECT_EQ(factors.roughness, 0.5f);
    EXPECT_TRUE(factors.doubleSided);
    EXPECT_EQ(factors.alphaMode, AlphaMode::Mask);
    EXPECT_EQ(factors.alphaCutoff, 0.25f);

    EXPECT_EQ(scene.materials[2].emission, glm::vec3(4.0f, 2.0f, 1.0f)); // (1, .5, .25) x 4
    EXPECT_EQ(scene.materials[3].alphaMode, AlphaMode::Blend);

    const SceneMaterial& fallback = scene.materials[4];
    EXPECT_EQ(fallback.baseColor, glm::vec4(1.0f));
    EXPECT_EQ(fallback.metallic, 1.0f);
    EXPECT_EQ(fallback.roughness, 1.0f);
    EXPECT_EQ(fallback.emission, glm::vec3(0.0f));
}

// --- Messages on stderr --------------------------------------------------------------------

TEST(GltfLoader, ListsUnsupportedExtensionsOnceInOneLine) {
    const std::string path = kLoaderDir + "extensions.gltf";
    testing::internal::CaptureStderr();
    loadGltfScene(path);
    EXPECT_EQ(testing::internal::GetCapturedStderr(),
              path +
                  ": ignoring unsupported extensions: EXT_lights_image_based, NV_materials_mdl\n");
}

TEST(GltfLoader, OptionSilencesTheUnsupportedExtensionNote) {
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    testing::internal::CaptureStderr();
    loadGltfScene(kLoaderDir + "extensions.gltf", options);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

// --- Broken files: one exact line each -----------------------------------------------------

struct InvalidCase {
    const char* behaviour; // the test's name
    const char* file;      // in scenes/invalid/
    const char* message;   // after "<path>: "
};

const InvalidCase kInvalidCases[] = {
    {"MissingFile", "does_not_exist.gltf", "cannot open the file: No such file or directory"},
    {"EmptyFile", "empty.glb", "the file is empty"},
    {"TextIsNotJson", "not_gltf.gltf",
     "not a glTF file: invalid JSON (parse error at line 1, column 1: syntax error while parsing "
     "value - invalid literal; last read: 'T')"},
    {"GlbWithoutMagic", "garbage.glb", "not a glTF file: a .glb file starts with 'glTF'"},
    {"JsonWithoutAsset", "no_asset.gltf", "not a glTF file: no \"asset\" object"},
    {"TruncatedGlb", "truncated.glb",
     "truncated .glb: its header says 780 bytes but the file has 390"},
    {"MissingExternalBuffer", "missing_buffer.gltf",
     "cannot find the buffer file 'missing_buffer.bin'"},
    {"ExternalBufferShorterThanByteLength", "short_buffer.gltf",
     "the buffer file 'short_buffer.bin' has 68 bytes but the buffer's byteLength is 80"},
    {"GlbBinChunkShorterThanByteLength", "short_bin_chunk.glb",
     "a buffer's byteLength 144 exceeds the .glb BIN chunk (80 bytes)"},
    {"BufferViewOutOfBuffer", "buffer_view_out_of_range.gltf",
     "buffer view 0: byteOffset 100 + byteLength 40 exceeds buffer 0 (80 bytes)"},
    {"AccessorOutOfBufferView", "accessor_out_of_range.gltf",
     "mesh 0, primitive 0: POSITION: accessor 0 reads past the end of buffer view 0: 4 elements "
     "of 12 bytes at stride 12 from byte 0 need 48 bytes, the view has 36"},
    {"StrideSmallerThanElement", "stride_too_small.gltf",
     "mesh 0, primitive 0: POSITION: accessor 0: byteStride 8 of buffer view 0 is smaller than "
     "its 12-byte elements"},
    {"IndexOutOfRange", "index_out_of_range.gltf",
     "mesh 1, primitive 1: index 3 >= vertex count 3"},
    {"NonFinitePosition", "nan_position.gltf",
     "mesh 0, primitive 0: vertex 2 has a non-finite position"},
    {"PointsMode", "points_mode.gltf",
     "mesh 0, primitive 0: mode POINTS is not supported, only TRIANGLES"},
    {"PositionNotFloat", "position_not_float.gltf",
     "mesh 0, primitive 0: POSITION: accessor 0 is VEC3 of UNSIGNED_SHORT, expected VEC3 of "
     "FLOAT"},
    {"IndicesNotInteger", "indices_not_integer.gltf",
     "mesh 0, primitive 0: indices: accessor 1 is SCALAR of FLOAT, expected SCALAR of "
     "UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT"},
    {"NoPosition", "no_position.gltf", "mesh 0, primitive 0: no POSITION attribute"},
    {"SparseIndexOutOfRange", "sparse_index_out_of_range.gltf",
     "mesh 0, primitive 0: POSITION: accessor 0: sparse index 5 >= count 3"},
    {"NoTriangles", "no_triangles.gltf", "the scene has no triangles"},
    {"UnsupportedRequiredExtension", "required_extension.gltf",
     "required extensions KHR_texture_basisu, EXT_lights_image_based are not supported (convert "
     "the KTX2 textures to PNG, JPEG or WebP)"},
    {"InstancingAttributeCountsDiffer", "instancing_count_mismatch.gltf",
     "node 0: EXT_mesh_gpu_instancing: SCALE has 2 elements, TRANSLATION 3"},
    {"InstancingWithoutAttributes", "instancing_without_attributes.gltf",
     "node 0: EXT_mesh_gpu_instancing: no attributes (TRANSLATION, ROTATION or SCALE)"},
    {"InstancingZeroRotation", "instancing_zero_rotation.gltf",
     "node 0: EXT_mesh_gpu_instancing: instance 1 has a zero or non-finite ROTATION"},
    {"InstancingRotationUnsigned", "instancing_rotation_unsigned.gltf",
     "node 0: EXT_mesh_gpu_instancing ROTATION: accessor 4 is VEC4 of UNSIGNED_BYTE, expected "
     "VEC4 of FLOAT, BYTE or SHORT"},
    {"NodeCycle", "node_cycle.gltf", "node 0: the node hierarchy has a cycle"},
    {"MissingNode", "missing_node.gltf", "scene 0: node 7 does not exist (the file has 2 nodes)"},
    {"MissingMaterial", "missing_material.gltf",
     "mesh 0, primitive 0: material 3 does not exist (the file has 2 materials)"},
    {"PartialTriangle", "partial_triangle.gltf",
     "mesh 0, primitive 0: 4 indices do not make whole triangles"},
    {"NormalCountMismatch", "normal_count_mismatch.gltf",
     "mesh 0, primitive 0: NORMAL has 2 elements but POSITION has 3"},
    {"MissingAccessor", "missing_accessor.gltf",
     "mesh 0, primitive 0: POSITION: accessor 7 does not exist (the file has 3 accessors)"},
    {"VariantOutOfRange", "variant_out_of_range.gltf",
     "mesh 0, primitive 0: KHR_materials_variants: mapping 0: variants[1] is not the index of "
     "one of the file's 1 variants"},
    {"UnknownLightType", "light_type.gltf",
     "light 0: type 'area' is not point, spot or directional"},
    {"TransmissionOutOfRange", "transmission_out_of_range.gltf",
     "material 0: KHR_materials_transmission: transmissionFactor must be in [0, 1]"},
    {"IorBelowOne", "ior_below_one.gltf", "material 0: KHR_materials_ior: ior must be >= 1 (or 0)"},
    {"DispersionNegative", "dispersion_negative.gltf",
     "material 0: KHR_materials_dispersion: dispersion must be a finite number >= 0"},
    {"DiffuseTransmissionOutOfRange", "diffuse_transmission_out_of_range.gltf",
     "material 0: KHR_materials_diffuse_transmission: diffuseTransmissionFactor must be in [0, "
     "1]"},
    {"AttenuationDistanceZero", "attenuation_distance_zero.gltf",
     "material 0: KHR_materials_volume: attenuationDistance must be > 0"},
    {"NegativeLightIntensity", "light_negative_intensity.gltf",
     "light 0: intensity must not be negative"},
    {"SpotInnerConeWiderThanOuter", "light_spot_cone.gltf",
     "light 0: spot innerConeAngle 0.75 exceeds outerConeAngle 0.5"},
    {"SphereUnderNonUniformScale", "sphere_non_uniform_scale.gltf",
     "node 1: sphere under non-uniform scale (1, 2, 1)"},
    {"TextureWithoutSource", "texture_without_source.gltf",
     "material 0: baseColorTexture: texture 0 has only a KHR_texture_basisu image, which vkpt "
     "does not decode; convert it to PNG, JPEG or WebP"},
    {"UndecodableImage", "image_undecodable.gltf",
     "image 0: cannot decode the PNG data (bad zlib header)"},
    {"ImageNotPngOrJpeg", "image_not_png.gltf",
     "image 0: not a PNG, JPEG or WebP image (the formats glTF 2.0 and EXT_texture_webp "
     "allow)"},
    {"MissingImageFile", "missing_image.gltf",
     "image 0: cannot find the image file 'missing_image.png'"},
    {"CorruptDracoData", "draco_corrupt.gltf",
     "mesh 0, primitive 0: KHR_draco_mesh_compression: the Draco data does not decode (Input is "
     "not a mesh.)"},
    {"TruncatedMeshoptStream", "meshopt_truncated.gltf",
     "buffer view 0: EXT_meshopt_compression: the compressed data does not decode (the stream is "
     "truncated or malformed)"},
    {"MeshoptFilterOnWrongStride", "meshopt_filter_stride.gltf",
     "buffer view 0: EXT_meshopt_compression: the filter does not apply to this mode and "
     "byteStride"},
    {"UncompressedViewOnMeshoptFallback", "meshopt_fallback_read.gltf",
     "buffer view 0 reads the EXT_meshopt_compression fallback buffer 1 without decoding, and "
     "that buffer holds no data"},
    {"QuantizedNormalNotNormalized", "quantized_normal_not_normalized.gltf",
     "mesh 0, primitive 0: NORMAL: accessor 2 is VEC3 of BYTE but not normalized, as normals "
     "must be"},
    {"UndecodableWebp", "webp_undecodable.gltf", "image 0: cannot decode the WebP data"},
    {"TextureOnTexcoord1", "texcoord_1.gltf",
     "material 0: baseColorTexture: reads TEXCOORD_1; only TEXCOORD_0 is supported"},
    {"SkinJointOutOfRange", "skin_joint_out_of_range.gltf",
     "mesh 0, primitive 0: vertex 1: joint 3 is out of range (the skin has 2 joints)"},
    {"SkinJointNotANode", "skin_joint_not_a_node.gltf",
     "skin 0: joint 1 is node 9, which does not exist (the file has 3 nodes)"},
    {"SkinWithTooFewBindMatrices", "skin_bind_matrix_count.gltf",
     "skin 0: inverseBindMatrices has 2 matrices for 3 joints"},
    {"SkinnedPrimitiveWithoutJoints", "skin_without_joints.gltf",
     "mesh 0, primitive 0: the node has a skin but the primitive has no JOINTS_0 and WEIGHTS_0"},
    {"SkinnedVertexWithoutWeight", "skin_zero_weights.gltf",
     "mesh 0, primitive 0: vertex 2 has no non-zero skin weight"},
    {"MissingSkin", "skin_missing.gltf", "node 0: skin 4 does not exist (the file has 1 skin)"},
    {"MorphWeightsUnlikeTargets", "morph_weight_count.gltf",
     "mesh 0, primitive 0: 3 morph weights for 2 morph targets"},
    {"AnimationTimesGoBack", "animation_times_decrease.gltf",
     "animation 0, sampler 0: input times do not increase at keyframe 2"},
    {"AnimationOutputTooLong", "animation_output_count.gltf",
     "animation 0, sampler 0: output has 9 numbers, 2 keyframes need 6"},
    {"AnimationInterpolationUnknown", "animation_interpolation.gltf",
     "animation 0, sampler 0: interpolation 'SMOOTH' is not one of LINEAR, STEP, CUBICSPLINE"},
    {"AnimationOnMatrixNode", "animation_matrix_node.gltf",
     "animation 0, channel 0: node 0 has a matrix, which animations may not target (only TRS)"},
    {"AnimationOfMissingNode", "animation_missing_node.gltf",
     "animation 0, channel 0: node 5 does not exist (the file has 2 nodes)"},
    {"WeightsAnimationWithoutTargets", "animation_weights_without_targets.gltf",
     "animation 0, channel 0: node 0 has no mesh with morph targets for its weights"},
};

class GltfLoaderRejects : public testing::TestWithParam<InvalidCase> {};

TEST_P(GltfLoaderRejects, WithOneLineNamingTheFileAndPlace) {
    const std::string path = kInvalidDir + GetParam().file;
    testing::internal::CaptureStderr();
    try {
        loadGltfScene(path);
        ADD_FAILURE() << path << " loaded";
    } catch (const InputError& error) {
        EXPECT_EQ(error.what(), path + ": " + GetParam().message);
    }
    // A failed load says nothing else: the caller prints the one line.
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

INSTANTIATE_TEST_SUITE_P(InvalidFiles, GltfLoaderRejects, testing::ValuesIn(kInvalidCases),
                         [](const testing::TestParamInfo<InvalidCase>& test) {
                             return std::string(test.param.behaviour);
                         });

TEST(GltfLoaderRejects, EveryFileInTheInvalidFolderHasACase) {
    for (const auto& entry : std::filesystem::directory_iterator(kInvalidDir)) {
        const std::string name = entry.path().filename().string();
        const std::string extension = entry.path().extension().string();
        if (extension != ".gltf" && extension != ".glb") continue; // README, short_buffer.bin
        const bool covered = std::any_of(std::begin(kInvalidCases), std::end(kInvalidCases),
                                         [&](const InvalidCase& c) { return name == c.file; });
        EXPECT_TRUE(covered) << name << " has no expected message";
    }
}

// --- The shared real-world scenes ----------------------------------------------------------

struct SharedScene {
    const char* name; // the test's name
    const char* file; // under shared/scenes/
    std::size_t triangles;
    glm::vec3 boundsMin;
    glm::vec3 boundsMax;
    std::size_t cameras;
    std::size_t emissiveMaterials;
    std::size_t images; // decoded: those the materials' base colour, MR, emissive, normal and
                        // transmission slots use
    std::size_t normalMapped = 0; // materials with a normal texture
};

// Figures from shared/scenes/README.md (bounds printed there with six significant digits).
const SharedScene kSharedScenes[] = {
    {"Box", "Box/Box.glb", 12, {-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, 0, 0, 0},
    {"EmissiveStrengthTest",
     "EmissiveStrengthTest/EmissiveStrengthTest.glb",
     90,
     {-8.00261f, -6.00107f, -2.0f},
     {8.00111f, 4.0094f, 1.99893f},
     0,
     5,
     1},
    {"CornellBox",
     "CornellBox/cornellBox.gltf",
     16732,
     {-5.05f, -5.05f, -5.05f},
     {5.05f, 5.05f, 5.0f},
     1,
     1,
     0},
    {"DamagedHelmet",
     "DamagedHelmet/DamagedHelmet.glb",
     15452,
     {-0.947459f, -0.900974f, -1.18716f},
     {0.942495f, 0.900995f, 0.812845f},
     0,
     1,
     4,
     1},
    {"ToyCar",
     "ToyCar/ToyCar.gltf",
     108936,
     {-0.0349951f, -0.0162063f, -0.0369811f},
     {0.0384478f, 0.0126166f, 0.0369811f},
     8,
     1,
     7, // 6 for the core slots, 1 more for KHR_materials_clearcoat's clearcoatTexture
     2},
    {"TransmissionTest",
     "TransmissionTest/TransmissionTest.glb",
     128775,
     {-0.976367f, -0.4f, -0.521006f},
     {0.826243f, 0.620546f, 1.36801f},
     1,
     1,
     9}, // 8 for the core slots, 1 more for KHR_materials_transmission's transmissionTexture
};

std::size_t emissiveMaterialCount(const Scene& scene) {
    return static_cast<std::size_t>(
        std::count_if(scene.materials.begin(), scene.materials.end(),
                      [](const SceneMaterial& m) { return m.emission != glm::vec3(0.0f); }));
}

class GltfLoaderSharedScene : public testing::TestWithParam<SharedScene> {
protected:
    void SetUp() override {
        if (!std::filesystem::is_directory(kSharedScenesDir)) {
            GTEST_SKIP() << "shared scenes not found at " << kSharedScenesDir;
        }
    }
};

TEST_P(GltfLoaderSharedScene, MatchesTheCountsAndBoundsOfTheReadme) {
    const SharedScene& expected = GetParam();
    LoadOptions quiet;
    quiet.warnUnsupportedExtensions = false;
    const Scene scene = loadGltfScene(kSharedScenesDir + expected.file, quiet);
    expectSizesConsistent(scene);
    // The README counts the file's triangles (placed: some are kept once, "Shared geometry");
    // the loader leaves out those of zero area.
    EXPECT_EQ(scene.placedTriangleCount() + scene.repairs.zeroAreaTriangles, expected.triangles);
    EXPECT_EQ(scene.cameras.size(), expected.cameras);
    EXPECT_EQ(emissiveMaterialCount(scene), expected.emissiveMaterials);
    EXPECT_EQ(scene.images.size(), expected.images);
    for (const SceneImage& image : scene.images)
        EXPECT_EQ(image.texels.size(), std::size_t(image.width) * image.height) << image.name;
    // TEXCOORD_0 per triangle corner exactly when some texture is read.
    EXPECT_EQ(scene.texcoords.size(), expected.images > 0 ? 3 * scene.triangleCount() : 0);
    const Bounds bounds = computeBounds(scene);
    const float tolerance = 1e-5f * glm::length(expected.boundsMax - expected.boundsMin);
    expectNear(bounds.min, expected.boundsMin, tolerance);
    expectNear(bounds.max, expected.boundsMax, tolerance);
}

// Normal textures are honoured: read, with a tangent frame (unit, orthogonal to the shading
// normal, w = ±1) at every corner of a normal-mapped triangle, and no note that one is ignored.
TEST_P(GltfLoaderSharedScene, HonoursNormalTextures) {
    const SharedScene& expected = GetParam();
    testing::internal::CaptureStderr();
    const Scene scene = loadGltfScene(kSharedScenesDir + expected.file);
    const std::string notes = testing::internal::GetCapturedStderr();
    // (Not "normal" alone: a checkout's path may contain the word.)
    EXPECT_EQ(notes.find("normal map"), std::string::npos) << notes;
    EXPECT_EQ(notes.find("normalTexture"), std::string::npos) << notes;
    const auto mapped =
        std::size_t(std::count_if(scene.materials.begin(), scene.materials.end(),
                                  [](const SceneMaterial& m) { return m.hasNormalMap(); }));
    EXPECT_EQ(mapped, expected.normalMapped);
    if (mapped == 0) return;
    ASSERT_EQ(scene.tangents.size(), scene.positions.size());
    std::size_t checked = 0;
    for (std::size_t c = 0; c < scene.tangents.size(); ++c) {
        if (!scene.materials[scene.materialIndices[c / 3]].hasNormalMap()) continue;
        const glm::vec4& t = scene.tangents[c];
        ASSERT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-4f) << "corner " << c;
        ASSERT_NEAR(glm::dot(glm::vec3(t), scene.normals[c]), 0.0f, 1e-4f) << "corner " << c;
        ASSERT_TRUE(t.w == 1.0f || t.w == -1.0f) << "corner " << c;
        ++checked;
    }
    EXPECT_GT(checked, 0u);
}

INSTANTIATE_TEST_SUITE_P(SharedScenes, GltfLoaderSharedScene, testing::ValuesIn(kSharedScenes),
                         [](const testing::TestParamInfo<SharedScene>& test) {
                             return std::string(test.param.name);
                         });

TEST(GltfLoaderEmissiveStrength, ScalesEmissionByOneToSixteen) {
    const std::string path = kSharedScenesDir + "EmissiveStrengthTest/EmissiveStrengthTest.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
    const Scene scene = loadGltfScene(path);
    const glm::vec3 factor(0.1f, 0.5f, 0.9f); // every cube's emissiveFactor
    std::vector<float> strengths;
    for (const SceneMaterial& material : scene.materials) {
        if (material.emission == glm::vec3(0.0f)) continue;
        const float strength = material.emission.y / factor.y;
        expectNear(material.emission, factor * strength, 1e-5f);
        strengths.push_back(strength);
    }
    std::sort(strengths.begin(), strengths.end());
    ASSERT_EQ(strengths.size(), 5u);
    const float expected[5] = {1, 2, 4, 8, 16};
    for (std::size_t i = 0; i < 5; ++i)
        EXPECT_NEAR(strengths[i], expected[i], 1e-5f);
}

} // namespace
} // namespace vkpt::gltf_loader_test
