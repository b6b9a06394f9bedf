// scene.cpp — whole-scene queries on the loaded triangle soup, spheres and instances.
#include "scene/scene.h"

namespace vkpt {

namespace {

void extend(Bounds& bounds, const glm::vec3& point) {
    bounds.min = glm::min(bounds.min, point);
    bounds.max = glm::max(bounds.max, point);
}

bool isEmpty(const Bounds& bounds) {
    return bounds.min.x > bounds.max.x;
}

} // namespace

std::uint64_t Scene::placedTriangleCount() const {
    std::uint64_t count = triangleCount();
    for (const SceneInstance& instance : instances)
        count += meshes[instance.mesh].triangleCount();
    return count;
}

std::uint64_t Scene::storedTriangleCount() const {
    std::uint64_t count = triangleCount();
    for (const SceneMesh& mesh : meshes)
        count += mesh.triangleCount();
    return count;
}

Bounds computeBounds(const TriangleSoup& soup) {
    Bounds bounds;
    for (const glm::vec3& position : soup.positions)
        extend(bounds, position);
    return bounds;
}

Bounds transformBounds(const Bounds& bounds, const glm::dmat4& transform) {
    Bounds result;
    if (isEmpty(bounds)) return result;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? bounds.max.x : bounds.min.x,
                           (corner & 2) ? bounds.max.y : bounds.min.y,
                           (corner & 4) ? bounds.max.z : bounds.min.z);
        extend(result, glm::vec3(transform * glm::dvec4(p, 1.0)));
    }
    return result;
}

Bounds computeBounds(const Scene& scene) {
    Bounds bounds = computeBounds(static_cast<const TriangleSoup&>(scene));
    for (const SceneSphere& sphere : scene.spheres) {
        extend(bounds, sphere.centre - glm::vec3(sphere.radius));
        extend(bounds, sphere.centre + glm::vec3(sphere.radius));
    }
    std::vector<Bounds> meshBounds;
    for (const SceneMesh& mesh : scene.meshes)
        meshBounds.push_back(computeBounds(mesh));
    for (const SceneInstance& instance : scene.instances) {
        const Bounds placed = transformBounds(meshBounds[instance.mesh], instance.objectToWorld);
        if (isEmpty(placed)) continue;
        extend(bounds, placed.min);
        extend(bounds, placed.max);
    }
    return bounds;
}

} // namespace vkpt
