// gltf_loader.h — reads a .gltf or .glb file into a Scene, validating everything the GPU
// will index.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "common/render_settings.h"
#include "scene/scene.h"

namespace vkpt {

struct LoadOptions {
    bool warnUnsupportedExtensions = true; // one stderr line listing extensionsUsed we ignore
    // Which meshes placed more than once are kept once and placed by Scene::instances
    // (gltf_instancing_plan.h); the others are flattened into world space at every placement.
    Instancing instancing = Instancing::Auto;
    // Pose the scene at this time in seconds (docs/scene-model.md, "Animation"); nullopt: at
    // rest, as the file stores its nodes (morph weights and skins still apply).
    std::optional<double> time;
    std::string animation; // which one plays at `time`: "" all, else an index or a name
    // KHR_materials_variants (--variant): a variant's name, or its index in decimal; empty: the
    // primitives' own (default) materials.
    std::string variant;
    // An animation's frames (docs/scene-model.md, "Frames"), with a time: the meshes an animation
    // moves are kept apart from the still geometry, so that the next frame keeps the still
    // geometry (walked once: GltfSceneSource) and its bottom level: a mesh on a node that a
    // translation, rotation or scale channel moves (or under one) is placed by an instance, a
    // skinned or morphed mesh is a posed mesh of its own (Scene::meshes, placed unmoved); the
    // still part comes first in the scene's arrays. Off: they are flattened as Instancing
    // decides.
    bool keepMovingApart = false;
};

// Loads the default scene (`scene`, else scene 0): TRIANGLES primitives of every mesh node (and of
// every EXT_mesh_gpu_instancing instance), morphed by their weights and skinned by their skins,
// posed by the animations at options.time when given, with their materials (with
// options.variant, each primitive takes the material its KHR_materials_variants mapping gives
// that variant; Scene::materialVariants lists them all), flattened into world space or kept
// once per mesh and placed by instances as options.instancing decides; the textures those
// materials use (decoded; TEXCOORD_0 read only then, or for an anisotropic material's
// tangents); KHR_lights_punctual lights; KHR_implicit_shapes spheres (gltf_shapes.cpp); and the
// perspective cameras. Compressed files are decoded on the way: Draco and meshopt geometry,
// quantized attributes, WebP images (docs/scene-model.md, "Compressed files"). Throws
// InputError, one line naming the file and the place, for any bad input (malformed skins and
// animations too), including other primitive modes, undecodable images and unsupported
// required extensions. What it ignores (orthographic cameras, unsupported extensions in
// extensionsUsed, KHR_materials_volume's thicknessTexture) it notes on stderr, one line each,
// and only once the load has succeeded.
Scene loadGltfScene(const std::string& path, const LoadOptions& options = {});

// A file read once and posed many times: an animation's frames share the parsed document, the
// decoded textures, the materials, the checked animations and the layout at rest (instancing
// plan, extent); a pose that keeps what moves apart also shares the still part, walked by the
// first such pose and kept for the later ones (docs/scene-model.md, "Frames"), and walks, morphs
// and skins only what moves. Poses are not taken concurrently (they fill those memos).
// loadGltfScene(path, options) is GltfSceneSource(path).pose(options).
class GltfSceneSource {
public:
    // Parses and checks the file, decodes its textures; throws InputError like loadGltfScene.
    explicit GltfSceneSource(const std::string& path);
    ~GltfSceneSource();
    GltfSceneSource(GltfSceneSource&&) noexcept;
    GltfSceneSource& operator=(GltfSceneSource&&) = delete;

    const std::string& path() const;
    // The scene as options.time and options.animation pose it (the other options too).
    Scene pose(const LoadOptions& options) const;

    struct Parsed;

private:
    std::unique_ptr<Parsed> parsed_;
};

} // namespace vkpt
