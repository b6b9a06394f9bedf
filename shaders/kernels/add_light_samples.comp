// add_light_samples.comp — after trace_shadow: sums each ray's visible light samples in the
// order k = 0..N-1 and adds the sum to its path's radiance, as the reference adds its NEE
// estimate after the vertex's emission. A sum in fixed order keeps the image deterministic
// with no float atomics, and lets trace_shadow trace one record per invocation.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

#include "lib/kernel_bindings.h"

VKPT_DECLARE_BUFFERS(ADD_LIGHT_SAMPLES_BINDINGS)

#include "lib/records.glsl"

void main() {
    uint i = flatInvocationIndex();
    uint queueHalf = passParams.bounce & 1u;
    if (i >= queueCounters[COUNTER_RAYS + queueHalf]) return;
    uint n = frame.lightSamples;
    vec3 sum = vec3(0.0);
    bool visible = false;
    for (uint k = 0u; k < n; ++k) {
        ShadowRay record = fetchShadowRay(i * n + k);
        if ((record.flags & SHADOW_VISIBLE) == 0u) continue;
        sum += record.contribution;
        visible = true;
    }
    // Adding a zero sum would leave the radiance as it is.
    if (!visible) return;
    uint slot = fetchRay(queueHalf * frame.slotCount + i).slot;
    PathState state = fetchPathState(slot);
    if (frame.integrator == INTEGRATOR_PATH) {
        pathStates[slot].radiance = state.radiance + state.lightScale * sum;
    } else {
        pathStates[slot].radiance = state.radiance + sum / float(n);
    }
}
