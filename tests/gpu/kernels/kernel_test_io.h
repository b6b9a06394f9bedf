// kernel_test_io.h — the records that test kernels read and write, declared once for the C++
// tests and the GLSL kernels, under the same layout rules as shared/host_device.h (vec4s and
// 4-byte scalars only, so std430 and C++ agree without padding).
#ifndef VKPT_KERNEL_TEST_IO_H
#define VKPT_KERNEL_TEST_IO_H

#include "lib/wavefront.h"
#include "shared/host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu::test {
#endif

// run_rng: one call of randomBits, randomFloats and shared/sampler.h's sampleFloats per record.
struct RngInput {
    uint seed;
    uint pixel;
    uint sampleIndex;
    uint bounce;
    uint dimension;
    uint samplerSetup; // makeSamplerSetup's word
    uint width;        // the image width sampleFloats reads the pixel's coordinates with
    uint unused0;
};
struct RngOutput {
    uvec4 bits;
    vec4 floats;
    vec4 sampled; // sampleFloats
};

// run_sampling: every function of shared/sampling.h on one record.
struct SamplingInput {
    vec4 u;      // .xy: the uniform sample of the warps
    vec4 normal; // .xyz: unit normal for makeBasis; .w: cos θ for cosineHemispherePdf
    vec4 mis;    // powerHeuristic(nf, fPdf, ng, gPdf)
    vec4 color;  // .rgb for luminance
};
struct SamplingOutput {
    vec4 cosineDirection;  // sampleCosineHemisphere(u); .w: cosineHemispherePdf(normal.w)
    vec4 uniformDirection; // sampleUniformHemisphere(u); .w: uniformHemispherePdf()
    vec4 barycentrics;     // sampleTriangleBarycentrics(u); .w: luminance(color)
    vec4 tangent;          // makeBasis(normal).tangent; .w: powerHeuristic(mis)
    vec4 bitangent;        // makeBasis(normal).bitangent
    vec4 worldDirection;   // basisToWorld(makeBasis(normal), cosineDirection)
};

// run_intersect: one ray against one triangle and one box.
struct IntersectInput {
    vec4 origin;    // .w: tMin
    vec4 direction; // .w: tMax
    vec4 v0;
    vec4 v1;
    vec4 v2;
    vec4 boxMin;
    vec4 boxMax;
};
struct IntersectOutput {
    vec4 triangle;         // t, u, v of intersectTriangle
    uvec4 hits;            // .x: triangle hit, .y: box hit (entry < VKPT_FAR)
    vec4 box;              // .x: intersectBox entry distance
    vec4 inverseDirection; // safeInverseDirection(direction)
    vec4 faceNormal;       // triangleFaceNormal
};

// read_layouts / write_layouts: each struct of shared/host_device.h and each wavefront record of
// lib/wavefront.h flattened to 32-bit words in declaration order, one region per struct type,
// LAYOUT_COUNT records per region.
#define LAYOUT_COUNT 5u
#define LAYOUT_BUFFER_COUNT 16u // one per struct type, and the words (binding 8)
#define LAYOUT_WORDS_BVH_NODE 20u
#define LAYOUT_WORDS_TRIANGLE 12u
#define LAYOUT_WORDS_TRIANGLE_NORMALS 12u
#define LAYOUT_WORDS_MATERIAL 116u
#define LAYOUT_WORDS_TEXTURE_INFO 4u
#define LAYOUT_WORDS_EMITTER 16u
#define LAYOUT_WORDS_ENVIRONMENT 8u
#define LAYOUT_WORDS_CAMERA 20u
#define LAYOUT_WORDS_FRAME_PARAMS 44u
#define LAYOUT_WORDS_PATH_STATE 16u
#define LAYOUT_WORDS_SHADOW_RAY 12u
#define LAYOUT_WORDS_PIXEL_STATE 20u
#define LAYOUT_WORDS_LIGHT_TREE_NODE 16u
#define LAYOUT_WORDS_SPECULAR_LOBES 48u
#define LAYOUT_WORDS_MATERIAL_LOBES 24u
#define LAYOUT_OFFSET_BVH_NODES 0u
#define LAYOUT_OFFSET_TRIANGLES (LAYOUT_OFFSET_BVH_NODES + LAYOUT_COUNT * LAYOUT_WORDS_BVH_NODE)
#define LAYOUT_OFFSET_TRIANGLE_NORMALS                                                             \
    (LAYOUT_OFFSET_TRIANGLES + LAYOUT_COUNT * LAYOUT_WORDS_TRIANGLE)
#define LAYOUT_OFFSET_MATERIALS                                                                    \
    (LAYOUT_OFFSET_TRIANGLE_NORMALS + LAYOUT_COUNT * LAYOUT_WORDS_TRIANGLE_NORMALS)
