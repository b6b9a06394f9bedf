// gltf_writer.h — glTF files made by the tests and benchmarks: for what only the loader
// decides (degenerate vertex data, scenes placed far from the origin through the node tree),
// and generated benchmark scenes that every renderer reads from the same file. Written with
// tinygltf; buffers embedded as data URIs, or in a .bin file beside a large scene.
#pragma once

#include <algorithm>

#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scratch_directory.h"

namespace vkpt::test {

// A mesh of one primitive: positions, optional vertex normals and texture coordinates,
// triangle indices.
struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; // empty: none in the file
    std::vector<glm::vec2> uvs;     // TEXCOORD_0; empty: none in the file
    std::vector<std::uint32_t> indices;
    int material = 0;
};

class GltfWriter {
public:
    GltfWriter() {
        model_.asset.version = "2.0";
        model_.asset.generator = "vkpt tests";
        model_.buffers.emplace_back();
        model_.scenes.emplace_back();
        model_.defaultScene = 0;
    }

    // A texture whose image is `png` (a PNG file's bytes), stored in the buffer.
    int addPngTexture(const std::vector<unsigned char>& png) {
        tinygltf::Image image;
        image.bufferView = addView(png.data(), png.size(), 0);
        image.mimeType = "image/png";
        model_.images.push_back(image);
        tinygltf::Texture texture;
        texture.source = int(model_.images.size() - 1);
        model_.textures.push_back(texture);
        return int(model_.textures.size() - 1);
    }

