// gltf_draco.cpp — finds the compressed bytes of a KHR_draco_mesh_compression primitive, decodes
// them into a draco::Mesh and reads its attributes per point (Draco's points are the glTF
// vertices; its faces, the triangles).
#include "scene/gltf_draco.h"

#include <memory>

#include <draco/compression/decode.h>

#include "scene/gltf_document.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kDraco = "KHR_draco_mesh_compression";

std::string_view viewBytes(const tinygltf::Model& model, int viewIndex, const std::string& where) {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model.bufferViews.size()) {
        throw GltfProblem(where + ": buffer view " + std::to_string(viewIndex) +
                          " does not exist (the file has " +
                          std::to_string(model.bufferViews.size()) + " buffer views)");
    }
    // checkBufferViews has placed the view inside its buffer.
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
    const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    return {reinterpret_cast<const char*>(data.data()) + view.byteOffset, view.byteLength};
}

std::unique_ptr<draco::Mesh> decodeMesh(std::string_view bytes, const std::string& where) {
    draco::DecoderBuffer buffer;
    buffer.Init(bytes.data(), bytes.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) {
        throw GltfProblem(where + ": the Draco data does not decode (" +
                          decoded.status().error_msg_string() + ")");
    }
    std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (!mesh) throw GltfProblem(where + ": the Draco data holds no mesh");
    return mesh;
}

// The extension's attribute id for `name`, or nullopt when it does not list the attribute.
std::optional<std::uint32_t> attributeId(const tinygltf::Value& extension, const char* name,
                                         const std::string& where) {
    const tinygltf::Value* attributes = findMember(extension, "attributes");
    if (attributes == nullptr) return std::nullopt;
    const int id = readIndex(*attributes, name, where + ": attributes");
    if (id < 0) return std::nullopt;
    return static_cast<std::uint32_t>(id);
}

// Attribute `id`'s value at every point as N floats (integers converted, normalized ones to
// [0, 1] or [−1, 1] as their flag says).
template <int N>
std::vector<glm::vec<N, float>> readAttribute(const draco::Mesh& mesh, std::uint32_t id,
                                              const char* name, const std::string& where) {
    const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id);
    if (attribute == nullptr) {
        throw GltfProblem(where + ": " + name + ": the Draco data has no attribute " +
                          std::to_string(id));
    }
    if (attribute->num_components() < N) {
        throw GltfProblem(where + ": " + name + ": Draco attribute " + std::to_string(id) +
                          " has " + std::to_string(attribute->num_components()) +
                          " components, expected " + std::to_string(N));
    }
    std::vector<glm::vec<N, float>> values(mesh.num_points());
    for (draco::PointIndex::ValueType p = 0; p < mesh.num_points(); ++p) {
        const draco::AttributeValueIndex value = attribute->mapped_index(draco::PointIndex(p));
        if (value.value() >= attribute->size() ||
            !attribute->ConvertValue<float>(value, N, &values[p][0])) {
            throw GltfProblem(where + ": " + name + ": Draco attribute " + std::to_string(id) +
                              " has no value for point " + std::to_string(p));
        }
    }
    return values;
}

std::vector<std::uint32_t> readFaces(const draco::Mesh& mesh, const std::string& where) {
    std::vector<std::uint32_t> indices;
    indices.reserve(std::size_t(mesh.num_faces()) * 3);
    for (draco::FaceIndex::ValueType f = 0; f < mesh.num_faces(); ++f) {
        for (const draco::PointIndex& corner : mesh.face(draco::FaceIndex(f))) {
            if (corner.value() >= mesh.num_points()) {
                throw GltfProblem(where + ": Draco face " + std::to_string(f) + " names point " +
                                  std::to_string(corner.value()) + " of " +
                                  std::to_string(mesh.num_points()));
            }
            indices.push_back(corner.value());
        }
    }
    return indices;
}

} // namespace

bool isDracoPrimitive(const tinygltf::Primitive& primitive) {
    return findExtension(primitive.extensions, kDraco) != nullptr;
}

DracoPrimitive decodeDracoPrimitive(const tinygltf::Model& model,
                                    const tinygltf::Primitive& primitive, bool withTexcoords,
                                    const std::string& where) {
    const std::string place = where + ": " + kDraco;
    const tinygltf::Value& extension = *findExtension(primitive.extensions, kDraco);
    const int view = readIndex(extension, "bufferView", place);
    const std::unique_ptr<draco::Mesh> mesh = decodeMesh(viewBytes(model, view, place), place);
    DracoPrimitive decoded;
    const std::optional<std::uint32_t> position = attributeId(extension, "POSITION", place);
    if (!position) throw GltfProblem(place + ": no POSITION attribute");
    decoded.positions = readAttribute<3>(*mesh, *position, "POSITION", place);
    if (const auto normal = attributeId(extension, "NORMAL", place)) {
        decoded.normals = readAttribute<3>(*mesh, *normal, "NORMAL", place);
    }
    if (const auto texcoord = attributeId(extension, "TEXCOORD_0", place);
        texcoord && withTexcoords) {
        decoded.texcoords = readAttribute<2>(*mesh, *texcoord, "TEXCOORD_0", place);
    }
    decoded.indices = readFaces(*mesh, place);
    return decoded;
}

} // namespace vkpt::gltf
