// ray_offset.h — where a secondary or shadow ray starts so that it cannot re-hit the surface
// it leaves, at any distance from the origin.
#ifndef VKPT_RAY_OFFSET_H
#define VKPT_RAY_OFFSET_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// The largest coordinate magnitude of a triangle: the scale of the rounding error in any point
// computed from its vertices (barycentric interpolation errs by a few ulps of it).
VKPT_FN float triangleCoordinateScale(vec3 v0, vec3 v1, vec3 v2) {
    vec3 m = max(max(abs(v0), abs(v1)), abs(v2));
    return max(max(m.x, m.y), m.z);
}

// A point moved off its surface along the geometric normal by RAY_OFFSET_EPSILONS float
// epsilons of the surface's coordinate scale. The error of a hit point interpolated from the
// vertices, and of the intersection test's plane distance, are a few epsilons of that scale
// wherever the triangle is, so the offset serves a millimetre part at the origin and a city
// block a million units away alike. Wächter and Binder ("A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6, 2019) move the point by 256 ulps of itself,
// with an absolute 1/65536 near the origin: that absolute step swallows a 1e-4-scale scene,
// and 256 ulps are a quarter of a metre at 1e4 (docs/numerical-stability.md measures both).
// 64 epsilons: tests/extremes/self_intersection_test.cpp found re-hits at 16 (1 in 10^6) and
// 32 (2 in 2·10^7), none at 64 in 2·10^7 triangles of size 1e-4..1e4 up to 1e6 away, leaving
// at grazing angles down to cos θ = 1e-4.
#define RAY_OFFSET_EPSILONS 64.0f
#define FLOAT_EPSILON 1.1920929e-7f

VKPT_FN vec3 offsetFromSurface(vec3 p, vec3 normal, float coordinateScale) {
    return p + normal * (RAY_OFFSET_EPSILONS * FLOAT_EPSILON * coordinateScale);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_RAY_OFFSET_H