    // baseColorTexture: a texture of addPngTexture, read at TEXCOORD_0; -1 for none.
    int addMaterial(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f),
                    int baseColorTexture = -1) {
        tinygltf::Material m;
        m.pbrMetallicRoughness.baseColorFactor = {albedo.x, albedo.y, albedo.z, 1.0};
        m.pbrMetallicRoughness.baseColorTexture.index = baseColorTexture;
        m.pbrMetallicRoughness.metallicFactor = 0.0;
        // The core emissiveFactor stays in [0, 1]; brighter emitters carry the rest in
        // KHR_materials_emissive_strength, as the specification asks.
        const double strength =
            std::max({1.0, double(emission.x), double(emission.y), double(emission.z)});
        m.emissiveFactor = {emission.x / strength, emission.y / strength, emission.z / strength};
        if (strength > 1.0) {
            tinygltf::Value::Object emissive;
            emissive["emissiveStrength"] = tinygltf::Value(strength);
            m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(emissive);
            addExtensionUsed("KHR_materials_emissive_strength");
        }
        // specularFactor 0: the Lambertian "diffuse" kind the extreme-case answers assume.
        tinygltf::Value::Object specular;
        specular["specularFactor"] = tinygltf::Value(0.0);
        m.extensions["KHR_materials_specular"] = tinygltf::Value(specular);
        addExtensionUsed("KHR_materials_specular");
        model_.materials.push_back(m);
        return int(model_.materials.size() - 1);
    }

    // A mesh of one primitive, placed by no node yet; its index.
    int addMeshData(const MeshData& data) {
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = data.material;
        primitive.attributes["POSITION"] = addVec3Accessor(data.positions);
        if (!data.normals.empty()) primitive.attributes["NORMAL"] = addVec3Accessor(data.normals);
        if (!data.uvs.empty()) primitive.attributes["TEXCOORD_0"] = addVec2Accessor(data.uvs);
        primitive.indices = addIndexAccessor(data.indices);
        tinygltf::Mesh mesh;
        mesh.primitives.push_back(primitive);
        model_.meshes.push_back(mesh);
        return int(model_.meshes.size() - 1);
    }

    // A node with the mesh under the scene root.
    void addMesh(const MeshData& data) {
        tinygltf::Node node;
        node.mesh = addMeshData(data);
        addRootNode(node);
    }

    // A node placing mesh `mesh` by translation × rotation × scale (rotation x, y, z, w).
    void addMeshNode(int mesh, glm::vec3 translation = glm::vec3(0.0f),
                     glm::vec4 rotation = glm::vec4(0, 0, 0, 1),
                     glm::vec3 scale = glm::vec3(1.0f)) {
        tinygltf::Node node;
        node.mesh = mesh;
        node.translation = {translation.x, translation.y, translation.z};
        node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
        node.scale = {scale.x, scale.y, scale.z};
        addRootNode(node);
    }

    // A node placing mesh `mesh` once per element of EXT_mesh_gpu_instancing's TRANSLATION,
    // ROTATION (x, y, z, w) and SCALE, which must be of one length.
    void addInstancedMeshNode(int mesh, const std::vector<glm::vec3>& translations,
                              const std::vector<glm::vec4>& rotations,
                              const std::vector<glm::vec3>& scales) {
        tinygltf::Value::Object attributes;
        attributes["TRANSLATION"] = tinygltf::Value(addVec3Accessor(translations));
        attributes["ROTATION"] = tinygltf::Value(addVec4Accessor(rotations));
        attributes["SCALE"] = tinygltf::Value(addVec3Accessor(scales));
        tinygltf::Value::Object extension;
        extension["attributes"] = tinygltf::Value(attributes);
        tinygltf::Node node;
        node.mesh = mesh;
        node.extensions["EXT_mesh_gpu_instancing"] = tinygltf::Value(extension);
        addExtensionUsed("EXT_mesh_gpu_instancing");
        addRootNode(node);
    }

    // A perspective camera at `position` looking down −z (glTF's camera convention), turned by
    // `rotation` (x, y, z, w).
    void addCamera(glm::vec3 position, double yfovRadians,
                   glm::vec4 rotation = glm::vec4(0, 0, 0, 1)) {
        tinygltf::Camera camera;
        camera.type = "perspective";
        camera.perspective.yfov = yfovRadians;
        camera.perspective.znear = 0.001;
        model_.cameras.push_back(camera);
        tinygltf::Node node;
        node.camera = int(model_.cameras.size() - 1);
        node.translation = {position.x, position.y, position.z};
        if (rotation != glm::vec4(0, 0, 0, 1))
            node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
        addRootNode(node);
    }

    // Embedded: one self-contained .gltf (base64 data URIs, 4/3 the size). Separate: the
    // buffer in <name>.bin beside the .gltf, as exporters write large scenes.
    enum class Buffers { Embedded, Separate };

    void write(const std::string& path, Buffers buffers = Buffers::Embedded) {
        writeModel(model_, path, buffers);
    }

    void addExtensionUsed(const std::string& name) {
        auto& used = model_.extensionsUsed;
        if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
    }

    static void writeModel(tinygltf::Model& model, const std::string& path,
                           Buffers buffers = Buffers::Embedded) {
        tinygltf::TinyGLTF io;
        const bool embedBuffers = buffers == Buffers::Embedded;
        if (!io.WriteGltfSceneToFile(&model, path, false, embedBuffers, false, false))
            throw std::runtime_error("cannot write " + path);
    }

