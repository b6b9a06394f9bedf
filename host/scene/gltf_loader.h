// gltf_loader.h — reads a .gltf or .glb file into a Scene, validating everything the GPU
// will index.
#pragma once

#include <string>

#include "common/render_settings.h"
#include "scene/scene.h"

namespace vkpt {

struct LoadOptions {
    bool warnUnsupportedExtensions = true; // one stderr line listing extensionsUsed we ignore
    // Which meshes placed more than once are kept once and placed by Scene::instances
    // (gltf_instancing_plan.h); the others are flattened into world space at every placement.
    Instancing instancing = Instancing::Auto;
    // KHR_materials_variants (--variant): a variant's name, or its index in decimal; empty: the
    // primitives' own (default) materials.
    std::string variant;
};

// Loads the default scene (`scene`, else scene 0): TRIANGLES primitives of every mesh node (and of
// every EXT_mesh_gpu_instancing instance), with their materials, flattened into world space or
// kept once per mesh and placed by instances as options.instancing decides; the textures those
// materials use (decoded; TEXCOORD_0 read only then); KHR_lights_punctual lights;
// KHR_implicit_shapes spheres (gltf_shapes.cpp); and the perspective cameras. With
// options.variant, each primitive takes the material its KHR_materials_variants mapping gives
// that variant (Scene::materialVariants lists them all). Compressed files are
// decoded on the way: Draco and meshopt geometry, quantized attributes, WebP images
// (docs/scene-model.md, "Compressed files"). Throws InputError, one line naming the file and the
// place, for any bad input, including sparse accessors, other primitive modes, undecodable images
// and unsupported required extensions. What it ignores (orthographic cameras, unsupported
// extensions in extensionsUsed, KHR_materials_volume's thicknessTexture) it notes on stderr, one
// line each, and only once the load has succeeded.
Scene loadGltfScene(const std::string& path, const LoadOptions& options = {});

} // namespace vkpt
