// gltf_draco.h — KHR_draco_mesh_compression: a primitive whose vertices and indices are stored as
// one Draco-compressed buffer view, decoded with Google's Draco library (libdraco).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkpt::gltf {

// The attributes a Draco primitive carries compressed, as the loader uses them; an attribute
// the extension does not list stays nullopt (it is then read from its accessor, as the
// extension allows).
struct DracoPrimitive {
    std::vector<glm::vec3> positions;
    std::optional<std::vector<glm::vec3>> normals;
    std::optional<std::vector<glm::vec2>> texcoords;
    std::vector<std::uint32_t> indices; // three per triangle, each < positions.size()
};

// Whether the primitive has a KHR_draco_mesh_compression object.
bool isDracoPrimitive(const tinygltf::Primitive& primitive);

// Decodes the primitive's bufferView with Draco and maps the attributes by the extension's
// attribute ids: POSITION always, NORMAL when listed, TEXCOORD_0 when listed and wanted. Buffer
// views must have been checked (checkBufferViews). Throws GltfProblem (starting with `where`)
// for a missing view or attribute, data Draco rejects, or a decoded attribute of the wrong size.
DracoPrimitive decodeDracoPrimitive(const tinygltf::Model& model,
                                    const tinygltf::Primitive& primitive, bool withTexcoords,
                                    const std::string& where);

} // namespace vkpt::gltf
