// scene_setup.h — the first steps both executables share: load, build the BVH, lay the
// scene out, choose the camera; with one log line for each that takes time.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "common/render_settings.h"
#include "prepare/bvh_cache.h"
#include "prepare/level_cache.h"
#include "prepare/prepared_scene.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"

namespace vkpt {

struct SceneSetup {
    PreparedScene prepared;
    gpu::Camera camera{};
    double loadSeconds = 0.0;
    std::uint64_t placedTriangles = 0; // what the render sees (Scene::placedTriangleCount)
    std::size_t instances = 0;         // placements of meshes kept once
    std::size_t meshes = 0;            // meshes kept once
};

// What an animation's frames keep from one to the next (docs/scene-model.md, "Frames"): the
// file, read by the first frame and posed by every one (which keeps the still geometry it walked
// once: GltfSceneSource); the --env image, read once; and the bottom levels of the geometry that
// did not move: their records and hashes, and the BVHs of geometry whose boxes did not change.
struct FrameCache {
    std::optional<GltfSceneSource> source;
    std::optional<SceneEnvironment> environment;
    BvhCache bvhs;
    LevelCache levels;
};

// `afterLoad`, when given, sees the loaded scene before it is prepared (vkpt starts creating its
// pipelines there, while the BVH builds). A scene posed at a time (--time, or a frame) keeps
// what moves apart from the still geometry (LoadOptions::keepMovingApart, unless --instancing
// off). With `frames`, the scene is one frame of an animation: the file and the --env image are
// read the first time and kept, and the still geometry's BVHs are taken from the frames before.
SceneSetup setUpScene(const RenderSettings& settings, const std::string& program,
                      const std::function<void(const Scene&)>& afterLoad = {},
                      FrameCache* frames = nullptr);

// main()'s one catch: one line on stderr and the exit code of DESIGN's error contract
// (1 bad input, 2 Vulkan or device failure, 3 internal error).
int reportFailure(const std::string& program, const std::exception& error, int exitCode);

} // namespace vkpt
