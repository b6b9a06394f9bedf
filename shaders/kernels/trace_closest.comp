// trace_closest.comp — the extend stage: the closest hit of each ray in the current queue half,
// one ray per invocation (on lavapipe a walk must stay within the loop budget of docs/gpu.md).
// A camera ray (bounce 0) passes the back faces of single-sided opaque materials
// (shared/camera_culling.h), as the reference's SceneTracer does.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

#include "lib/kernel_bindings.h"

VKPT_DECLARE_BUFFERS(TRACE_CLOSEST_BINDINGS)

#include "lib/traversal_stats.glsl"
#include "lib/traverse.glsl"
#include "shared/camera_culling.h"

// The closest hit, passing (camera rays) the back faces the camera does not see: the walk again
// from each culled crossing's t, the same ray, so that it finds what lies beyond (t > that t, as
// the reference's re-query). One call of the walk, so that the driver inlines it once.
Traversal traceRay(uint i) {
    uint queueHalf = passParams.bounce & 1u;
    RayRecord ray = fetchRay(queueHalf * frame.slotCount + i);
    Traversal walk = noTraversal();
    float tMin = 0.0;
    uint walks = 0u;
    bool again;
    do {
        Traversal beyond = traceClosest(ray.origin, ray.direction, tMin, VKPT_FAR);
        beyond.nodesVisited += walk.nodesVisited;
        beyond.triangleTests += walk.triangleTests;
        beyond.truncated = beyond.truncated || walk.truncated;
        walk = beyond;
        tMin = walk.hit.t;
        again = passParams.bounce == 0u && walks < CAMERA_CULLED_FACES_MAX &&
                walk.hit.triangle != NO_HIT &&
                hiddenFromCamera(walk.hit.triangle, walk.instance,
                                 TriangleHit(walk.hit.t, walk.hit.u, walk.hit.v, true), ray.origin,
                                 ray.direction);
        ++walks;
    } while (again);
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
