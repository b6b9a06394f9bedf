// gltf_skins.h — linear blend skinning (glTF 2.0, section 3.7.3): a skinned mesh's vertices
// placed by its skin's joints rather than by its node, each the weighted sum of its (up to four
// per JOINTS_n/WEIGHTS_n set) joints' matrices applied to it.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkpt::gltf {

// World transforms of the nodes the scene walk visited, in the walk's space (after its root);
// placed[i] says whether node i was visited.
struct NodeWorlds {
    std::vector<glm::dmat4> transforms;
    std::vector<char> placed;
};

// The joint matrices of skin `skinIndex`: each joint's world transform × its inverse bind matrix
// (the identity when the skin has no inverseBindMatrices, as the specification defaults). Throws
// GltfProblem naming the skin for a skin that does not exist, has no joints, names a node that
// does not exist or is not in the scene, or has fewer or non-finite inverse bind matrices.
std::vector<glm::dmat4> jointMatrices(const tinygltf::Model& model, int skinIndex,
                                      const NodeWorlds& worlds);

// A primitive's vertices before any transform; normals and tangents may be null (not read).
struct SkinnableVertices {
    std::vector<glm::vec3>& positions;
    std::vector<glm::vec3>* normals;
    std::vector<glm::vec4>* tangents;
};

// Replaces each vertex by its skinned one: positions by Σ w·J, normals by that matrix's inverse
// transpose, tangents by its linear part. Reads every JOINTS_n/WEIGHTS_n pair of the primitive
// (there must be at least JOINTS_0 and WEIGHTS_0, in pairs). Weights that do not sum to one are
// renormalised (counted in repairs.renormalisedSkinWeights when off by more than the 8-bit
// quantisation allows); a joint index outside the skin under a non-zero weight, a negative or
// non-finite weight, or weights that are all zero are GltfProblems naming the vertex.
void skinVertices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                  const std::vector<glm::dmat4>& joints, SkinnableVertices vertices,
                  const std::string& where, GeometryRepairs& repairs);

} // namespace vkpt::gltf
