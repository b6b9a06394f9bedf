// gltf_cameras.h — the perspective and orthographic cameras that the scene's nodes place.
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkpt::gltf {

// The camera node nodeIndex places with its world transform. The camera looks down its local
// -Z with +Y up; scale is removed (also from an orthographic camera's xmag and ymag, which glTF
// gives in the camera's own units and which the node's scale does not change).
SceneCamera placeCamera(const tinygltf::Model& model, int nodeIndex, const glm::dmat4& world);

} // namespace vkpt::gltf
