// gltf_mesh_instancing.cpp — reads EXT_mesh_gpu_instancing's per-instance attributes into
// transforms. The extension (Khronos, glTF 2.0) gives each instance a TRANSLATION (VEC3), ROTATION
// (unit quaternion VEC4, x y z w) and SCALE (VEC3), each optional, all of one count; an instance's
// transform is the node's world transform × T × R × S.
#include "scene/gltf_mesh_instancing.h"

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scene/gltf_accessors.h"
#include "scene/gltf_document.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kMeshInstancing = "EXT_mesh_gpu_instancing";
// (tinygltf reads an empty "attributes": {} as no value at all: one message for both.)
constexpr const char* kNoAttributes = "no attributes (TRANSLATION, ROTATION or SCALE)";

std::string placeOf(int nodeIndex) {
    return "node " + std::to_string(nodeIndex) + ": " + kMeshInstancing;
}

// The accessor index of attribute `name`, -1 when absent.
int attributeAccessor(const tinygltf::Value& attributes, const char* name, int nodeIndex) {
    return readIndex(attributes, name, placeOf(nodeIndex) + " attributes");
}

const tinygltf::Value* instancingAttributes(const tinygltf::Node& node, int nodeIndex) {
    const tinygltf::Value* extension = findExtension(node.extensions, kMeshInstancing);
    if (extension == nullptr) return nullptr;
    const tinygltf::Value* attributes = findMember(*extension, "attributes");
    if (attributes == nullptr || !attributes->IsObject()) {
        throw GltfProblem(placeOf(nodeIndex) + ": " + kNoAttributes);
    }
    return attributes;
}

// The attributes' element counts, which must agree: the first one read sets the count.
struct InstanceCount {
    std::optional<std::size_t> count;
    const char* firstName = nullptr;

    void agree(std::size_t size, const char* name, int nodeIndex) {
        if (count && size != *count) {
            throw GltfProblem(placeOf(nodeIndex) + ": " + name + " has " + std::to_string(size) +
                              " elements, " + firstName + " " + std::to_string(*count));
        }
        count = size;
        firstName = name;
    }
};

bool isFinite(const glm::dvec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

glm::dmat4 rotationOf(const glm::vec4& xyzw, std::size_t instance, int nodeIndex) {
    const glm::dvec4 q(xyzw);
    const double length = glm::length(q);
    if (!(length > 0.0) || !isFinite(q)) {
        throw GltfProblem(placeOf(nodeIndex) + ": instance " + std::to_string(instance) +
                          " has a zero or non-finite ROTATION");
    }
    // Stored (x, y, z, w); glm's constructor takes w first. Renormalised, as for node rotations:
    // quantized quaternions are a few 1e-3 from unit length.
    return glm::mat4_cast(glm::dquat(q.w, q.x, q.y, q.z) / length);
}

void requireFinite(const glm::vec3& v, const char* name, std::size_t instance, int nodeIndex) {
    if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) return;
    throw GltfProblem(placeOf(nodeIndex) + ": instance " + std::to_string(instance) +
                      " has a non-finite " + name);
}

} // namespace

std::optional<std::vector<glm::dmat4>> meshInstanceTransforms(const tinygltf::Model& model,
                                                              int nodeIndex) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(nodeIndex)];
    const tinygltf::Value* attributes = instancingAttributes(node, nodeIndex);
    if (attributes == nullptr) return std::nullopt;
    const std::string where = placeOf(nodeIndex);
    const int translationAccessor = attributeAccessor(*attributes, "TRANSLATION", nodeIndex);
    const int rotationAccessor = attributeAccessor(*attributes, "ROTATION", nodeIndex);
    const int scaleAccessor = attributeAccessor(*attributes, "SCALE", nodeIndex);
    if (translationAccessor < 0 && rotationAccessor < 0 && scaleAccessor < 0) {
        throw GltfProblem(where + ": " + kNoAttributes);
    }
    std::vector<glm::vec3> translations, scales;
    std::vector<glm::vec4> rotations;
    InstanceCount count;
    if (translationAccessor >= 0) {
        translations = readPositions(model, translationAccessor, where + " TRANSLATION");
        count.agree(translations.size(), "TRANSLATION", nodeIndex);
    }
    if (rotationAccessor >= 0) {
        rotations = readRotations(model, rotationAccessor, where + " ROTATION");
        count.agree(rotations.size(), "ROTATION", nodeIndex);
    }
    if (scaleAccessor >= 0) {
        scales = readPositions(model, scaleAccessor, where + " SCALE");
        count.agree(scales.size(), "SCALE", nodeIndex);
    }
    std::vector<glm::dmat4> transforms(*count.count, glm::dmat4(1.0));
    for (std::size_t i = 0; i < *count.count; ++i) {
        glm::dmat4& transform = transforms[i];
        if (!translations.empty()) {
            requireFinite(translations[i], "TRANSLATION", i, nodeIndex);
            transform = glm::translate(transform, glm::dvec3(translations[i]));
        }
        if (!rotations.empty()) transform = transform * rotationOf(rotations[i], i, nodeIndex);
        if (!scales.empty()) {
            requireFinite(scales[i], "SCALE", i, nodeIndex);
            transform = glm::scale(transform, glm::dvec3(scales[i]));
        }
    }
    return transforms;
}

std::uint64_t meshPlacementCount(const tinygltf::Model& model, int nodeIndex) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(nodeIndex)];
    const tinygltf::Value* extension = findExtension(node.extensions, kMeshInstancing);
    if (extension == nullptr) return 1;
    const tinygltf::Value* attributes = findMember(*extension, "attributes");
    if (attributes == nullptr || !attributes->IsObject()) return 0;
    for (const char* name : {"TRANSLATION", "ROTATION", "SCALE"}) {
        const tinygltf::Value* accessor = findMember(*attributes, name);
        if (accessor == nullptr || !accessor->IsInt()) continue;
        const int index = accessor->GetNumberAsInt();
        if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) return 0;
        return model.accessors[static_cast<std::size_t>(index)].count;
    }
    return 0;
}

} // namespace vkpt::gltf
