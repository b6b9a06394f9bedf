// instanced_scene.cpp — writes the instancing test scene with tinygltf.
#include "instanced_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include "bvh/synthetic_scenes.h"

namespace vkpt::test {

namespace {

constexpr float kSpacing = 2.5f; // between placements' centres
constexpr std::uint32_t kBoxCells = 2;

class Writer {
public:
    Writer() {
        model_.asset.version = "2.0";
        model_.asset.generator = "vkpt tests: instanced scene";
        model_.buffers.emplace_back();
        model_.scenes.emplace_back();
        model_.defaultScene = 0;
    }

    int material(glm::vec3 albedo, glm::vec3 emission, float metallic, float roughness) {
        tinygltf::Material m;
        m.pbrMetallicRoughness.baseColorFactor = {albedo.x, albedo.y, albedo.z, 1.0};
        m.pbrMetallicRoughness.metallicFactor = metallic;
        m.pbrMetallicRoughness.roughnessFactor = roughness;
        const double strength =
            std::max({1.0, double(emission.x), double(emission.y), double(emission.z)});
        m.emissiveFactor = {emission.x / strength, emission.y / strength, emission.z / strength};
        if (strength > 1.0) {
            tinygltf::Value::Object emissive;
            emissive["emissiveStrength"] = tinygltf::Value(strength);
            m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(emissive);
            used("KHR_materials_emissive_strength");
        }
        model_.materials.push_back(m);
        return int(model_.materials.size() - 1);
    }

    // A mesh of one primitive from a soup of three positions per triangle (flat normals, which
    // the loader generates).
    int mesh(const std::vector<glm::vec3>& soup, int material) {
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = material;
        primitive.attributes["POSITION"] = vec3Accessor(soup, true);
        tinygltf::Mesh mesh;
        mesh.primitives.push_back(primitive);
        model_.meshes.push_back(mesh);
        return int(model_.meshes.size() - 1);
    }

    void node(int mesh, glm::vec3 translation, glm::quat rotation, glm::vec3 scale) {
        tinygltf::Node node;
        node.mesh = mesh;
        node.translation = {translation.x, translation.y, translation.z};
        node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
        node.scale = {scale.x, scale.y, scale.z};
        root(node);
    }

    void instancedNode(int mesh, const std::vector<glm::vec3>& translations,
                       const std::vector<glm::quat>& rotations,
                       const std::vector<glm::vec3>& scales) {
        std::vector<glm::vec4> quaternions;
        for (const glm::quat& q : rotations)
            quaternions.emplace_back(q.x, q.y, q.z, q.w);
        tinygltf::Value::Object attributes;
        attributes["TRANSLATION"] = tinygltf::Value(vec3Accessor(translations, false));
        attributes["ROTATION"] = tinygltf::Value(vec4Accessor(quaternions));
        attributes["SCALE"] = tinygltf::Value(vec3Accessor(scales, false));
        tinygltf::Value::Object extension;
        extension["attributes"] = tinygltf::Value(attributes);
        tinygltf::Node node;
        node.mesh = mesh;
        node.extensions["EXT_mesh_gpu_instancing"] = tinygltf::Value(extension);
        used("EXT_mesh_gpu_instancing");
        root(node);
    }

    void camera(glm::vec3 position, glm::quat rotation) {
        tinygltf::Camera camera;
        camera.type = "perspective";
        camera.perspective.yfov = 0.8;
        camera.perspective.znear = 0.01;
        model_.cameras.push_back(camera);
        tinygltf::Node node;
        node.camera = int(model_.cameras.size() - 1);
        node.translation = {position.x, position.y, position.z};
        node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
        root(node);
    }

    void write(const std::string& path, bool separateBuffer) {
        tinygltf::TinyGLTF io;
        if (!io.WriteGltfSceneToFile(&model_, path, false, !separateBuffer, true, false))
            throw std::runtime_error("cannot write " + path);
    }

private:
    void used(const char* name) {
        for (const std::string& u : model_.extensionsUsed)
            if (u == name) return;
        model_.extensionsUsed.emplace_back(name);
    }

    void root(const tinygltf::Node& node) {
        model_.nodes.push_back(node);
        model_.scenes[0].nodes.push_back(int(model_.nodes.size() - 1));
    }

