// trace_closest.comp — the extend stage: the closest hit of each ray in the current queue half,
// one ray per invocation (on lavapipe a walk must stay within the loop budget of docs/gpu.md).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

#include "lib/kernel_bindings.h"

VKPT_DECLARE_BUFFERS(TRACE_CLOSEST_BINDINGS)

#include "lib/traversal_stats.glsl"
#include "lib/traverse.glsl"

Traversal traceRay(uint i) {
    uint queueHalf = passParams.bounce & 1u;
    RayRecord ray = fetchRay(queueHalf * frame.slotCount + i);
    Traversal walk = traceClosest(ray.origin, ray.direction, 0.0, VKPT_FAR);
    hits[i] = walk.hit;
#if VKPT_INSTANCES
    hitInstances[i] = walk.instance;
#endif
    return walk;
}

void main() {
    uint i = flatInvocationIndex();
    bool inQueue = i < queueCounters[COUNTER_RAYS + (passParams.bounce & 1u)];
    countTraversal(inQueue ? traceRay(i) : noTraversal());
}
