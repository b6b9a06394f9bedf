// gltf_morph.cpp — reads each morph target's displacement accessors and adds them, weighted, to
// the vertices. Displacements of NORMAL and TANGENT are added before renormalising, as the glTF
// 2.0 specification (section 3.7.2.2) prescribes; tangents keep their w.
#include "scene/gltf_morph.h"

#include <cmath>

#include "scene/gltf_accessors.h"
#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

std::string targetPlace(const std::string& where, std::size_t target, const char* attribute) {
    return where + ": morph target " + std::to_string(target) + " " + attribute;
}

// Adds weight × the target's `attribute` displacements to the first three components of
// `values`; nothing when the target does not displace that attribute.
template <typename Vector>
void addDisplacements(const tinygltf::Model& model, const std::map<std::string, int>& target,
                      const char* attribute, double weight, std::vector<Vector>& values,
                      std::size_t targetIndex, const std::string& where) {
    const auto accessor = target.find(attribute);
    if (accessor == target.end()) return;
    const std::string place = targetPlace(where, targetIndex, attribute);
    const std::vector<glm::vec3> displacements = readPositions(model, accessor->second, place);
    if (displacements.size() != values.size()) {
        throw GltfProblem(place + " has " + std::to_string(displacements.size()) +
                          " elements but POSITION has " + std::to_string(values.size()));
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        const glm::dvec3 moved =
            glm::dvec3(glm::vec3(values[i])) + weight * glm::dvec3(displacements[i]);
        for (int c = 0; c < 3; ++c)
            values[i][c] = static_cast<float>(moved[c]);
    }
}

void checkWeights(const std::vector<double>& weights, std::size_t targets,
                  const std::string& where) {
    if (weights.size() != targets) {
        throw GltfProblem(where + ": " + std::to_string(weights.size()) + " morph weights for " +
                          std::to_string(targets) + " morph targets");
    }
    for (double weight : weights) {
        if (!std::isfinite(weight)) throw GltfProblem(where + ": a morph weight is not finite");
    }
}

} // namespace

std::vector<double> morphWeights(const tinygltf::Model& model, int nodeIndex,
                                 const ScenePose* pose) {
    const auto index = static_cast<std::size_t>(nodeIndex);
    if (pose != nullptr && index < pose->weights.size() && pose->weights[index])
        return *pose->weights[index];
    const tinygltf::Node& node = model.nodes[index];
    if (!node.weights.empty()) return node.weights;
    if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= model.meshes.size()) return {};
    return model.meshes[static_cast<std::size_t>(node.mesh)].weights;
}

void applyMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                       const std::vector<double>& weights, MorphableVertices vertices,
                       const std::string& where) {
    if (weights.empty() || primitive.targets.empty()) return;
    checkWeights(weights, primitive.targets.size(), where);
    for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
        if (weights[t] == 0.0) continue;
        const std::map<std::string, int>& target = primitive.targets[t];
        addDisplacements(model, target, "POSITION", weights[t], vertices.positions, t, where);
        if (vertices.normals != nullptr)
            addDisplacements(model, target, "NORMAL", weights[t], *vertices.normals, t, where);
        if (vertices.tangents != nullptr)
            addDisplacements(model, target, "TANGENT", weights[t], *vertices.tangents, t, where);
    }
}

} // namespace vkpt::gltf
