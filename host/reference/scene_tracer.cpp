// scene_tracer.cpp — counts each query and forwards it to the stack traversal.
#include "reference/scene_tracer.h"

#include "reference/surface.h"
#include "shared/sphere.h"

namespace vkpt {

bool AlphaMaskFilter::accepts(std::uint32_t primitive, const RayQuery& ray,
                              const gpu::TriangleHit& hit) const {
    glm::vec3 sphereNormal(0.0f);
    const gpu::Triangle& record = scene_.triangles[primitive];
    if (gpu::isSpherePrimitive(record))
        sphereNormal = gpu::sphereNormalAt(ray.origin + hit.t * ray.direction, record.v0);
    return !alphaMasked(scene_, primitive, hit.u, hit.v, sphereNormal);
}

ClosestHit SceneTracer::closest(const glm::vec3& origin, const glm::vec3& direction, RayKind kind) {
    (kind == RayKind::Camera ? rays_.camera : rays_.extension) += 1;
    RayQuery query{origin, direction, 0.0f, VKPT_FAR, filter_};
    return closestHitStack(scene_.tree, scene_.triangles, query, &traversal_);
}

bool SceneTracer::occluded(const glm::vec3& origin, const glm::vec3& direction, float tMax) {
    rays_.shadow += 1;
    RayQuery query{origin, direction, 0.0f, tMax, filter_};
    return anyHitStack(scene_.tree, scene_.triangles, query, &traversal_);
}

} // namespace vkpt
