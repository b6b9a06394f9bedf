// alpha_mask_filter.cpp — a crossing counts unless the material's alpha there is below its cutoff.
#include "reference/alpha_mask_filter.h"

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

} // namespace vkpt
