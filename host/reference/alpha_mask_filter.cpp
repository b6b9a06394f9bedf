// alpha_mask_filter.cpp — a crossing counts unless the material's alpha there is below its cutoff.
#include "reference/alpha_mask_filter.h"

#include "shared/materials.h"

namespace vkpt {

bool AlphaMaskFilter::accepts(std::uint32_t primitive, std::uint32_t instance, const RayQuery& ray,
                              const gpu::TriangleHit& hit) const {
    return !gpu::isCutOut(primitive, instance, hit, ray.origin, ray.direction, view_);
}

} // namespace vkpt
