// run_sampling.comp — shared/sampling.h on the device, one record per invocation.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "kernel_test_io.h"
#include "lib/buffers.glsl"
#include "shared/sampling.h"

layout(local_size_x = WORKGROUP_SIZE) in;
layout(push_constant) uniform Params {
    uint count;
}
params;

VKPT_READONLY_BUFFER(0, SamplingInput, samplingInputs)
VKPT_WRITEONLY_BUFFER(1, SamplingOutput, samplingOutputs)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count) return;
    SamplingInput s = samplingInputs[i];
    vec3 cosineDirection = sampleCosineHemisphere(s.u.xy);
    Basis basis = makeBasis(s.normal.xyz);
    SamplingOutput o;
    o.cosineDirection = vec4(cosineDirection, cosineHemispherePdf(s.normal.w));
    o.uniformDirection = vec4(sampleUniformHemisphere(s.u.xy), uniformHemispherePdf());
    o.barycentrics = vec4(sampleTriangleBarycentrics(s.u.xy), luminance(s.color.rgb));
    o.tangent = vec4(basis.tangent, powerHeuristic(s.mis.x, s.mis.y, s.mis.z, s.mis.w));
    o.bitangent = vec4(basis.bitangent, 0.0);
    o.worldDirection = vec4(basisToWorld(basis, cosineDirection), 0.0);
    samplingOutputs[i] = o;
}
