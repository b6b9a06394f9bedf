// instance.h — rays into an instance's mesh and hits back out to world space (host_device.h,
// Instance), for the walks (wide_bvh.h, the reference's stack walk) and for shading (surface.h).
// Pure functions of the record, compiled by the kernels and by the CPU alike.
#ifndef VKPT_INSTANCE_H
#define VKPT_INSTANCE_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Rows r0, r1, r2 of a 3×4 affine transform applied to a point and to a vector.
VKPT_FN vec3 transformPoint(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
    vec4 h = vec4(p, 1.0f);
    return vec3(dot(r0, h), dot(r1, h), dot(r2, h));
}

VKPT_FN vec3 transformVector(vec4 r0, vec4 r1, vec4 r2, vec3 v) {
    return vec3(dot(vec3(r0), v), dot(vec3(r1), v), dot(vec3(r2), v));
}

// A world-space ray in the instance's mesh space. The direction is not normalised, so that a
// crossing's t is the same in both spaces and one best t serves the whole walk.
VKPT_FN vec3 instanceRayOrigin(Instance x, vec3 worldOrigin) {
    return transformPoint(x.worldToObject0, x.worldToObject1, x.worldToObject2, worldOrigin);
}

VKPT_FN vec3 instanceRayDirection(Instance x, vec3 worldDirection) {
    return transformVector(x.worldToObject0, x.worldToObject1, x.worldToObject2, worldDirection);
}

// A point of the mesh in world space.
VKPT_FN vec3 instancePointToWorld(Instance x, vec3 p) {
    return transformPoint(x.objectToWorld0, x.objectToWorld1, x.objectToWorld2, p);
}

// A vector along the surface (an edge, a tangent) in world space.
VKPT_FN vec3 instanceVectorToWorld(Instance x, vec3 v) {
    return transformVector(x.objectToWorld0, x.objectToWorld1, x.objectToWorld2, v);
}

// A normal in world space, unit: the inverse transpose, which is worldToObject's transpose; it
// keeps the normal on the side of the surface it was on whatever the determinant's sign (as
// the loader's flattened normals, scene/gltf_primitives.cpp). A zero normal stays zero.
VKPT_FN vec3 instanceNormalToWorld(Instance x, vec3 n) {
    vec3 w =
        n.x * vec3(x.worldToObject0) + n.y * vec3(x.worldToObject1) + n.z * vec3(x.worldToObject2);
    float l = length(w);
    return l > 0.0f ? w / l : vec3(0.0f);
}

// A tangent (xyz, w the bitangent sign) in world space, as the loader transforms a flattened
// one: xyz along the surface, unit; w flipped by a mirroring transform, since the normal keeps
// its side while cross(n, t) turns over. w = 0 (no tangent frame) stays all zero.
VKPT_FN vec4 instanceTangentToWorld(Instance x, vec4 t) {
    if (t.w == 0.0f) return vec4(0.0f);
    vec3 w = instanceVectorToWorld(x, vec3(t));
    float l = length(w);
    float sign = (x.flags & INSTANCE_MIRRORED) != 0u ? -t.w : t.w;
    return l > 0.0f ? vec4(w / l, sign) : vec4(0.0f);
}

// Among crossings at the same t the one of the lower instance wins, then the lower primitive
// (intersect.h, crossingPrecedes, whose rule this extends: NO_INSTANCE, the single-level case,
// compares equal to itself).
VKPT_FN bool instancedCrossingPrecedes(float t, uint instance, uint primitive, float bestT,
                                       uint bestInstance, uint bestPrimitive) {
    return t < bestT || (t == bestT && (instance < bestInstance ||
                                        (instance == bestInstance && primitive < bestPrimitive)));
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_INSTANCE_H
