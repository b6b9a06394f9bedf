// gltf_skins.cpp — joint matrices from the posed node tree, and per-vertex skin matrices blended
// from them in double.
#include "scene/gltf_skins.h"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_accessors.h"
#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

std::string skinName(int index) {
    return "skin " + std::to_string(index);
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

std::vector<glm::dmat4> inverseBindMatrices(const tinygltf::Model& model,
                                            const tinygltf::Skin& skin, int skinIndex) {
    const std::size_t jointCount = skin.joints.size();
    if (skin.inverseBindMatrices < 0) return std::vector<glm::dmat4>(jointCount, glm::dmat4(1.0));
    const std::string where = skinName(skinIndex) + ": inverseBindMatrices";
    const std::vector<float> values =
        readFloatComponents(model, skin.inverseBindMatrices, TINYGLTF_TYPE_MAT4, false, where);
    if (values.size() / 16 < jointCount) {
        throw GltfProblem(where + " has " + std::to_string(values.size() / 16) + " matrices for " +
                          std::to_string(jointCount) + " joints");
    }
    std::vector<glm::dmat4> matrices(jointCount);
    for (std::size_t j = 0; j < jointCount; ++j) {
        matrices[j] = glm::dmat4(glm::make_mat4(values.data() + 16 * j)); // column-major
        if (!isFinite(matrices[j])) {
            throw GltfProblem(where + ": matrix " + std::to_string(j) + " is not finite");
        }
    }
    return matrices;
}

// Normals transform by the inverse transpose; the cofactor matrix is that times the
// determinant, and exists for a singular blend too (gltf_primitives.cpp does the same).
glm::dmat3 cofactorOf(const glm::dmat3& m) {
    const glm::dmat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]),
                              glm::cross(m[0], m[1]));
    return glm::determinant(m) < 0.0 ? -cofactor : cofactor;
}

// The JOINTS_n and WEIGHTS_n sets of a primitive, read.
struct Influences {
    std::vector<std::vector<glm::uvec4>> joints;
    std::vector<std::vector<float>> weights; // 4 per vertex
};

Influences readInfluences(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                          std::size_t vertexCount, const std::string& where) {
    Influences influences;
    for (int set = 0;; ++set) {
        const std::string jointsName = "JOINTS_" + std::to_string(set);
        const std::string weightsName = "WEIGHTS_" + std::to_string(set);
        const auto joints = primitive.attributes.find(jointsName);
        const auto weights = primitive.attributes.find(weightsName);
        if (joints == primitive.attributes.end() && weights == primitive.attributes.end()) break;
        if (joints == primitive.attributes.end() || weights == primitive.attributes.end()) {
            throw GltfProblem(where + ": " +
                              (joints == primitive.attributes.end()
                                   ? weightsName + " without " + jointsName
                                   : jointsName + " without " + weightsName));
        }
        influences.joints.push_back(readJoints(model, joints->second, where + ": " + jointsName));
        influences.weights.push_back(readFloatComponents(model, weights->second, TINYGLTF_TYPE_VEC4,
                                                         true, where + ": " + weightsName));
        if (influences.joints.back().size() != vertexCount ||
            influences.weights.back().size() != 4 * vertexCount) {
            throw GltfProblem(where + ": " + jointsName + " and " + weightsName + " have " +
                              std::to_string(influences.joints.back().size()) + " and " +
                              std::to_string(influences.weights.back().size() / 4) +
                              " elements but POSITION has " + std::to_string(vertexCount));
        }
    }
    if (influences.joints.empty()) {
        throw GltfProblem(where + ": the node has a skin but the primitive has no JOINTS_0 and "
                                  "WEIGHTS_0");
    }
    return influences;
}

// Weights of 8-bit storage are off by up to half a step each; more than that is a file whose
// weights do not sum to one.
constexpr double kWeightSumTolerance = 4.0 * 0.5 / 255.0;

class SkinBlender {
public:
    SkinBlender(const Influences& influences, const std::vector<glm::dmat4>& joints,
                const std::string& where)
        : influences_(influences), joints_(joints), where_(where) {}

