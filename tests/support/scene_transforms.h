// scene_transforms.h — the same scene made tiny, huge or far from the origin, in memory:
// every position and the cameras move together, so the image should not change.
#pragma once

#include "scene/scene.h"

namespace vkpt::test {

inline Scene scaledScene(Scene scene, float scale) {
    for (glm::vec3& p : scene.positions)
        p *= scale;
    for (SceneCamera& c : scene.cameras)
        c.position *= scale;
    return scene;
}

inline Scene translatedScene(Scene scene, glm::vec3 offset) {
    for (glm::vec3& p : scene.positions)
        p += offset;
    for (SceneCamera& c : scene.cameras)
        c.position += offset;
    return scene;
}

} // namespace vkpt::test
