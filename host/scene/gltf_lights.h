// gltf_lights.h — KHR_lights_punctual: the document's point, spot and directional lights, placed
// in world space by the nodes that reference them.
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkpt::gltf {

// The light node `nodeIndex` places (node.extensions.KHR_lights_punctual.light), nullopt when it
// places none: at the node's origin, shining along its −Z axis, both through `world`. Throws
// GltfProblem for a light index that does not exist or a light the extension does not allow
// (unknown type, negative colour, intensity or range, cone angles outside
// 0 <= inner <= outer <= π/2 with outer > 0).
std::optional<SceneLight> placeLight(const tinygltf::Model& model, int nodeIndex,
                                     const glm::dmat4& world);

} // namespace vkpt::gltf
