// gltf_mesh_instancing.h — EXT_mesh_gpu_instancing: a node that places its mesh many times, once
// per element of its TRANSLATION, ROTATION and SCALE accessors.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkpt::gltf {

// The local transforms T × R × S (relative to the node) of each placement of node `nodeIndex`'s
// mesh, or nullopt when the node does not use the extension (its mesh is placed once, at the
// node). Throws GltfProblem for a malformed extension: no attributes, accessors of other types
// or of unequal counts, non-finite values, a zero quaternion.
std::optional<std::vector<glm::dmat4>> meshInstanceTransforms(const tinygltf::Model& model,
                                                              int nodeIndex);

// How many placements node `nodeIndex` makes of its mesh, from the accessors' counts alone
// (nothing is read): 1 without the extension; 0 when the extension is malformed, which the
// loading walk then reports.
std::uint64_t meshPlacementCount(const tinygltf::Model& model, int nodeIndex);

} // namespace vkpt::gltf
