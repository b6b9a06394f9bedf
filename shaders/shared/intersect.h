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
// never computes 0·∞ = NaN for a ray that starts on a slab plane. The sign is the sign bit's, −0
// giving −1e30, as 1/x would: the wide walk picks each axis's near plane by the same sign bit
// (wide_bvh.h, rayOctant), and the two must agree. Rays moved into an instance's space, and
// orthographic camera rays, have −0 components.
VKPT_FN float safeReciprocal(float x) {
    const float tiny = VKPT_TINY_DIRECTION;
    bool negative = (floatBitsToUint(x) >> 31u) != 0u;
    return abs(x) > tiny ? 1.0f / x : (negative ? -1.0f / tiny : 1.0f / tiny);
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

VKPT_FN TriangleHit triangleMiss(float tMax) {
    TriangleHit miss;
    miss.t = tMax;
    miss.u = 0.0f;
    miss.v = 0.0f;
    miss.hit = false;
    return miss;
}

// Möller and Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection", JGT 2(1), 1997.
// Edges count as inside, but two triangles sharing an edge compute it differently, so a ray
// aimed at the edge can miss both (tests/extremes/watertight_test.cpp measured leaks of a few
// per cent for rays aimed exactly at edges). Kept to measure the watertight test's cost.
VKPT_FN TriangleHit intersectTriangleMollerTrumbore(vec3 origin, vec3 direction, vec3 v0, vec3 v1,
                                                    vec3 v2, float tMin, float tMax) {
    TriangleHit result = triangleMiss(tMax);
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

// Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection", JCGT 2(1), 2013. The
// vertices are sheared into a frame where the ray runs along +z through the origin; then the
// three 2D edge functions decide. Two triangles that share an edge evaluate its function from
// the same sheared vertices as a·b − c·d and c·d − a·b, exact negatives in floating point,
// so with inclusive tests at least one of them accepts a ray through the edge: no leaks.
// VKPT_PRECISE forbids the GPU compiler to fuse those products into an FMA, which would
// break the symmetry. Edges and vertices count as inside; both faces are hit; only t in
// (tMin, tMax) is a hit. u and v are the barycentric weights of v1 and v2.
struct ShearedRay {
    int kx;
    int ky;
    int kz;
    vec3 shear; // Sx, Sy, Sz
};

VKPT_FN ShearedRay shearRay(vec3 direction) {
    vec3 a = abs(direction);
    ShearedRay r;
    r.kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    r.kx = r.kz == 2 ? 0 : r.kz + 1;
    r.ky = r.kx == 2 ? 0 : r.kx + 1;
    if (direction[r.kz] < 0.0f) { // keep the winding: swap x and y
        int k = r.kx;
        r.kx = r.ky;
        r.ky = k;
    }
    r.shear = vec3(direction[r.kx] / direction[r.kz], direction[r.ky] / direction[r.kz],
                   1.0f / direction[r.kz]);
    return r;
}

VKPT_FN vec3 shearVertex(ShearedRay r, vec3 p) {
    VKPT_PRECISE float x = p[r.kx] - r.shear.x * p[r.kz];
    VKPT_PRECISE float y = p[r.ky] - r.shear.y * p[r.kz];
    return vec3(x, y, r.shear.z * p[r.kz]);
}

VKPT_FN float edgeFunction(vec3 a, vec3 b) {
    VKPT_PRECISE float value = a.x * b.y - a.y * b.x;
    return value;
}

VKPT_FN TriangleHit intersectTriangleWatertight(vec3 origin, ShearedRay ray, vec3 v0, vec3 v1,
                                                vec3 v2, float tMin, float tMax) {
    TriangleHit result = triangleMiss(tMax);
    vec3 a = shearVertex(ray, v0 - origin);
    vec3 b = shearVertex(ray, v1 - origin);
    vec3 c = shearVertex(ray, v2 - origin);
    float u = edgeFunction(c, b); // weight of v0
    float v = edgeFunction(a, c); // weight of v1
    float w = edgeFunction(b, a); // weight of v2
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return result;
    float det = u + v + w;
    if (det == 0.0f) return result; // seen edge-on, or degenerate
    // Barycentrics first: u·a.z + v·b.z + w·c.z grows as size³ and leaves the float range
    // beyond a scene size of about 1e13 (1e-13 on the small side); each b·z stays near size.
    vec3 bary = vec3(u, v, w) / det;
    float t = bary.x * a.z + bary.y * b.z + bary.z * c.z;
    if (!(t > tMin && t < tMax)) return result;
    result.t = t;
    result.u = bary.y;
    result.v = bary.z;
    result.hit = true;
    return result;
}

// The smallest float above t, for t >= 0 and finite: a test whose tMax is exclusive then
// also finds crossings at exactly t (VKPT_FAR becomes infinity, which is fine as a bound).
VKPT_FN float nextFloatUp(float t) {
    return uintBitsToFloat(floatBitsToUint(t) + 1u);
}

// Closest-hit walks keep the crossing with the smallest t and, among crossings at the same t
// (rays through a shared edge or vertex, coplanar duplicates), the one with the lowest
// primitive index, whatever order they meet them in; so the device's wide walk, the reference's
// stack walk and brute force agree on such rays, except where a walk passes over a box whose
// computed entry rounds above the best t although it holds a crossing at it (box entries and
// triangle hits round differently). A walk tests each primitive against
// (tMin, nextFloatUp(best t)) once it has a best crossing.
VKPT_FN bool crossingPrecedes(float t, uint primitive, float bestT, uint bestPrimitive) {
    return t < bestT || (t == bestT && primitive < bestPrimitive);
}

// The test both renderers use.
VKPT_FN TriangleHit intersectTriangle(vec3 origin, vec3 direction, vec3 v0, vec3 v1, vec3 v2,
                                      float tMin, float tMax) {
    return intersectTriangleWatertight(origin, shearRay(direction), v0, v1, v2, tMin, tMax);
}

// Unnormalised geometric normal; it points to the front side, from which v0, v1, v2 run
// counter-clockwise.
VKPT_FN vec3 triangleFaceNormal(vec3 v0, vec3 v1, vec3 v2) {
    return cross(v1 - v0, v2 - v0);
}

// The largest component magnitude of v.
VKPT_FN float largestMagnitude(vec3 v) {
    vec3 a = abs(v);
    return max(max(a.x, a.y), a.z);
}

// |v|, scaled by its largest component first: |v|² of a triangle's normal (size⁴) underflows
// below a size of about 1e-10 and overflows above 1e9, v/largest does neither.
VKPT_FN float scaledLength(vec3 v) {
    float largest = largestMagnitude(v);
    return largest > 0.0f ? largest * length(v / largest) : 0.0f;
}

// The unit geometric normal on the front side, robust at any scale (see scaledLength); the
// zero vector for a triangle without area.
VKPT_FN vec3 unitFaceNormal(vec3 v0, vec3 v1, vec3 v2) {
    vec3 n = triangleFaceNormal(v0, v1, v2);
    float largest = largestMagnitude(n);
    return largest > 0.0f ? normalize(n / largest) : vec3(0.0f);
}

// A triangle's area, robust at any scale where it is a finite float.
VKPT_FN float triangleAreaOf(vec3 v0, vec3 v1, vec3 v2) {
    return 0.5f * scaledLength(triangleFaceNormal(v0, v1, v2));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_INTERSECT_H
