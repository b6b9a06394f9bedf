// gltf_morph.h — morph targets: a primitive's vertices moved by its targets' displacements,
// weighted by the node's (or its mesh's, or an animation's) weights (glTF 2.0, section 3.7.2.2).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_animation.h"
#include "scene/gltf_nodes.h"

namespace vkpt::gltf {

// The weights that morph node `nodeIndex`'s mesh: the pose's, else node.weights, else
// mesh.weights; empty when none is given (every weight is then 0: the mesh as stored).
std::vector<double> morphWeights(const tinygltf::Model& model, int nodeIndex,
                                 const ScenePose* pose);

// The interval a morph target's weight can take.
struct WeightRange {
    double low = 0.0;
    double high = 0.0;
};

// Per morph target of node `nodeIndex`'s mesh, the interval its weight takes: its weight at rest
// (morphWeights without a pose; 0 where none is given) and every value a weights channel of
// `animations` on the node can give it: the keyframes' values (STEP and LINEAR stay between
// them) and, for CUBICSPLINE, each segment's Bézier control points v₀ + Δt·b₀/3 and v₁ − Δt·a₁/3
// (a cubic Hermite segment is the Bézier curve of those four points and lies in their hull;
// glTF 2.0, Appendix C). Empty when the mesh has no morph targets.
std::vector<WeightRange> morphWeightRanges(const tinygltf::Model& model, int nodeIndex,
                                           const std::vector<Animation>& animations);

// A primitive's vertices before any transform; normals and tangents may be null (not read).
struct MorphableVertices {
    std::vector<glm::vec3>& positions;
    std::vector<glm::vec3>* normals;
    std::vector<glm::vec4>* tangents;
};

// Adds weights[i] × target i's POSITION, NORMAL and TANGENT (xyz) displacements to `vertices`,
// in double. The weights must be as many as the primitive's targets (or none: nothing moves); a
// target's accessors must have one element per vertex. `where` names the primitive.
void applyMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                       const std::vector<double>& weights, MorphableVertices vertices,
                       const std::string& where);

} // namespace vkpt::gltf
