// traverse.glsl — the stackless skip-link walk of the flattened BVH, exactly as host/bvh's
// closestHitStackless walks it: children in stored order, a missed box or a finished leaf
// continues at missIndex, an entered interior node at index + 1. A leaf's primitives are
// triangles or spheres (FEATURE_SPHERES); a crossing of an alpha-masked material's cut-out
// (FEATURE_ALPHA_MASK) is no hit, for every kind of ray, as the reference's AlphaMaskFilter
// decides. Needs what lib/materials.glsl needs, and bvhNodes.
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

// The ray's crossing of primitive `index` in (tMin, tMax), unless it is an alpha-masked cut-out.
TriangleHit testPrimitive(uint index, vec3 origin, vec3 direction, ShearedRay sheared, float tMin,
                          float tMax) {
    Triangle primitive = triangles[index];
    bool sphere = featureSpheres && isSpherePrimitive(primitive);
    TriangleHit h;
    if (sphere) {
        h = intersectSphere(origin, direction, primitive.v0, primitive.v1.x, tMin, tMax);
    } else {
        h = intersectTriangleWatertight(origin, sheared, primitive.v0, primitive.v1, primitive.v2,
                                        tMin, tMax);
    }
    if (featureAlphaMask && h.hit) {
        vec3 sphereNormal =
            sphere ? sphereNormalAt(origin + h.t * direction, primitive.v0) : vec3(0.0);
        if (alphaMasked(index, primitive, h.u, h.v, sphereNormal)) h.hit = false;
    }
    return h;
}

// The loop runs while index < nodeCount: every node index is below it and BVH_END is not.
// Mesa 22.3's lavapipe silently leaves loops after 65,535 iterations per SIMD vector
// (docs/gpu.md); such a walk stops at a real node, so index != BVH_END afterwards reports
// it. The test is written so that the compiler cannot fold it away: the loop condition
// proves index >= nodeCount, not index == BVH_END.
Traversal walkBvh(vec3 origin, vec3 direction, float tMin, float tMax, bool stopAtFirst) {
    vec3 invDirection = safeInverseDirection(direction);
    // The watertight test's shear depends on the ray alone: once per walk, not per triangle.
    ShearedRay sheared = shearRay(direction);
    Traversal walk;
    walk.hit = HitRecord(tMax, 0.0, 0.0, NO_HIT);
    walk.nodesVisited = 0u;
    walk.triangleTests = 0u;
    uint nodeCount = frame.nodeCount;
    uint index = 0u;
    while (index < nodeCount) {
        BvhNode node = bvhNodes[index];
        ++walk.nodesVisited;
        float entry =
            intersectBox(origin, invDirection, node.boundsMin, node.boundsMax, tMin, walk.hit.t);
        if (entry == VKPT_FAR || node.leafTriangles == 0u) {
            index = entry == VKPT_FAR ? node.missIndex : index + 1u;
            continue;
        }
        uint first = leafFirstTriangle(node.leafTriangles);
        uint end = first + leafTriangleCount(node.leafTriangles);
        for (uint i = first; i < end; ++i) {
            ++walk.triangleTests;
            TriangleHit h = testPrimitive(i, origin, direction, sheared, tMin, walk.hit.t);
            if (!h.hit) continue;
            walk.hit = HitRecord(h.t, h.u, h.v, i);
            if (stopAtFirst) break;
        }
        index = (stopAtFirst && walk.hit.triangle != NO_HIT) ? BVH_END : node.missIndex;
    }
    walk.truncated = index != BVH_END;
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
