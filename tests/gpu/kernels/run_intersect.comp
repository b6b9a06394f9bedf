// run_intersect.comp — shared/intersect.h on the device: one ray against one triangle and one
// box per invocation.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "kernel_test_io.h"
#include "lib/buffers.glsl"
#include "shared/intersect.h"

layout(local_size_x = WORKGROUP_SIZE) in;
layout(push_constant) uniform Params {
    uint count;
}
params;

VKPT_READONLY_BUFFER(0, IntersectInput, intersectInputs)
VKPT_WRITEONLY_BUFFER(1, IntersectOutput, intersectOutputs)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count) return;
    IntersectInput r = intersectInputs[i];
    TriangleHit hit = intersectTriangle(r.origin.xyz, r.direction.xyz, r.v0.xyz, r.v1.xyz, r.v2.xyz,
                                        r.origin.w, r.direction.w);
    vec3 inverseDirection = safeInverseDirection(r.direction.xyz);
    float entry = intersectBox(r.origin.xyz, inverseDirection, r.boxMin.xyz, r.boxMax.xyz,
                               r.origin.w, r.direction.w);
    IntersectOutput o;
    o.triangle = vec4(hit.t, hit.u, hit.v, 0.0);
    o.hits = uvec4(hit.hit ? 1u : 0u, entry < VKPT_FAR ? 1u : 0u, 0u, 0u);
    o.box = vec4(entry, 0.0, 0.0, 0.0);
    o.inverseDirection = vec4(inverseDirection, 0.0);
    o.faceNormal = vec4(triangleFaceNormal(r.v0.xyz, r.v1.xyz, r.v2.xyz), 0.0);
    intersectOutputs[i] = o;
}
