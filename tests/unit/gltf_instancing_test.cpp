// gltf_instancing_test.cpp — meshes placed many times (nodes sharing a mesh,
// EXT_mesh_gpu_instancing): kept once and placed by instances, or flattened, as the instancing
// mode says; both give the same placed triangles.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "scene/gltf_instancing_plan.h"
#include "scene/gltf_loader.h"

namespace vkpt::gltf_instancing_test {
namespace {

const std::string kInstancingScene = VKPT_SCENES_DIR "/loader/instancing.gltf";
// shared_geometry.gltf: one triangle's accessors used by two meshes of different materials.
const std::string kSharedGeometryScene = VKPT_SCENES_DIR "/loader/shared_geometry.gltf";

// instancing.gltf: one triangle mesh placed 6 times (2 nodes, 1 mirrored node, 3
// EXT_mesh_gpu_instancing instances), an emissive quad mesh placed twice.
constexpr std::size_t kTrianglePlacements = 6;
constexpr std::size_t kLampTriangles = 2 * 2;

Scene load(Instancing mode) {
    LoadOptions options;
    options.instancing = mode;
    return loadGltfScene(kInstancingScene, options);
}

glm::vec3 place(const glm::dmat4& transform, const glm::vec3& p) {
    return glm::vec3(transform * glm::dvec4(glm::dvec3(p), 1.0));
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(GltfInstancing, OffFlattensEveryPlacement) {
    const Scene scene = load(Instancing::Off);
    EXPECT_TRUE(scene.meshes.empty());
    EXPECT_TRUE(scene.instances.empty());
    EXPECT_EQ(scene.triangleCount(), kTrianglePlacements + kLampTriangles);
    EXPECT_EQ(scene.placedTriangleCount(), scene.triangleCount());
}

TEST(GltfInstancing, OnKeepsTheMeshOnceAndFlattensTheEmitters) {
    const Scene scene = load(Instancing::On);
    ASSERT_EQ(scene.meshes.size(), 1u); // the lamp mesh emits: none of it is kept
    EXPECT_EQ(scene.meshes[0].triangleCount(), 1u);
    EXPECT_EQ(scene.meshes[0].name, "mesh 0 (triangle)");
    EXPECT_EQ(scene.instances.size(), kTrianglePlacements);
    EXPECT_EQ(scene.triangleCount(), kLampTriangles);
    for (std::uint32_t material : scene.materialIndices)
        EXPECT_TRUE(scene.materials[material].emits());
    EXPECT_EQ(scene.placedTriangleCount(), kTrianglePlacements + kLampTriangles);
    EXPECT_EQ(scene.storedTriangleCount(), 1u + kLampTriangles);
}

// Each instance's transform places the mesh's triangle where flattening put it (a mirrored
// placement with two corners swapped, so that its front face stays the front face).
TEST(GltfInstancing, InstancesPlaceTheVerticesFlatteningMakes) {
    const Scene flat = load(Instancing::Off);
    const Scene instanced = load(Instancing::On);
    ASSERT_EQ(instanced.instances.size(), kTrianglePlacements);
    const SceneMesh& mesh = instanced.meshes[0];
    for (std::size_t i = 0; i < kTrianglePlacements; ++i) {
        SCOPED_TRACE("placement " + std::to_string(i));
        const glm::dmat4& transform = instanced.instances[i].objectToWorld;
        const bool mirrored = glm::determinant(glm::dmat3(transform)) < 0.0;
        const int order[3] = {0, mirrored ? 2 : 1, mirrored ? 1 : 2};
        for (int k = 0; k < 3; ++k)
            expectNear(place(transform, mesh.positions[std::size_t(order[k])]),
                       flat.positions[3 * i + std::size_t(k)], 1e-6f);
    }
    EXPECT_TRUE(glm::determinant(glm::dmat3(instanced.instances[2].objectToWorld)) < 0.0);
}

// Instance 1 of the EXT_mesh_gpu_instancing node: T (2, 0, 0), R 90° about z (a normalized
// SHORT quaternion), S 2, under the node's translation (10, 0, 0): (1, 0, 0) → (12, 2, 0).
TEST(GltfInstancing, GpuInstancingComposesNodeTranslationRotationScale) {
    const Scene flat = load(Instancing::Off);
    const std::size_t triangle = 4; // plain, moved, mirrored, then the extension's three
    expectNear(flat.positions[3 * triangle + 0], {12.0f, 0.0f, 0.0f}, 1e-4f);
    expectNear(flat.positions[3 * triangle + 1], {12.0f, 2.0f, 0.0f}, 1e-4f);
    expectNear(flat.positions[3 * triangle + 2], {10.0f, 0.0f, 0.0f}, 1e-4f);
}

TEST(GltfInstancing, AutoFlattensASmallScene) {
    const Scene scene = load(Instancing::Auto);
    EXPECT_TRUE(scene.instances.empty());
    EXPECT_EQ(scene.triangleCount(), kTrianglePlacements + kLampTriangles);
}

TEST(GltfInstancing, BoundsOfInstancesHoldTheFlattenedBounds) {
    const Bounds flat = computeBounds(load(Instancing::Off));
    const Bounds instanced = computeBounds(load(Instancing::On));
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(instanced.min[axis], flat.min[axis] + 1e-6f);
        EXPECT_GE(instanced.max[axis], flat.max[axis] - 1e-6f);
    }
}

// A mesh a million units from its own origin is kept measured from its centre, so that rays in
// its space keep float precision, and its instances still place it where flattening does.
TEST(GltfInstancing, MeshFarFromItsOwnOriginIsRecentred) {
    LoadOptions options;
    options.instancing = Instancing::Off;
    const Scene flat = loadGltfScene(VKPT_SCENES_DIR "/loader/instancing_far.gltf", options);
    options.instancing = Instancing::On;
    const Scene instanced = loadGltfScene(VKPT_SCENES_DIR "/loader/instancing_far.gltf", options);
    ASSERT_EQ(instanced.meshes.size(), 1u);
    const SceneMesh& mesh = instanced.meshes[0];
    EXPECT_NEAR(mesh.origin.x, 1e6, 1.0);
    for (const glm::vec3& p : mesh.positions)
        EXPECT_LT(glm::length(p), 2.0f);
    ASSERT_EQ(instanced.instances.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t k = 0; k < 3; ++k)
            expectNear(place(instanced.instances[i].objectToWorld, mesh.positions[k]),
                       flat.positions[3 * i + k], 1e-6f);
}

// The plan counts placements and triangles from the node tree and accessor counts alone.
TEST(GltfInstancingPlan, CountsPlacementsAndTriangles) {
    tinygltf::Model model;
    tinygltf::TinyGLTF io;
    std::string error, warning;
    ASSERT_TRUE(io.LoadASCIIFromFile(&model, &error, &warning, kInstancingScene)) << error;
    const std::vector<SceneMaterial> materials = loadGltfScene(kInstancingScene, {}).materials;
    const gltf::InstancingPlan plan = gltf::planInstancing(model, 0, Instancing::Auto, materials);
    ASSERT_EQ(plan.placements.size(), 2u);
    EXPECT_EQ(plan.placements[0], kTrianglePlacements);
    EXPECT_EQ(plan.placements[1], 2u);
    EXPECT_EQ(plan.meshTriangles[0], 1u);
    EXPECT_EQ(plan.meshTriangles[1], 2u);
    EXPECT_EQ(plan.placedTriangles, kTrianglePlacements + kLampTriangles);
    EXPECT_FALSE(plan.isInstanced(0)); // saves far less than kInstancingMinSavedBytes
    EXPECT_TRUE(gltf::planInstancing(model, 0, Instancing::On, materials).isInstanced(0));
    EXPECT_FALSE(gltf::planInstancing(model, 0, Instancing::Off, materials).isInstanced(0));
}

// A model of meshes that refer to accessors by index only (the plan reads no data): each
// primitive (indices, POSITION, material), every mesh placed once by a node of scene 0.
struct PrimitiveSpec {
    int indices;
    int position;
    int material;
};

tinygltf::Model modelOfMeshes(const std::vector<std::vector<PrimitiveSpec>>& meshes,
                              std::size_t trianglesPerAccessor) {
    tinygltf::Model model;
    for (int a = 0; a < 3; ++a) {
        tinygltf::Accessor accessor;
        accessor.count = 3 * trianglesPerAccessor;
        model.accessors.push_back(accessor);
    }
    tinygltf::Scene scene;
    for (const std::vector<PrimitiveSpec>& specs : meshes) {
        tinygltf::Mesh mesh;
        for (const PrimitiveSpec& spec : specs) {
            tinygltf::Primitive primitive;
            primitive.indices = spec.indices;
            primitive.attributes["POSITION"] = spec.position;
            primitive.material = spec.material;
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            mesh.primitives.push_back(primitive);
        }
        tinygltf::Node node;
        node.mesh = static_cast<int>(model.meshes.size());
        scene.nodes.push_back(static_cast<int>(model.nodes.size()));
        model.nodes.push_back(node);
        model.meshes.push_back(mesh);
    }
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    return model;
}

// Meshes that share their index and POSITION accessors are one geometry whatever their one
// material, alpha-masked ones apart from the others (the triangle marks that the walk tests its
// alpha); meshes of several primitives share only with the same materials, in the same order;
// emitters do not count.
TEST(GltfGeometryGrouping, GroupsMeshesByAccessors) {
    std::vector<SceneMaterial> materials(5);
    materials[2].alphaMode = AlphaMode::Mask;
    materials[3].alphaMode = AlphaMode::Mask;
    materials[4].emission = glm::vec3(1.0f);
    const tinygltf::Model model = modelOfMeshes(
        {
            {{0, 1, 0}},            // 0
            {{0, 1, 1}},            // 1: 0's geometry, another material
            {{0, 1, 2}},            // 2: masked
            {{0, 1, 3}},            // 3: 2's geometry, masked otherwise
            {{0, 2, 0}},            // 4: other positions
            {{0, 1, 1}, {0, 2, 4}}, // 5: 0's geometry and an emitter
            {{0, 1, 0}, {0, 2, 1}}, // 6
            {{0, 1, 0}, {0, 2, 1}}, // 7: 6's
            {{0, 1, 1}, {0, 2, 0}}, // 8: 6's geometry, other materials
            {{0, 2, 4}},            // 9: emits only: nothing kept
        },
        20000);
    const gltf::InstancingPlan plan = gltf::planInstancing(model, 0, Instancing::Auto, materials);
    EXPECT_EQ(plan.geometry, (std::vector<int>{0, 0, 2, 2, 4, 0, 6, 6, 8, -1}));
    // Auto: 0's geometry is placed 3 times, 2's and 6's twice, each saving megabytes; the others
    // once.
    EXPECT_EQ(plan.instanced, (std::vector<char>{1, 1, 1, 1, 0, 1, 1, 1, 0, 0}));
    // 1,000 triangles placed twice save 115 kB, under kInstancingMinSavedBytes: flattened.
    const gltf::InstancingPlan small = gltf::planInstancing(
        modelOfMeshes({{{0, 1, 0}}, {{0, 1, 1}}}, 1000), 0, Instancing::Auto, materials);
    EXPECT_EQ(small.geometry, (std::vector<int>{0, 0}));
    EXPECT_EQ(small.instanced, (std::vector<char>{0, 0}));
}

// Loaded, meshes of one geometry share one kept copy; an instance of another mesh than the
// copy's carries its own material.
TEST(GltfGeometryGrouping, InstancesCarryTheirMaterial) {
    LoadOptions options;
    options.instancing = Instancing::On;
    const Scene scene = loadGltfScene(kSharedGeometryScene, options);
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.instances[0].material, SceneInstance::kKeepMaterial);
    EXPECT_EQ(scene.instances[1].material, 1u);
    EXPECT_EQ(scene.meshes[0].materialIndices[0], 0u);
}

} // namespace
} // namespace vkpt::gltf_instancing_test
