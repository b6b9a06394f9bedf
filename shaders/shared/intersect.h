// intersect.h — ray/box and ray/triangle tests shared by the CPU reference and the kernels.
#ifndef VKPT_INTERSECT_H
#define VKPT_INTERSECT_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

struct TriangleHit {
    float t;
    float u; // barycentric weight of v1
    float v; // barycentric weight of v2
    bool hit;
};

// Direction components no larger than this count as zero: their reciprocal is ±1/tiny.
#define VKPT_TINY_DIRECTION 1e-30f

// 1/x without infinities: a zero direction component becomes ±1e30, so the slab test below
// never computes 0·∞ = NaN for a ray that starts on a slab plane.
VKPT_FN float safeReciprocal(float x) {
    const float tiny = VKPT_TINY_DIRECTION;
    return abs(x) > tiny ? 1.0f / x : (x >= 0.0f ? 1.0f / tiny : -1.0f / tiny);
}

VKPT_FN vec3 safeInverseDirection(vec3 d) {
    return vec3(safeReciprocal(d.x), safeReciprocal(d.y), safeReciprocal(d.z));
}

// The far distance of one slab. For a ray parallel to the slab (a zero direction component)
// that starts on one of its planes, (plane - origin)·(1/tiny) = 0 would end the ray at t = 0
// on the far plane, so a ray running along a face or an edge would miss the box while it hits
// the triangles whose edges lie there. Such a ray lies in the closed slab for all t (as with
// pbrt's IEEE infinities, where the NaN drops out of the comparison): its far distance is FAR.
// A parallel ray outside the slab still misses: its near distance δ/tiny > 0 stays, or its far
// distance is negative.
VKPT_FN float slabFar(float tFar, float invDirection) {
    return (abs(invDirection) >= 1.0f / VKPT_TINY_DIRECTION && tFar >= 0.0f) ? VKPT_FAR : tFar;
}

// Slab test; returns the entry distance, or VKPT_FAR on a miss. The exit distance is widened
// by 1 + 2γ₃ so that rounding cannot reject a box the ray really touches (Ize, "Robust BVH
// Ray Traversal", JCGT 2(2), 2013; pbrt-v4 Bounds3::IntersectP). Touching a face, an edge
// or a corner counts as a hit.
VKPT_FN float intersectBox(vec3 origin, vec3 invDirection, vec3 boxMin, vec3 boxMax, float tMin,
                           float tMax) {
    vec3 t0 = (boxMin - origin) * invDirection;
    vec3 t1 = (boxMax - origin) * invDirection;
    vec3 tNear = min(t0, t1);
    vec3 tFar = max(t0, t1);
    tFar = vec3(slabFar(tFar.x, invDirection.x), slabFar(tFar.y, invDirection.y),
                slabFar(tFar.z, invDirection.z));
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, tMin));
    float exit = min(min(tFar.x, tFar.y), min(tFar.z, tMax)) * 1.0000004f;
    return enter <= exit ? enter : VKPT_FAR;
}

// Möller and Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection", JGT 2(1), 1997.
// Edges and vertices count as inside; both faces are hit; only t in (tMin, tMax) is a hit.
VKPT_FN TriangleHit intersectTriangle(vec3 origin, vec3 direction, vec3 v0, vec3 v1, vec3 v2,
                                      float tMin, float tMax) {
    TriangleHit result;
    result.t = tMax;
    result.u = 0.0f;
    result.v = 0.0f;
    result.hit = false;
    vec3 e1 = v1 - v0;
    vec3 e2 = v2 - v0;
    vec3 p = cross(direction, e2);
    float det = dot(e1, p);
    if (det == 0.0f) return result; // parallel to the plane, or a degenerate triangle
    float invDet = 1.0f / det;
    vec3 s = origin - v0;
    float u = dot(s, p) * invDet;
    if (!(u >= 0.0f && u <= 1.0f)) return result;
    vec3 q = cross(s, e1);
    float v = dot(direction, q) * invDet;
    if (!(v >= 0.0f && u + v <= 1.0f)) return result;
    float t = dot(e2, q) * invDet;
    if (!(t > tMin && t < tMax)) return result;
    result.t = t;
    result.u = u;
    result.v = v;
    result.hit = true;
    return result;
}

// Unnormalised geometric normal; it points to the front side, from which v0, v1, v2 run
// counter-clockwise.
VKPT_FN vec3 triangleFaceNormal(vec3 v0, vec3 v1, vec3 v2) { return cross(v1 - v0, v2 - v0); }

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_INTERSECT_H
