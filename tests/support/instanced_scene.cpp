// instanced_scene.cpp — writes the instancing test scene with the tests' glTF writer.
#include "instanced_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "bvh/synthetic_scenes.h"
#include "gltf_writer.h"

namespace vkpt::test {

namespace {

constexpr float kSpacing = 2.5f; // between placements' centres
constexpr std::uint32_t kBoxCells = 2;

// A mesh of a soup of three positions per triangle (flat normals, which the loader generates).
MeshData soupMesh(std::vector<glm::vec3> soup, int material) {
    MeshData mesh;
    mesh.indices.resize(soup.size());
    std::iota(mesh.indices.begin(), mesh.indices.end(), 0u);
    mesh.positions = std::move(soup);
    mesh.material = material;
    return mesh;
}

std::vector<glm::vec3> quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    return {a, b, c, a, c, d};
}

// The unit-size box, centred at the origin (closedCube spans [0, cells]).
std::vector<glm::vec3> centredBox() {
    std::vector<glm::vec3> box = synthetic::closedCube(kBoxCells);
    for (glm::vec3& p : box)
        p = p / float(kBoxCells) - glm::vec3(0.5f);
    return box;
}

glm::vec4 xyzw(const glm::quat& q) {
    return {q.x, q.y, q.z, q.w};
}

// Placement i of the grid: where, turned how far, scaled how (mirrored in x for every third
// when asked). Sizes stay under the spacing, so no two placements overlap.
struct Placement {
    glm::vec3 translation;
    glm::quat rotation;
    glm::vec3 scale;
};

Placement placementOf(const InstancedSceneSpec& spec, std::uint32_t i) {
    synthetic::Rng rng(1000 + i);
    const std::uint32_t column = i % spec.columns, row = i / spec.columns;
    const float size = rng.uniform(0.7f, 1.0f);
    const float angle = rng.uniform(0.0f, 2.0f * std::numbers::pi_v<float>);
    Placement p;
    p.scale = glm::vec3(size, size * rng.uniform(0.8f, 1.2f), size);
    if (spec.mirrored && i % 3 == 2) p.scale.x = -p.scale.x;
    p.rotation = glm::angleAxis(angle, glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::vec2 centre =
        0.5f * kSpacing * glm::vec2(float(spec.columns) - 1.0f, float(spec.rows) - 1.0f);
    p.translation = glm::vec3(float(column) * kSpacing - centre.x, 0.5f * std::abs(p.scale.y),
                              float(row) * kSpacing - centre.y);
    return p;
}

std::uint64_t sphereTriangles(const InstancedSceneSpec& spec) {
    return 4ull * spec.rings * spec.rings;
}

} // namespace

std::uint64_t instancedScenePlacedTriangles(const InstancedSceneSpec& spec) {
    const std::uint64_t placements = std::uint64_t(spec.columns) * spec.rows;
    const std::uint64_t spheres = (placements + 1) / 2, boxes = placements / 2;
    const std::uint64_t boxTriangles = 12ull * kBoxCells * kBoxCells;
    return 2 + 2 * 2 + spheres * sphereTriangles(spec) + boxes * boxTriangles;
}

void writeInstancedScene(const InstancedSceneSpec& spec, const std::string& path) {
    GltfWriter w;
    const int floorMaterial = w.addMaterial(glm::vec3(0.6f));
    const int lightMaterial = w.addMaterial(glm::vec3(0.0f), glm::vec3(12.0f));
    const int sphereMaterial = w.addMaterial(glm::vec3(0.8f, 0.75f, 0.6f));
    const int boxMaterial = w.addMaterial(glm::vec3(0.7f, 0.3f, 0.25f));

    const float half = 0.5f * kSpacing * float(std::max(spec.columns, spec.rows)) + 2.0f;
    w.addMesh(soupMesh(quad({-half, 0, -half}, {-half, 0, half}, {half, 0, half}, {half, 0, -half}),
                       floorMaterial));
    // One emissive mesh, facing down, placed twice.
    const int light = w.addMeshData(
        soupMesh(quad({-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}), lightMaterial));
    const float height = 0.6f * half + 3.0f;
    w.addMeshNode(light, glm::vec3(-0.3f * half, height, 0.0f));
    w.addMeshNode(light, glm::vec3(0.3f * half, height, 0.0f));

    const int sphere = w.addMeshData(
        soupMesh(synthetic::displacedSphere(spec.rings, 2 * spec.rings), sphereMaterial));
    const int box = w.addMeshData(soupMesh(centredBox(), boxMaterial));
    std::vector<glm::vec3> translations, scales;
    std::vector<glm::vec4> rotations;
    const std::uint32_t count = spec.columns * spec.rows;
    for (std::uint32_t i = 0; i < count; ++i) {
        const Placement p = placementOf(spec, i);
        const bool isSphere = i % 2 == 0;
        // Spheres of radius ~1.05 (displaced): half the size of a box of side 1.
        const glm::vec3 scale = isSphere ? 0.5f * p.scale : p.scale;
        if (isSphere && spec.gpuInstancing && (i / 2) % 2 == 1) {
            translations.push_back(p.translation);
            rotations.push_back(xyzw(p.rotation));
            scales.push_back(scale);
            continue;
        }
        w.addMeshNode(isSphere ? sphere : box, p.translation, xyzw(p.rotation), scale);
    }
    if (!translations.empty()) w.addInstancedMeshNode(sphere, translations, rotations, scales);
    // Above the near edge, looking down at the field's centre.
    const glm::vec3 eye(0.0f, 0.55f * half + 2.0f, 1.1f * half + 2.0f);
    const glm::quat look = glm::quatLookAtRH(glm::normalize(-eye), glm::vec3(0, 1, 0));
    w.addCamera(eye, 0.8, xyzw(look));
    w.write(path,
            spec.separateBuffer ? GltfWriter::Buffers::Separate : GltfWriter::Buffers::Embedded);
}

} // namespace vkpt::test
