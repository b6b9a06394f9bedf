// scene.cpp — whole-scene queries on the loaded triangle soup.
#include "scene/scene.h"

namespace vkpt {

Bounds computeBounds(const Scene& scene) {
    Bounds bounds;
    for (const glm::vec3& position : scene.positions) {
        bounds.min = glm::min(bounds.min, position);
        bounds.max = glm::max(bounds.max, position);
    }
    return bounds;
}

} // namespace vkpt
