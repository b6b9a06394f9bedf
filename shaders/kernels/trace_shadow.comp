// trace_shadow.comp — the connect stage: one light-sample record per invocation. A segment is
// an any-hit shadow ray; a probe (hemisphere estimator) a closest-hit ray that picks up the
// emission it reaches. Unblocked records are marked SHADOW_VISIBLE for add_light_samples.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

VKPT_READONLY_BUFFER(BINDING_BVH_NODES, BvhNode, bvhNodes)
VKPT_READONLY_BUFFER(BINDING_TRIANGLES, Triangle, triangles)
VKPT_READONLY_BUFFER(BINDING_MATERIALS, Material, materials)
VKPT_BUFFER(BINDING_SHADOW_RAYS, ShadowRay, shadowRays)
VKPT_BUFFER(BINDING_QUEUE_COUNTERS, uint, queueCounters)

#include "lib/traversal_stats.glsl"
#include "lib/traverse.glsl"

// Rays by kind within the workgroup, added to the 64-bit totals once per workgroup.
shared uint groupShadowRays;
shared uint groupProbeRays;

// The emission a probe's hit sends back along it: front face only unless double-sided, as
// host/reference/surface.cpp decides (makeSurfacePoint's frontFace, emittedRadiance).
vec3 emissionTowards(uint triangle, vec3 direction) {
    Triangle tri = triangles[triangle];
    vec3 face = unitFaceNormal(tri.v0, tri.v1, tri.v2);
    Material material = materials[tri.materialIndex];
    bool emitsHere = dot(face, direction) < 0.0 || (material.flags & MATERIAL_DOUBLE_SIDED) != 0u;
    return emitsHere ? material.emission : vec3(0.0);
}

void traceRecord(uint index) {
    ShadowRay record = shadowRays[index];
    uint kind = record.flags & SHADOW_KIND_MASK;
    if (kind == SHADOW_NONE) return;
    Traversal walk;
    if (kind == SHADOW_SEGMENT) {
        walk = traceAny(record.origin, record.direction, 0.0, record.tMax);
        if (walk.hit.triangle == NO_HIT) shadowRays[index].flags = record.flags | SHADOW_VISIBLE;
        atomicAdd(groupShadowRays, 1u);
    } else {
        walk = traceClosest(record.origin, record.direction, 0.0, record.tMax);
        if (walk.hit.triangle != NO_HIT) {
            vec3 emitted = emissionTowards(walk.hit.triangle, record.direction);
            shadowRays[index].contribution = record.contribution * emitted * record.factor;
            shadowRays[index].flags = record.flags | SHADOW_VISIBLE;
        }
        atomicAdd(groupProbeRays, 1u);
    }
    countTraversal(walk);
}

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        groupShadowRays = 0u;
        groupProbeRays = 0u;
    }
    beginTraversalStats();
    uint index = flatInvocationIndex();
    uint records = queueCounters[COUNTER_RAYS + (passParams.bounce & 1u)] * frame.lightSamples;
    if (index < records) traceRecord(index);
    endTraversalStats();
    if (gl_LocalInvocationIndex == 0u) {
        addToCounter64(COUNTER_SHADOW_RAYS, groupShadowRays);
        addToCounter64(COUNTER_EXTENSION_RAYS, groupProbeRays);
    }
}
