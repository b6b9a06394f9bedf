// prepared_scene_view.h — the prepared scene as the shared surface, material and light code
// reads it on the CPU: a SceneView (shaders/shared/scene_view.h) of spans over its arrays and
// the features the kernels would be specialised for.
#pragma once

#include "prepare/prepared_scene.h"
#include "shared/scene_view.h"

namespace vkpt {

// The view borrows the scene's arrays: it is valid while `scene` lives and is not changed.
gpu::SceneView makeSceneView(const PreparedScene& scene);

} // namespace vkpt
