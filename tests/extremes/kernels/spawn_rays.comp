// spawn_rays.comp — a secondary ray spawned on the device exactly as shade_hits spawns one (the
// hit point from barycentrics, the unit face normal, offsetFromSurface), then tested against the
// triangle it left: the device's own rounding (fused multiply-adds included) must not re-hit.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/buffers.glsl"
#include "shared/intersect.h"
#include "shared/ray_offset.h"
#include "spawn_io.h"

layout(local_size_x = WORKGROUP_SIZE) in;
layout(push_constant) uniform Params {
    uint count;
}
params;

VKPT_READONLY_BUFFER(0, SpawnInput, spawnInputs)
VKPT_WRITEONLY_BUFFER(1, SpawnOutput, spawnOutputs)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count) return;
    SpawnInput s = spawnInputs[i];
    vec3 v0 = s.v0.xyz, v1 = s.v1.xyz, v2 = s.v2.xyz;
    // As shared/surface.h computes the hit point and the normal.
    vec3 p = v0 * s.barycentrics.x + v1 * s.barycentrics.y + v2 * s.barycentrics.z;
    vec3 normal = unitFaceNormal(v0, v1, v2) * s.barycentrics.w;
    vec3 origin = offsetFromSurface(p, normal, triangleCoordinateScale(v0, v1, v2));
    TriangleHit hit = intersectTriangle(origin, s.direction.xyz, v0, v1, v2, 0.0, VKPT_FAR);
    spawnOutputs[i] = SpawnOutput(vec4(origin, hit.hit ? 1.0 : 0.0));
}
