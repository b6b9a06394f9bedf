// ray_box_test.h — intersect.h's slab test (gpu::intersectBox) for one ray against the many
// boxes of a CPU walk. What depends on the ray alone is worked out once: the inverse direction,
// which plane of each slab the ray meets first, and whether a zero direction component needs
// intersect.h's parallel-slab rule. Every box then costs the same float operations as
// intersectBox, minus the min/max that pick the planes and the parallel-slab selects, so the
// entry distance and the hit/miss answer are identical to intersectBox's bit for bit.
#pragma once

#include <glm/glm.hpp>

#include "shared/intersect.h"

namespace vkpt {

class RayBoxTest {
public:
    RayBoxTest(const glm::vec3& origin, const glm::vec3& direction)
        : origin_(origin), inv_(gpu::safeInverseDirection(direction)) {
        for (int k = 0; k < 3; ++k) {
            negative_[k] = inv_[k] < 0.0f;
            // intersectBox's slabFar applies where |1/d| reached 1/tiny: d was (almost) zero.
            parallel_ = parallel_ || std::abs(inv_[k]) >= 1.0f / VKPT_TINY_DIRECTION;
        }
    }

    // The entry distance of the box within (tMin, tMax), or VKPT_FAR on a miss: exactly
    // gpu::intersectBox(origin, 1/direction, lo, hi, tMin, tMax).
    float enter(const glm::vec3& lo, const glm::vec3& hi, float tMin, float tMax) const {
        if (parallel_) return gpu::intersectBox(origin_, inv_, lo, hi, tMin, tMax);
        // For 1/d > 0, (lo − o)/d <= (hi − o)/d in floats too (rounding is monotonic), so the
        // near plane is lo and min/max would pick the same values; for 1/d < 0 it is hi.
        float nearX = ((negative_[0] ? hi.x : lo.x) - origin_.x) * inv_.x;
        float farX = ((negative_[0] ? lo.x : hi.x) - origin_.x) * inv_.x;
        float nearY = ((negative_[1] ? hi.y : lo.y) - origin_.y) * inv_.y;
        float farY = ((negative_[1] ? lo.y : hi.y) - origin_.y) * inv_.y;
        float nearZ = ((negative_[2] ? hi.z : lo.z) - origin_.z) * inv_.z;
        float farZ = ((negative_[2] ? lo.z : hi.z) - origin_.z) * inv_.z;
        float enter = glm::max(glm::max(nearX, nearY), glm::max(nearZ, tMin));
        float exit = glm::min(glm::min(farX, farY), glm::min(farZ, tMax)) * 1.0000004f;
        return enter <= exit ? enter : VKPT_FAR;
    }

private:
    glm::vec3 origin_;
    glm::vec3 inv_;
    bool negative_[3] = {false, false, false};
    bool parallel_ = false;
};

} // namespace vkpt
