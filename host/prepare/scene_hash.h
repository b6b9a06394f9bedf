// scene_hash.h — a fingerprint of what a render sees, so that parts of a render made on other
// machines (tasks, crops, checkpoints) can prove they rendered the same scene.
#pragma once

#include <string>

#include "prepare/prepared_scene.h"

namespace vkpt {

// 16 hex digits: 64-bit FNV-1a over the hashes (common/content_hash.h) and sizes of the prepared
// primitives, normals, texture coordinates and tangents the scene uses (per bottom level, as
// PreparedScene::levelHashes holds them), and of its materials, emitters, instances, textures
// and texels, the environment, and the camera. Independent of --general (which only adds arrays
// the scene does not use) and of the executor; any change to the geometry, a material, a
// texture, a light, the environment or the view changes it. An animation's frames hash each
// bottom level once, when it is prepared (level_cache.h): a frame hashes what it prepared anew
// and the small arrays, not the still geometry again. Neither FNV-1a nor the content hash is
// cryptographic: they identify, they do not authenticate.
std::string sceneContentHash(const PreparedScene& scene, const gpu::Camera& camera);

} // namespace vkpt
