// gltf_materials.h — glTF metallic-roughness materials to SceneMaterial, emission included.
#pragma once

#include <vector>

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkpt::gltf {

// One SceneMaterial per glTF material, in file order (so material indices carry over).
std::vector<SceneMaterial> convertMaterials(const tinygltf::Model& model);

// The material the glTF specification prescribes for a primitive without one: white, fully
// metallic, fully rough, opaque, single-sided.
SceneMaterial defaultMaterial();

} // namespace vkpt::gltf