private:
    void addRootNode(const tinygltf::Node& node) {
        model_.nodes.push_back(node);
        model_.scenes[0].nodes.push_back(int(model_.nodes.size() - 1));
    }

    int addView(const void* bytes, std::size_t size, int target) {
        std::vector<unsigned char>& data = model_.buffers[0].data;
        while (data.size() % 4 != 0)
            data.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = data.size();
        view.byteLength = size;
        view.target = target; // 0: none (an image's bytes)
        data.resize(data.size() + size);
        std::memcpy(data.data() + view.byteOffset, bytes, size);
        model_.bufferViews.push_back(view);
        return int(model_.bufferViews.size() - 1);
    }

    int addVec3Accessor(const std::vector<glm::vec3>& values) {
        tinygltf::Accessor accessor;
        accessor.bufferView =
            addView(values.data(), values.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size();
        accessor.type = TINYGLTF_TYPE_VEC3;
        model_.accessors.push_back(accessor);
        return int(model_.accessors.size() - 1);
    }

    int addVec2Accessor(const std::vector<glm::vec2>& values) {
        tinygltf::Accessor accessor;
        accessor.bufferView =
            addView(values.data(), values.size() * sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size();
        accessor.type = TINYGLTF_TYPE_VEC2;
        model_.accessors.push_back(accessor);
        return int(model_.accessors.size() - 1);
    }

    int addVec4Accessor(const std::vector<glm::vec4>& values) {
        tinygltf::Accessor accessor;
        accessor.bufferView = addView(values.data(), values.size() * sizeof(glm::vec4), 0);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        accessor.count = values.size();
        accessor.type = TINYGLTF_TYPE_VEC4;
        model_.accessors.push_back(accessor);
        return int(model_.accessors.size() - 1);
    }

    int addIndexAccessor(const std::vector<std::uint32_t>& indices) {
        tinygltf::Accessor accessor;
        accessor.bufferView = addView(indices.data(), indices.size() * sizeof(std::uint32_t),
                                      TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        accessor.count = indices.size();
        accessor.type = TINYGLTF_TYPE_SCALAR;
        model_.accessors.push_back(accessor);
        return int(model_.accessors.size() - 1);
    }

    tinygltf::Model model_;
};

// The glTF file at `source` with all its root nodes moved under one new root node translated
// by `offset` (exactly as a double in the file): the scene and its camera, far from the origin,
// with the vertex data unchanged.
inline void writeTranslatedCopy(const std::string& source, const std::string& target,
                                glm::dvec3 offset) {
    tinygltf::Model model;
    tinygltf::TinyGLTF io;
    std::string error, warning;
    if (!io.LoadASCIIFromFile(&model, &error, &warning, source))
        throw std::runtime_error("cannot read " + source + ": " + error);
    tinygltf::Node root;
    root.name = "translated root";
    root.translation = {offset.x, offset.y, offset.z};
    tinygltf::Scene& scene = model.scenes.at(std::size_t(std::max(model.defaultScene, 0)));
    root.children = scene.nodes;
    model.nodes.push_back(root);
    scene.nodes = {int(model.nodes.size() - 1)};
    GltfWriter::writeModel(model, target);
}

// The glTF file at `source` with every POSITION moved by `offset` in float arithmetic, as an
// exporter that writes world-space vertices far from the origin would store them (quantised to
// the float grid there), and every camera node moved by the same offset (in double, as the file
// writes it). Every POSITION accessor must be tightly packed floats.
inline void writeQuantisedCopy(const std::string& source, const std::string& target,
                               glm::vec3 offset) {
    tinygltf::Model model;
    tinygltf::TinyGLTF io;
    std::string error, warning;
    if (!io.LoadASCIIFromFile(&model, &error, &warning, source))
        throw std::runtime_error("cannot read " + source + ": " + error);
    for (tinygltf::Mesh& mesh : model.meshes)
        for (tinygltf::Primitive& primitive : mesh.primitives) {
            tinygltf::Accessor& accessor =
                model.accessors.at(std::size_t(primitive.attributes.at("POSITION")));
            const tinygltf::BufferView& view =
                model.bufferViews.at(std::size_t(accessor.bufferView));
            if (view.byteStride != 0 && view.byteStride != sizeof(glm::vec3))
                throw std::runtime_error(source + ": interleaved positions");
            unsigned char* bytes = model.buffers.at(std::size_t(view.buffer)).data.data() +
                                   view.byteOffset + accessor.byteOffset;
            glm::vec3 lo(1e38f), hi(-1e38f);
            for (std::size_t i = 0; i < accessor.count; ++i) {
                glm::vec3 p;
                std::memcpy(&p, bytes + i * sizeof(glm::vec3), sizeof(p));
                p += offset;
                std::memcpy(bytes + i * sizeof(glm::vec3), &p, sizeof(p));
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            accessor.minValues = {lo.x, lo.y, lo.z};
            accessor.maxValues = {hi.x, hi.y, hi.z};
        }
    for (tinygltf::Node& node : model.nodes) {
        if (node.camera < 0) continue;
        if (node.translation.empty()) node.translation = {0.0, 0.0, 0.0};
        for (int k = 0; k < 3; ++k)
            node.translation[std::size_t(k)] += double(offset[k]);
    }
    GltfWriter::writeModel(model, target);
}

// A file name in the test process's scratch directory.
inline std::string testFilePath(const std::string& name) {
    return scratchPath("extremes_" + name);
}

} // namespace vkpt::test
