// traverse.glsl — the kernels' BVH walk: shared/wide_bvh.h's stackless walk of the 8-wide
// compressed nodes, reading nodes, primitives and (two-level scenes, FEATURE_INSTANCES)
// instances as texels (lib/records.glsl). A
// leaf's primitives are triangles or spheres (FEATURE_SPHERES); a crossing of an alpha-masked
// material's cut-out (FEATURE_ALPHA_MASK, shared/materials.h's isCutOut, which the
// reference's AlphaMaskFilter asks too) is no hit, for every kind of ray, in the same order of
// crossings. Reads what lib/materials.glsl reads, and bvhNodes and instances.
#ifndef VKPT_TRAVERSE_GLSL
#define VKPT_TRAVERSE_GLSL

#include "lib/materials.glsl"

uvec4 bvhNodeTexel(uint texel) {
    return bvhNodesAt(texel);
}

Triangle bvhPrimitive(uint index) {
    return fetchTriangle(index);
}

bool bvhHasSpheres() {
    return featureSpheres;
}

bool bvhHasAlphaMask() {
    return featureAlphaMask;
}

bool bvhHasInstances() {
    return featureInstances;
}

Instance bvhInstance(uint index) {
    return fetchWalkInstance(index);
}

#include "shared/wide_bvh.h"

struct Traversal {
    HitRecord hit;  // the closest hit found, triangle NO_HIT when none
    uint instance;  // its instance (two-level scenes), else NO_INSTANCE
    bool truncated; // the walk stopped before its end (a driver's loop limit, docs/gpu.md)
    uint nodesVisited;
    uint triangleTests;
};

// The walk. A crossing of an alpha-masked material is not tested inside the walk's loops:
// the walk stops there, the test runs once outside, and the walk resumes where it stopped, so
// it takes the same crossings in the same order as an inline test would. On lavapipe, which
// runs both sides of every branch as masked SIMD code, an inline test would cost a texture
// lookup per primitive tested, whatever the material.
Traversal walkBvh(vec3 origin, vec3 direction, float tMin, float tMax, bool stopAtFirst) {
    WideWalk walk = beginWideWalk(origin, direction, tMin, tMax, stopAtFirst);
    PendingCrossing pending;
    do {
        pending = continueWideWalk(walk);
        if (featureAlphaMask && pending.primitive != NO_PRIMITIVE &&
            !isCutOut(pending.primitive, WALK_INSTANCE(walk), pending.hit, origin, direction))
            takeCrossing(walk, pending.hit, pending.primitive);
    } while (featureAlphaMask && pending.primitive != NO_PRIMITIVE);
    Traversal result;
    result.hit = HitRecord(walk.t, walk.u, walk.v, walk.primitive);
    result.instance = walk.hitInstance;
    result.truncated = wideWalkTruncated(walk);
    result.nodesVisited = walk.nodesVisited;
    result.triangleTests = walk.primitiveTests;
    return result;
}

// The closest hit with t in (tMin, tMax).
Traversal traceClosest(vec3 origin, vec3 direction, float tMin, float tMax) {
    return walkBvh(origin, direction, tMin, tMax, false);
}

// Any hit with t in (tMin, tMax): hit.triangle is some hit triangle, or NO_HIT.
Traversal traceAny(vec3 origin, vec3 direction, float tMin, float tMax) {
    return walkBvh(origin, direction, tMin, tMax, true);
}

#endif // VKPT_TRAVERSE_GLSL
