// trace_shadow.comp — the connect stage: one light-sample record per invocation. A segment is
// an any-hit shadow ray (towards a light at infinity, one to VKPT_FAR); a probe (hemisphere
// estimator) a closest-hit ray that picks up the emission it reaches, or the environment when
// it leaves the scene. Unblocked records are marked SHADOW_VISIBLE for add_light_samples.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

VKPT_READONLY_BUFFER(BINDING_BVH_NODES, BvhNode, bvhNodes)
VKPT_READONLY_BUFFER(BINDING_TRIANGLES, Triangle, triangles)
VKPT_READONLY_BUFFER(BINDING_TRIANGLE_UVS, vec2, triangleUvs)
VKPT_READONLY_BUFFER(BINDING_MATERIALS, Material, materials)
VKPT_READONLY_BUFFER(BINDING_TEXTURES, TextureInfo, textures)
VKPT_READONLY_BUFFER(BINDING_TEXTURE_TEXELS, uint, textureTexels)
VKPT_READONLY_BUFFER(BINDING_ENVIRONMENT_TEXELS, vec4, environmentTexels)
VKPT_READONLY_BUFFER(BINDING_ENVIRONMENT_CDF, float, environmentCdf)
VKPT_BUFFER(BINDING_SHADOW_RAYS, ShadowRay, shadowRays)
VKPT_BUFFER(BINDING_QUEUE_COUNTERS, uint, queueCounters)

#include "lib/environment.glsl"
#include "lib/materials.glsl"
#include "lib/traversal_stats.glsl"
#include "lib/traverse.glsl"

// Rays by kind within the workgroup, added to the 64-bit totals once per workgroup.
shared uint groupShadowRays;
shared uint groupProbeRays;

void traceRecord(uint index) {
    ShadowRay record = shadowRays[index];
    uint kind = record.flags & SHADOW_KIND_MASK;
    if (kind == SHADOW_NONE) return;
    // One walk for both kinds: lavapipe runs both sides of a branch, so a walk on each side
    // would cost every record two walks' code.
    bool segment = kind == SHADOW_SEGMENT;
    Traversal walk = walkBvh(record.origin, record.direction, 0.0, record.tMax, segment);
    if (segment) {
        if (walk.hit.triangle == NO_HIT) shadowRays[index].flags = record.flags | SHADOW_VISIBLE;
        atomicAdd(groupShadowRays, 1u);
    } else {
        // The emission reached, or the environment when the probe leaves the scene.
        bool hit = walk.hit.triangle != NO_HIT;
        if (hit || hasEnvironment()) {
            vec3 found = hit ? emissionTowards(walk.hit, record.origin, record.direction)
                             : environmentRadianceAlong(record.direction);
            shadowRays[index].contribution = record.contribution * found * record.factor;
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
