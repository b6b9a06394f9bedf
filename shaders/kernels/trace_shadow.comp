// trace_shadow.comp — the connect stage: one light-sample record per invocation. A segment is
// an any-hit shadow ray (towards a light at infinity, one to VKPT_FAR); a probe (hemisphere
// estimator) a closest-hit ray that picks up the emission it reaches, or the environment when
// it leaves the scene. Unblocked records are marked SHADOW_VISIBLE for add_light_samples.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

#include "lib/kernel_bindings.h"

VKPT_DECLARE_BUFFERS(TRACE_SHADOW_BINDINGS)

#include "lib/environment.glsl"
#include "lib/materials.glsl"
#include "lib/traversal_stats.glsl"
#include "lib/traverse.glsl"

// What one record took: its walk, and whether it was a shadow segment or a probe.
struct RecordWork {
    Traversal walk;
    uint segments;
    uint probes;
};

RecordWork traceRecord(uint index) {
    RecordWork work = RecordWork(noTraversal(), 0u, 0u);
    ShadowRay record = fetchShadowRay(index);
    uint kind = record.flags & SHADOW_KIND_MASK;
    if (kind == SHADOW_NONE) return work;
    // One walk for both kinds: lavapipe runs both sides of a branch, so a walk on each side
    // would cost every record two walks' code.
    bool segment = kind == SHADOW_SEGMENT;
    work.walk = walkBvh(record.origin, record.direction, 0.0, record.tMax, segment);
    if (segment) {
        if (work.walk.hit.triangle == NO_HIT)
            shadowRays[index].flags = record.flags | SHADOW_VISIBLE;
        work.segments = 1u;
    } else {
        // The emission reached, or the environment when the probe leaves the scene.
        bool hit = work.walk.hit.triangle != NO_HIT;
        if (hit || hasEnvironment()) {
            vec3 found = hit ? emissionTowards(work.walk.hit.triangle, triangleHitOf(work.walk.hit),
                                               record.origin, record.direction)
                             : environmentRadianceAlong(record.direction);
            shadowRays[index].contribution = record.contribution * found * record.factor;
            shadowRays[index].flags = record.flags | SHADOW_VISIBLE;
        }
        work.probes = 1u;
    }
    return work;
}

void main() {
    uint index = flatInvocationIndex();
    uint records = queueCounters[COUNTER_RAYS + (passParams.bounce & 1u)] * frame.lightSamples;
    RecordWork work = index < records ? traceRecord(index) : RecordWork(noTraversal(), 0u, 0u);
    countTraversal(work.walk);
    addToCounter64InSubgroup(COUNTER_SHADOW_RAYS, work.segments);
    addToCounter64InSubgroup(COUNTER_EXTENSION_RAYS, work.probes);
}
