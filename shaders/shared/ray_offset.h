// ray_offset.h — where a secondary or shadow ray starts so that it cannot re-hit the surface
// it leaves, at any distance from the origin.
#ifndef VKPT_RAY_OFFSET_H
#define VKPT_RAY_OFFSET_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Wächter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing
// Gems, chapter 6, 2019: move the point a fixed number of float ULPs along the geometric
// normal (which scales with the point's magnitude, as the hit point's rounding error does),
// and by a small absolute distance near the origin where ULPs become tiny.
#define RAY_OFFSET_ORIGIN (1.0f / 32.0f)
#define RAY_OFFSET_FLOAT_SCALE (1.0f / 65536.0f)
#define RAY_OFFSET_INT_SCALE 256.0f

VKPT_FN float offsetCoordinate(float p, float n) {
    int ulps = int(RAY_OFFSET_INT_SCALE * n);
    float moved = intBitsToFloat(floatBitsToInt(p) + (p < 0.0f ? -ulps : ulps));
    return abs(p) < RAY_OFFSET_ORIGIN ? p + RAY_OFFSET_FLOAT_SCALE * n : moved;
}

// normal: the unit geometric normal on the side the new ray leaves towards.
VKPT_FN vec3 offsetRayOrigin(vec3 p, vec3 normal) {
    return vec3(offsetCoordinate(p.x, normal.x), offsetCoordinate(p.y, normal.y),
                offsetCoordinate(p.z, normal.z));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_RAY_OFFSET_H
