// gltf_loader.h — reads a .gltf or .glb file into a Scene, validating everything the GPU
// will index.
#pragma once

#include <string>

#include "scene/scene.h"

namespace vkpt {

struct LoadOptions {
    bool warnUnsupportedExtensions = true; // one stderr line listing extensionsUsed we ignore
};

// Loads the default scene (`scene`, else scene 0): TRIANGLES primitives of every mesh node, with
// their materials, and the perspective cameras. Images are not decoded (textures are not used
// yet). Throws InputError, one line naming the file and the place, for any bad input, including
// sparse accessors, other primitive modes and unsupported required extensions. What it ignores
// (orthographic cameras, unsupported extensions in extensionsUsed) it notes on stderr, one line
// each, and only once the load has succeeded.
Scene loadGltfScene(const std::string& path, const LoadOptions& options = {});

} // namespace vkpt
