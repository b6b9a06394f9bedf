// gltf_webp.h — EXT_texture_webp: WebP images decoded with libwebp into the RGBA8 texels every
// other image becomes.
#pragma once

#include <span>
#include <string>

#include "scene/scene.h"

namespace vkpt::gltf {

// Whether the bytes start with a WebP file's signature ("RIFF", a size, "WEBP").
bool isWebp(std::span<const unsigned char> bytes);

// Decodes WebP data (lossy or lossless, with or without alpha) to RGBA8, row 0 the image's top
// row as for PNG. Throws GltfProblem starting with `name` when libwebp rejects the data.
SceneImage decodeWebp(std::span<const unsigned char> bytes, const std::string& name);

} // namespace vkpt::gltf
