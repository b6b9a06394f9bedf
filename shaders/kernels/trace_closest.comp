// trace_closest.comp — the extend stage: the closest hit of each ray in the current queue half,
// one ray per invocation (on lavapipe a walk must stay within the loop budget of docs/gpu.md).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

VKPT_TEXEL_BUFFER(BINDING_BVH_NODES, bvhNodes)
VKPT_READONLY_BUFFER(BINDING_TRIANGLES, Triangle, triangles)
VKPT_TEXEL_BUFFER(BINDING_TRIANGLE_TEXELS, triangleTexels)
VKPT_READONLY_BUFFER(BINDING_TRIANGLE_UVS, vec2, triangleUvs)
VKPT_READONLY_BUFFER(BINDING_MATERIALS, Material, materials)
VKPT_READONLY_BUFFER(BINDING_TEXTURES, TextureInfo, textures)
VKPT_READONLY_BUFFER(BINDING_TEXTURE_TEXELS, uint, textureTexels)
VKPT_READONLY_BUFFER(BINDING_RAYS, RayRecord, rays)
VKPT_WRITEONLY_BUFFER(BINDING_HITS, HitRecord, hits)
VKPT_BUFFER(BINDING_QUEUE_COUNTERS, uint, queueCounters)

#include "lib/traversal_stats.glsl"
#include "lib/traverse.glsl"

Traversal traceRay(uint i) {
    uint queueHalf = passParams.bounce & 1u;
    RayRecord ray = rays[queueHalf * frame.slotCount + i];
    Traversal walk = traceClosest(ray.origin, ray.direction, 0.0, VKPT_FAR);
    hits[i] = walk.hit;
    return walk;
}

void main() {
    uint i = flatInvocationIndex();
    bool inQueue = i < queueCounters[COUNTER_RAYS + (passParams.bounce & 1u)];
    countTraversal(inQueue ? traceRay(i) : noTraversal());
}