#define LAYOUT_OFFSET_TEXTURES (LAYOUT_OFFSET_MATERIALS + LAYOUT_COUNT * LAYOUT_WORDS_MATERIAL)
#define LAYOUT_OFFSET_EMITTERS (LAYOUT_OFFSET_TEXTURES + LAYOUT_COUNT * LAYOUT_WORDS_TEXTURE_INFO)
#define LAYOUT_OFFSET_ENVIRONMENTS (LAYOUT_OFFSET_EMITTERS + LAYOUT_COUNT * LAYOUT_WORDS_EMITTER)
#define LAYOUT_OFFSET_CAMERAS (LAYOUT_OFFSET_ENVIRONMENTS + LAYOUT_COUNT * LAYOUT_WORDS_ENVIRONMENT)
#define LAYOUT_OFFSET_FRAME_PARAMS (LAYOUT_OFFSET_CAMERAS + LAYOUT_COUNT * LAYOUT_WORDS_CAMERA)
#define LAYOUT_OFFSET_PATH_STATES                                                                  \
    (LAYOUT_OFFSET_FRAME_PARAMS + LAYOUT_COUNT * LAYOUT_WORDS_FRAME_PARAMS)
#define LAYOUT_OFFSET_SHADOW_RAYS                                                                  \
    (LAYOUT_OFFSET_PATH_STATES + LAYOUT_COUNT * LAYOUT_WORDS_PATH_STATE)
#define LAYOUT_OFFSET_PIXEL_STATES                                                                 \
    (LAYOUT_OFFSET_SHADOW_RAYS + LAYOUT_COUNT * LAYOUT_WORDS_SHADOW_RAY)
#define LAYOUT_OFFSET_LIGHT_TREE_NODES                                                             \
    (LAYOUT_OFFSET_PIXEL_STATES + LAYOUT_COUNT * LAYOUT_WORDS_PIXEL_STATE)
#define LAYOUT_OFFSET_SPECULAR_LOBES                                                               \
    (LAYOUT_OFFSET_LIGHT_TREE_NODES + LAYOUT_COUNT * LAYOUT_WORDS_LIGHT_TREE_NODE)
#define LAYOUT_OFFSET_MATERIAL_LOBES                                                               \
    (LAYOUT_OFFSET_SPECULAR_LOBES + LAYOUT_COUNT * LAYOUT_WORDS_SPECULAR_LOBES)
#define LAYOUT_TOTAL_WORDS                                                                         \
    (LAYOUT_OFFSET_MATERIAL_LOBES + LAYOUT_COUNT * LAYOUT_WORDS_MATERIAL_LOBES)

// count_loop_iterations: per invocation, how many iterations each loop really ran.
struct LoopCounts {
    uint first;  // a loop of firstLoop iterations
    uint second; // then a loop of secondLoop iterations
    uint nested; // then outer × inner iterations of a nested loop, counted in the inner body
    uint unused;
};
#define ALL_INVOCATIONS 0xffffffffu
struct LoopParams {
    uint firstLoop;
    uint secondLoop;
    uint outerLoop;
    uint innerLoop;
    uint firstLoopInvocation; // the only invocation that runs the first loop, or ALL_INVOCATIONS
    uint unused0;
    uint unused1;
    uint unused2;
};

#ifdef __cplusplus
static_assert(sizeof(RngInput) == 32 && sizeof(RngOutput) == 48);
static_assert(sizeof(SamplingInput) == 64 && sizeof(SamplingOutput) == 96);
static_assert(sizeof(IntersectInput) == 112 && sizeof(IntersectOutput) == 80);
static_assert(sizeof(WideBvhNode) == 4 * LAYOUT_WORDS_BVH_NODE &&
              sizeof(Triangle) == 4 * LAYOUT_WORDS_TRIANGLE &&
              sizeof(TriangleNormals) == 4 * LAYOUT_WORDS_TRIANGLE_NORMALS &&
              sizeof(Material) == 4 * LAYOUT_WORDS_MATERIAL &&
              sizeof(TextureInfo) == 4 * LAYOUT_WORDS_TEXTURE_INFO &&
              sizeof(Emitter) == 4 * LAYOUT_WORDS_EMITTER &&
              sizeof(EnvironmentParams) == 4 * LAYOUT_WORDS_ENVIRONMENT &&
              sizeof(Camera) == 4 * LAYOUT_WORDS_CAMERA);
static_assert(sizeof(FrameParams) == 4 * LAYOUT_WORDS_FRAME_PARAMS &&
              sizeof(PathState) == 4 * LAYOUT_WORDS_PATH_STATE &&
              sizeof(ShadowRay) == 4 * LAYOUT_WORDS_SHADOW_RAY &&
              sizeof(PixelState) == 4 * LAYOUT_WORDS_PIXEL_STATE &&
              sizeof(LightTreeNode) == 4 * LAYOUT_WORDS_LIGHT_TREE_NODE &&
              sizeof(SpecularLobeParams) == 4 * LAYOUT_WORDS_SPECULAR_LOBES &&
              sizeof(MaterialLobes) == 4 * LAYOUT_WORDS_MATERIAL_LOBES);
static_assert(sizeof(LoopCounts) == 16 && sizeof(LoopParams) == 32);
} // namespace vkpt::gpu::test
#endif

#endif // VKPT_KERNEL_TEST_IO_H
