// scene_setup.h — the first steps both executables share: load, build the BVH, lay the
// scene out, choose the camera; with one log line for each that takes time.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "common/render_settings.h"
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

// `afterLoad`, when given, sees the loaded scene before it is prepared (vkpt starts creating its
// pipelines there, while the BVH builds). With `source`, the file is read into it the first
// time and posed from it every time (an animation's frames read their file once).
SceneSetup setUpScene(const RenderSettings& settings, const std::string& program,
                      const std::function<void(const Scene&)>& afterLoad = {},
                      std::optional<GltfSceneSource>* source = nullptr);

// main()'s one catch: one line on stderr and the exit code of DESIGN's error contract
// (1 bad input, 2 Vulkan or device failure, 3 internal error).
int reportFailure(const std::string& program, const std::exception& error, int exitCode);

} // namespace vkpt
