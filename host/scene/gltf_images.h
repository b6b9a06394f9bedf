// gltf_images.h — one glTF image (PNG or JPEG, from a file, a data: URI or a buffer view) decoded
// to RGBA8 texels.
#pragma once

#include <tiny_gltf.h>

#include "scene/scene.h"

namespace vkpt::gltf {

// Decodes image `imageIndex` (which must exist) with stb_image: 4 channels, 8 bits each (16-bit
// PNGs are reduced, grey ones expanded), texel (x, y) at texels[y·width + x] with row 0 the
// file's first row, which glTF maps to v = 0. Buffer views must have been checked
// (checkBufferViews). Throws GltfProblem for a missing file, a format other than PNG or JPEG,
// or bytes stb_image cannot decode.
SceneImage decodeImage(const tinygltf::Model& model, int imageIndex);

} // namespace vkpt::gltf