    int view(const void* bytes, std::size_t size, int target) {
        std::vector<unsigned char>& data = model_.buffers[0].data;
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = size;
        view.target = target;
        data.resize(data.size() + size);
        std::memcpy(data.data() + view.byteOffset, bytes, size);
        model_.bufferViews.push_back(view);
        return int(model_.bufferViews.size() - 1);
    }

    // POSITION accessors carry min and max, as glTF requires.
    int vec3Accessor(const std::vector<glm::vec3>& values, bool positions) {
        tinygltf::Accessor accessor;
        accessor.bufferView = view(values.data(), values.size() * sizeof(glm::vec3),
                                   positions ? TINYGLTF_TARGET_ARRAY_BUFFER : 0);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size();
        accessor.type = TINYGLTF_TYPE_VEC3;
        if (positions) {
            glm::vec3 lo(values[0]), hi(values[0]);
            for (const glm::vec3& v : values) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            accessor.minValues = {lo.x, lo.y, lo.z};
            accessor.maxValues = {hi.x, hi.y, hi.z};
        }
        model_.accessors.push_back(accessor);
        return int(model_.accessors.size() - 1);
    }

    int vec4Accessor(const std::vector<glm::vec4>& values) {
        tinygltf::Accessor accessor;
        accessor.bufferView = view(values.data(), values.size() * sizeof(glm::vec4), 0);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size();
        accessor.type = TINYGLTF_TYPE_VEC4;
        model_.accessors.push_back(accessor);
        return int(model_.accessors.size() - 1);
    }

    tinygltf::Model model_;
};

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
    Writer w;
    const int floorMaterial = w.material(glm::vec3(0.6f), glm::vec3(0.0f), 0.0f, 1.0f);
    const int lightMaterial = w.material(glm::vec3(0.0f), glm::vec3(12.0f), 0.0f, 1.0f);
    const int sphereMaterial =
        w.material(glm::vec3(0.8f, 0.75f, 0.6f), glm::vec3(0.0f), 0.0f, 0.6f);
    const int boxMaterial = w.material(glm::vec3(0.7f, 0.3f, 0.25f), glm::vec3(0.0f), 0.3f, 0.4f);

    const float half = 0.5f * kSpacing * float(std::max(spec.columns, spec.rows)) + 2.0f;
    w.node(w.mesh(quad({-half, 0, -half}, {-half, 0, half}, {half, 0, half}, {half, 0, -half}),
                  floorMaterial),
           glm::vec3(0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    // One emissive mesh, facing down, placed twice.
    const int light = w.mesh(quad({-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}), lightMaterial);
    const float height = 0.6f * half + 3.0f;
    w.node(light, glm::vec3(-0.3f * half, height, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));
    w.node(light, glm::vec3(0.3f * half, height, 0.0f), glm::quat(1, 0, 0, 0), glm::vec3(1.0f));

    const int sphere =
        w.mesh(synthetic::displacedSphere(spec.rings, 2 * spec.rings), sphereMaterial);
    const int box = w.mesh(centredBox(), boxMaterial);
    std::vector<glm::vec3> translations, scales;
    std::vector<glm::quat> rotations;
    const std::uint32_t count = spec.columns * spec.rows;
    for (std::uint32_t i = 0; i < count; ++i) {
        const Placement p = placementOf(spec, i);
        const bool isSphere = i % 2 == 0;
        // Spheres of radius ~1.05 (displaced): half the size of a box of side 1.
        const glm::vec3 scale = isSphere ? 0.5f * p.scale : p.scale;
        if (isSphere && spec.gpuInstancing && (i / 2) % 2 == 1) {
            translations.push_back(p.translation);
            rotations.push_back(p.rotation);
            scales.push_back(scale);
            continue;
        }
        w.node(isSphere ? sphere : box, p.translation, p.rotation, scale);
    }
    if (!translations.empty()) w.instancedNode(sphere, translations, rotations, scales);
    // Above the near edge, looking down at the field's centre.
    const glm::vec3 eye(0.0f, 0.55f * half + 2.0f, 1.1f * half + 2.0f);
    const glm::vec3 forward = glm::normalize(-eye);
    const glm::quat look = glm::quatLookAtRH(forward, glm::vec3(0, 1, 0));
    w.camera(eye, look);
    w.write(path, spec.separateBuffer);
}

} // namespace vkpt::test
