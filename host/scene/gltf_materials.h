// gltf_materials.h — glTF metallic-roughness materials to SceneMaterial: factors, emission,
// KHR_materials_specular (factors and textures), the base colour, metallic-roughness and
// emissive textures, glass: KHR_materials_transmission (factor and texture), KHR_materials_ior,
// KHR_materials_volume; the clearcoat and sheen layers; KHR_materials_unlit.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/gltf_textures.h"
#include "scene/scene.h"

namespace vkpt::gltf {

// One SceneMaterial per glTF material, in file order (so material indices carry over). The
// textures they use are added to `textures` (and so decoded); normal and occlusion textures are
// not read.
std::vector<SceneMaterial> convertMaterials(const tinygltf::Model& model, TextureTable& textures);

// What the conversion left out, one stderr line each: KHR_materials_volume's thicknessTexture.
std::vector<std::string> materialNotes(const tinygltf::Model& model);

// The material the glTF specification prescribes for a primitive without one: white, fully
// metallic, fully rough, opaque, single-sided.
SceneMaterial defaultMaterial();

} // namespace vkpt::gltf
