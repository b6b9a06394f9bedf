// traverse.glsl — the stackless skip-link walk of the flattened BVH, exactly as host/bvh's
// closestHitStackless walks it: children in stored order, a missed box or a finished leaf
// continues at missIndex, an entered interior node at index + 1. A leaf's primitives are
// triangles or spheres (FEATURE_SPHERES); a crossing of an alpha-masked material's cut-out
// (FEATURE_ALPHA_MASK) is no hit, for every kind of ray, as the reference's AlphaMaskFilter
// decides, in the same order of crossings. Needs what lib/materials.glsl needs, and bvhNodes.
#ifndef VKPT_TRAVERSE_GLSL
#define VKPT_TRAVERSE_GLSL

#include "lib/materials.glsl"
#include "shared/intersect.h"
#include "shared/sphere.h"

struct Traversal {
    HitRecord hit;  // the closest hit found, triangle NO_HIT when none
    bool truncated; // the walk stopped before the end of the tree (see below)
    uint nodesVisited;
    uint triangleTests;
};

// The ray's crossing of `primitive` in (tMin, tMax), cut-outs included.
TriangleHit crossPrimitive(Triangle primitive, vec3 origin, vec3 direction, ShearedRay sheared,
                           float tMin, float tMax) {
    if (featureSpheres && isSpherePrimitive(primitive))
        return intersectSphere(origin, direction, primitive.v0, primitive.v1.x, tMin, tMax);
    return intersectTriangleWatertight(origin, sheared, primitive.v0, primitive.v1, primitive.v2,
                                       tMin, tMax);
}

// Whether crossing `h` of primitive `index` lies in an alpha-masked material's cut-out.
bool isCutOut(uint index, TriangleHit h, vec3 origin, vec3 direction) {
    Triangle primitive = triangles[index];
    bool sphere = featureSpheres && isSpherePrimitive(primitive);
    vec3 sphereNormal =
        sphere ? sphereNormalAt(origin + h.t * direction, primitive.v0) : vec3(0.0);
    return alphaMasked(index, primitive, h.u, h.v, sphereNormal);
}

// Where a walk stands: the next node to visit and, when a leaf was left half-tested, the rest
// of its primitives [leafNext, leafEnd).
struct WalkCursor {
    uint node;
    uint leafNext;
    uint leafEnd;
};

// A crossing that needs the alpha test before the walk may take it; primitive NO_HIT: none.
struct PendingCrossing {
    TriangleHit hit;
    uint primitive;
};

// Tests primitives [cursor.leafNext, cursor.leafEnd), taking each crossing closer than the
// best so far, until the range ends or a crossing needs the alpha test (returned, with the
// cursor just past it).
PendingCrossing testLeafRange(inout WalkCursor cursor, inout Traversal walk, vec3 origin,
                              vec3 direction, ShearedRay sheared, float tMin, bool stopAtFirst) {
    PendingCrossing pending;
    pending.primitive = NO_HIT;
    for (; cursor.leafNext < cursor.leafEnd; ++cursor.leafNext) {
        uint i = cursor.leafNext;
        ++walk.triangleTests;
        Triangle primitive = triangles[i];
        TriangleHit h = crossPrimitive(primitive, origin, direction, sheared, tMin, walk.hit.t);
        if (!h.hit) continue;
        // Marked at load time (PRIMITIVE_ALPHA_MASKED): no material read per crossing.
        if (featureAlphaMask && isAlphaMaskedPrimitive(primitive)) {
            pending = PendingCrossing(h, i);
            ++cursor.leafNext;
            break;
        }
        walk.hit = HitRecord(h.t, h.u, h.v, i);
        if (stopAtFirst) break;
    }
    return pending;
}

// Walks on from `cursor` until the tree ends or a crossing needs the alpha test.
// The loop runs while node < nodeCount: every node index is below it and BVH_END is not.
// Mesa 22.3's lavapipe silently leaves loops after 65,535 iterations per SIMD vector
// (docs/gpu.md); such a walk stops at a real node, so node != BVH_END afterwards reports it.
// The test is written so that the compiler cannot fold it away: the loop condition proves
// node >= nodeCount, not node == BVH_END.
PendingCrossing walkOn(inout WalkCursor cursor, inout Traversal walk, vec3 origin,
                       vec3 direction, vec3 invDirection, ShearedRay sheared, float tMin,
                       bool stopAtFirst) {
    PendingCrossing pending =
        testLeafRange(cursor, walk, origin, direction, sheared, tMin, stopAtFirst);
    if (pending.primitive != NO_HIT) return pending;
    if (stopAtFirst && walk.hit.triangle != NO_HIT) cursor.node = BVH_END;
    uint nodeCount = frame.nodeCount;
    while (cursor.node < nodeCount) {
        BvhNode node = bvhNodes[cursor.node];
        ++walk.nodesVisited;
        float entry =
            intersectBox(origin, invDirection, node.boundsMin, node.boundsMax, tMin, walk.hit.t);
        if (entry == VKPT_FAR || node.leafTriangles == 0u) {
            cursor.node = entry == VKPT_FAR ? node.missIndex : cursor.node + 1u;
            continue;
        }
        cursor.leafNext = leafFirstTriangle(node.leafTriangles);
        cursor.leafEnd = cursor.leafNext + leafTriangleCount(node.leafTriangles);
        cursor.node = node.missIndex;
        pending = testLeafRange(cursor, walk, origin, direction, sheared, tMin, stopAtFirst);
        if (pending.primitive != NO_HIT) break;
        if (stopAtFirst && walk.hit.triangle != NO_HIT) cursor.node = BVH_END;
    }
    return pending;
}

// The stackless skip-link walk. A crossing of an alpha-masked material is not tested inside
// the walk's loop: the walk stops there, the test runs once outside, and the walk resumes
// where it stopped, so it takes the same crossings in the same order as an inline test would.
// On lavapipe, which runs both sides of every branch as masked SIMD code, an inline test
// would cost a texture lookup per primitive tested, whatever the material.
Traversal walkBvh(vec3 origin, vec3 direction, float tMin, float tMax, bool stopAtFirst) {
    vec3 invDirection = safeInverseDirection(direction);
    // The watertight test's shear depends on the ray alone: once per walk, not per triangle.
    ShearedRay sheared = shearRay(direction);
    Traversal walk;
    walk.hit = HitRecord(tMax, 0.0, 0.0, NO_HIT);
    walk.nodesVisited = 0u;
    walk.triangleTests = 0u;
    WalkCursor cursor = WalkCursor(0u, 0u, 0u);
    PendingCrossing pending;
    do {
        pending = walkOn(cursor, walk, origin, direction, invDirection, sheared, tMin, stopAtFirst);
        if (featureAlphaMask && pending.primitive != NO_HIT &&
            !isCutOut(pending.primitive, pending.hit, origin, direction)) {
            walk.hit = HitRecord(pending.hit.t, pending.hit.u, pending.hit.v, pending.primitive);
            if (stopAtFirst) cursor = WalkCursor(BVH_END, 0u, 0u);
        }
    } while (featureAlphaMask && pending.primitive != NO_HIT);
    walk.truncated = cursor.node != BVH_END;
    return walk;
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
