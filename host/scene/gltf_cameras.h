// gltf_cameras.h — the perspective cameras that the scene's nodes place.
#pragma once

#include <optional>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkpt::gltf {

// The camera node nodeIndex places with its world transform, or nullopt for an orthographic
// camera, which vkpt skips. The camera looks down its local -Z with +Y up; scale is removed.
std::optional<SceneCamera> placeCamera(const tinygltf::Model& model, int nodeIndex,
                                       const glm::dmat4& world);

} // namespace vkpt::gltf