    // Σ w·J over the vertex's influences, the weights renormalised to sum to one.
    glm::dmat4 skinMatrix(std::size_t vertex, GeometryRepairs& repairs) const {
        glm::dmat4 sum(0.0);
        double total = 0.0;
        for (std::size_t set = 0; set < influences_.joints.size(); ++set) {
            for (int c = 0; c < 4; ++c) {
                const double weight = influences_.weights[set][4 * vertex + std::size_t(c)];
                if (!(weight >= 0.0) || !std::isfinite(weight)) {
                    throw GltfProblem(place(vertex) + " has a negative or non-finite weight");
                }
                if (weight == 0.0) continue; // its joint index need not be valid
                const std::uint32_t joint = influences_.joints[set][vertex][c];
                if (joint >= joints_.size()) {
                    throw GltfProblem(place(vertex) + ": joint " + std::to_string(joint) +
                                      " is out of range (the skin has " +
                                      std::to_string(joints_.size()) + " joints)");
                }
                sum += weight * joints_[joint];
                total += weight;
            }
        }
        if (!(total > 0.0)) throw GltfProblem(place(vertex) + " has no non-zero skin weight");
        if (std::abs(total - 1.0) > kWeightSumTolerance) ++repairs.renormalisedSkinWeights;
        return sum / total;
    }

private:
    std::string place(std::size_t vertex) const {
        return where_ + ": vertex " + std::to_string(vertex);
    }

    const Influences& influences_;
    const std::vector<glm::dmat4>& joints_;
    const std::string& where_;
};

} // namespace

std::vector<glm::dmat4> jointMatrices(const tinygltf::Model& model, int skinIndex,
                                      const NodeWorlds& worlds) {
    if (skinIndex < 0 || static_cast<std::size_t>(skinIndex) >= model.skins.size()) {
        throw GltfProblem(skinName(skinIndex) + " does not exist (the file has " +
                          std::to_string(model.skins.size()) + " skins)");
    }
    const tinygltf::Skin& skin = model.skins[static_cast<std::size_t>(skinIndex)];
    if (skin.joints.empty()) throw GltfProblem(skinName(skinIndex) + " has no joints");
    const std::vector<glm::dmat4> inverseBind = inverseBindMatrices(model, skin, skinIndex);
    std::vector<glm::dmat4> matrices(skin.joints.size());
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        const int node = skin.joints[j];
        if (node < 0 || static_cast<std::size_t>(node) >= model.nodes.size()) {
            throw GltfProblem(skinName(skinIndex) + ": joint " + std::to_string(j) + " is node " +
                              std::to_string(node) + ", which does not exist (the file has " +
                              std::to_string(model.nodes.size()) + " nodes)");
        }
        if (!worlds.placed[static_cast<std::size_t>(node)]) {
            throw GltfProblem(skinName(skinIndex) + ": joint " + std::to_string(j) + " is node " +
                              std::to_string(node) + ", which is not in the scene");
        }
        matrices[j] = worlds.transforms[static_cast<std::size_t>(node)] * inverseBind[j];
    }
    return matrices;
}

void skinVertices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                  const std::vector<glm::dmat4>& joints, SkinnableVertices vertices,
                  const std::string& where, GeometryRepairs& repairs) {
    const std::size_t vertexCount = vertices.positions.size();
    const Influences influences = readInfluences(model, primitive, vertexCount, where);
    const SkinBlender blender(influences, joints, where);
    for (std::size_t v = 0; v < vertexCount; ++v) {
        const glm::dmat4 skin = blender.skinMatrix(v, repairs);
        vertices.positions[v] =
            glm::vec3(skin * glm::dvec4(glm::dvec3(vertices.positions[v]), 1.0));
        const glm::dmat3 linear(skin);
        if (vertices.normals != nullptr) {
            glm::vec3& normal = (*vertices.normals)[v];
            normal = glm::vec3(cofactorOf(linear) * glm::dvec3(normal)); // unit later
        }
        if (vertices.tangents != nullptr) {
            glm::vec4& tangent = (*vertices.tangents)[v];
            tangent = glm::vec4(glm::vec3(linear * glm::dvec3(glm::vec3(tangent))), tangent.w);
        }
    }
}

} // namespace vkpt::gltf
