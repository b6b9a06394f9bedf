// pair_box_test.h — intersect.h's slab test (gpu::intersectBox) of one ray against both boxes of
// a StackBvhPair at once, in 4-wide float vectors (GCC's vector extensions: SSE on x86-64). A
// pair stores each slab as (min₀, min₁, max₀, max₁), so one subtraction and one multiplication
// give all four plane distances of a slab; a swap of the halves lines each min up with its max.
// Each lane does the float operations intersectBox does, in the same order where order matters
// (max and min are exact, so their grouping does not), so both entry distances and hit/miss
// answers are intersectBox's bit for bit.
#pragma once

#include <cstring>

#include <glm/glm.hpp>

#include "bvh/bvh_stack_layout.h"
#include "shared/intersect.h"

namespace vkpt {

using Float4 = float __attribute__((vector_size(16)));

class PairBoxTest {
public:
    PairBoxTest(const glm::vec3& origin, const glm::vec3& direction) {
        const glm::vec3 inv = gpu::safeInverseDirection(direction);
        const float o[3] = {origin.x, origin.y, origin.z}, i[3] = {inv.x, inv.y, inv.z};
        for (int k = 0; k < 3; ++k) {
            origin_[k] = splat(o[k]);
            inv_[k] = splat(i[k]);
            // intersectBox's slabFar applies where |1/d| reached 1/tiny: d was (almost) zero.
            parallel_[k] = std::abs(i[k]) >= 1.0f / VKPT_TINY_DIRECTION;
            anyParallel_ = anyParallel_ || parallel_[k];
        }
    }

    struct Entries {
        float child[2]; // entry distance into each child's box, VKPT_FAR where missed
    };

    Entries enter(const StackBvhPair& pair, float tMin, float tMax) const {
        Float4 nearX, farX, nearY, farY, nearZ, farZ;
        planes(pair, 0, nearX, farX);
        planes(pair, 1, nearY, farY);
        planes(pair, 2, nearZ, farZ);
        if (anyParallel_) { // rare: a direction component (almost) zero
            if (parallel_[0]) farX = slabFar(farX);
            if (parallel_[1]) farY = slabFar(farY);
            if (parallel_[2]) farZ = slabFar(farZ);
        }
        const Float4 enter = max(max(nearX, nearY), max(nearZ, splat(tMin)));
        const Float4 exit = min(min(farX, farY), min(farZ, splat(tMax))) * 1.0000004f;
        return {
            {enter[0] <= exit[0] ? enter[0] : VKPT_FAR, enter[1] <= exit[1] ? enter[1] : VKPT_FAR}};
    }

private:
    // The near and far plane distances of slab k for both children (lanes 0 and 1).
    void planes(const StackBvhPair& pair, int k, Float4& nearest, Float4& farthest) const {
        Float4 slab;
        std::memcpy(&slab, pair.slabs[k], sizeof slab);
        const Float4 t = (slab - origin_[k]) * inv_[k]; // (min₀, min₁, max₀, max₁) planes
        const Float4 swapped = __builtin_shufflevector(t, t, 2, 3, 0, 1);
        nearest = min(t, swapped);
        farthest = max(t, swapped);
    }

    static Float4 splat(float x) { return Float4{x, x, x, x}; }
    static Float4 min(Float4 a, Float4 b) { return a < b ? a : b; }
    static Float4 max(Float4 a, Float4 b) { return a > b ? a : b; }
    // intersect.h's slabFar for a slab the ray runs parallel to: inside it for all t.
    static Float4 slabFar(Float4 tFar) { return tFar >= 0.0f ? splat(VKPT_FAR) : tFar; }

    Float4 origin_[3];
    Float4 inv_[3];
    bool parallel_[3] = {false, false, false};
    bool anyParallel_ = false;
};

} // namespace vkpt
