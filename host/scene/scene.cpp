// scene.cpp — whole-scene queries on the loaded triangle soup and spheres.
#include "scene/scene.h"

namespace vkpt {

Bounds computeBounds(const Scene& scene) {
    Bounds bounds;
    for (const glm::vec3& position : scene.positions) {
        bounds.min = glm::min(bounds.min, position);
        bounds.max = glm::max(bounds.max, position);
    }
    for (const SceneSphere& sphere : scene.spheres) {
        bounds.min = glm::min(bounds.min, sphere.centre - glm::vec3(sphere.radius));
        bounds.max = glm::max(bounds.max, sphere.centre + glm::vec3(sphere.radius));
    }
    return bounds;
}

} // namespace vkpt
