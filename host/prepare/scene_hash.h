// scene_hash.h — a fingerprint of what a render sees, so that parts of a render made on other
// machines (tasks, crops, checkpoints) can prove they rendered the same scene.
#pragma once

#include <string>

#include "prepare/prepared_scene.h"

namespace vkpt {

// 16 hex digits: 64-bit FNV-1a over the prepared primitives, normals, texture coordinates and
// texels the scene uses, materials, emitters, the environment and the camera. Independent of
// --general (which only adds arrays the scene does not use) and of the executor; any change to
// the geometry, a material, a texture, a light, the environment or the view changes it. FNV-1a
// is not a cryptographic hash: it identifies, it does not authenticate.
std::string sceneContentHash(const PreparedScene& scene, const gpu::Camera& camera);

} // namespace vkpt
