// scene_tracer.cpp — counts each query and forwards it to the stack traversal.
#include "reference/scene_tracer.h"

namespace vkpt {

ClosestHit SceneTracer::closest(const glm::vec3& origin, const glm::vec3& direction,
                                RayKind kind) {
    (kind == RayKind::Camera ? rays_.camera : rays_.extension) += 1;
    RayQuery query{origin, direction, 0.0f, VKPT_FAR};
    return closestHitStack(scene_.tree, scene_.triangles, query, &traversal_);
}

bool SceneTracer::occluded(const glm::vec3& origin, const glm::vec3& toTarget) {
    rays_.shadow += 1;
    RayQuery query{origin, toTarget, 0.0f, 1.0f};
    return anyHitStack(scene_.tree, scene_.triangles, query, &traversal_);
}

} // namespace vkpt
