// wavefront.h — the records and bindings of the wavefront path tracer (vkpt), declared once for
// host/render (C++) and shaders/kernels (GLSL), under the rules of shared/host_device.h: every
// vec3 is followed by a 4-byte scalar and every struct is a multiple of 16 bytes.
// It lives beside the kernels rather than in shared/ because only vkpt uses it: the CPU
// reference has no queues.
#ifndef VKPT_WAVEFRONT_H
#define VKPT_WAVEFRONT_H

#include "shared/host_device.h"
#include "shared/sample_features.h"
#include "shared/scene_array_table.h"

// ---------------------------------------------------------------------------------------------
// Bindings of descriptor set 0. Each kernel declares only the buffers it uses, and its pipeline
// layout lists exactly those. A scene array a scene does not have (no textures, one emitter, no
// environment map) is not uploaded: its bindings get a small placeholder buffer that the
// specialised kernels never read (host/render/device_scene.h). frameParams is a uniform buffer;
// the read-only records (scene arrays, and the work arrays where a kernel only reads them) are
// uniform texel buffers fetched as 16-byte texels (lib/records.glsl); the rest are storage
// buffers (lib/kernel_bindings.h lists each kernel's; docs/gpu.md).
//
// X(binding, number): the bindings of the render's own buffers. The scene arrays' are in their
// table (shared/scene_array_table.h); both lists become the BINDING_* constants below.
#define VKPT_WORK_BINDINGS(X)                                                                      \
    X(BINDING_FRAME_PARAMS, 0) /* uniform buffer */                                                \
    X(BINDING_PATH_STATES, 6)                                                                      \
    X(BINDING_RAYS, 7)                                                                             \
    X(BINDING_HITS, 8)                                                                             \
    X(BINDING_SHADOW_RAYS, 9)                                                                      \
    X(BINDING_PIXEL_STATES, 10)                                                                    \
    X(BINDING_ACTIVE_PIXELS, 11)                                                                   \
    X(BINDING_QUEUE_COUNTERS, 12)                                                                  \
    X(BINDING_DISPATCH_ARGS, 13)                                                                   \
    /* The work arrays as uniform texel buffers, for the kernels that read them. */                \
    X(BINDING_RAY_TEXELS, 20)                                                                      \
    X(BINDING_HIT_TEXELS, 21)                                                                      \
    X(BINDING_SHADOW_RAY_TEXELS, 22)                                                               \
    X(BINDING_PATH_STATE_TEXELS, 23)                                                               \
    X(BINDING_HIT_INSTANCES, 27) /* uint per hit: the instance hit (two-level scenes) */           \
    /* The AOVs (shared/sample_features.h), only in renders whose output or state records them */  \
    X(BINDING_SAMPLE_FEATURES, 28) /* SampleFeatures per slot: its camera sample's first hit */    \
    X(BINDING_PIXEL_FEATURES, 29)  /* PixelFeatures per pixel */

// The BINDING_* constants: plain ints in GLSL, whose layout qualifiers and specialisation ids
// take constant expressions; in namespace vkpt in C++, where host/render uses them.
#ifdef __cplusplus
#define VKPT_BINDING_CONSTANT(binding, number) inline constexpr std::uint32_t binding = number;
#else
#define VKPT_BINDING_CONSTANT(binding, number) const int binding = number;
#endif
#define VKPT_SCENE_BINDING_CONSTANT(name, Type, binding, number, access, split, member, reader,    \
                                    accessor)                                                      \
    VKPT_BINDING_CONSTANT(binding, number)
#ifdef __cplusplus
namespace vkpt {
#endif
VKPT_WORK_BINDINGS(VKPT_BINDING_CONSTANT)
VKPT_SCENE_ARRAYS(VKPT_SCENE_BINDING_CONSTANT)
#ifdef __cplusplus
// One more than the highest binding: every number below it is taken, each by one entry of
// either list (checked below).
#define VKPT_COUNT_WORK_BINDING(binding, number) +1
#define VKPT_COUNT_SCENE_BINDING(name, Type, binding, number, access, split, member, reader,       \
                                 accessor)                                                         \
    +1
inline constexpr std::uint32_t BINDING_COUNT =
    0 VKPT_WORK_BINDINGS(VKPT_COUNT_WORK_BINDING) VKPT_SCENE_ARRAYS(VKPT_COUNT_SCENE_BINDING);

// Whether the two lists number the bindings 0 … BINDING_COUNT − 1, each once: a number given
// twice would make two buffers one binding.
constexpr bool bindingsNumberedOnce() {
#define VKPT_WORK_BINDING_NUMBER(binding, number) number,
#define VKPT_SCENE_BINDING_NUMBER(name, Type, binding, number, access, split, member, reader,      \
                                  accessor)                                                        \
    number,
    const std::uint32_t numbers[] = {VKPT_WORK_BINDINGS(VKPT_WORK_BINDING_NUMBER)
                                         VKPT_SCENE_ARRAYS(VKPT_SCENE_BINDING_NUMBER)};
    bool taken[BINDING_COUNT] = {};
    for (std::uint32_t number : numbers) {
        if (number >= BINDING_COUNT || taken[number]) return false;
        taken[number] = true;
    }
    return true;
}
static_assert(bindingsNumberedOnce(), "a binding number is used twice or leaves a gap");
static_assert(FEATURE_COUNT <= 32, "the scene features' specialisation ids reach the chunks'");
} // namespace vkpt
#endif

// A scene array larger than one binding may hold (maxStorageBufferRange, maxTexelBufferElements,
// maxMemoryAllocationSize) is split into up to SCENE_ARRAY_MAX_CHUNKS buffers of 2^k elements
// each, bound as the elements of a descriptor array (lib/scene_arrays.glsl, docs/gpu.md). Two
// specialisation constants per scene binding say into how many chunks, and k; the defaults (one
// chunk) leave the kernels reading element 0 only, as if there were no arrays.
#define SCENE_ARRAY_MAX_CHUNKS 4
#define SPEC_SCENE_ARRAY_CHUNKS(binding) (32 + 2 * (binding))
#define SPEC_SCENE_ARRAY_CHUNK_LOG2(binding) (33 + 2 * (binding))

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// ---------------------------------------------------------------------------------------------
// What every kernel needs to know about the render, uploaded once (buffer frameParams).
#define INTEGRATOR_PATH 0u
#define INTEGRATOR_DIRECT_LIGHT 1u      // CS184 direct lighting, light sampling
#define INTEGRATOR_DIRECT_HEMISPHERE 2u // CS184 direct lighting, uniform hemisphere directions
#define INTEGRATOR_NORMALS 3u

struct FrameParams {
    Camera camera;
    uint seed;
    uint maxDepth;
    uint rrStartDepth;
    uint lightSamples; // N per shading point
    uint integrator;   // INTEGRATOR_*
    uint pathFilter;   // PATH_FILTER_*
    uint emitterCount;
    uint adaptive; // 1: adaptive sampling on
    uint adaptiveBatch;
    uint adaptiveMinSamples;
    float adaptiveTolerance;
    float adaptiveDarkFloor; // ADAPTIVE_DARK_FLOOR · 2^-EV
    uint slotCount;          // path slots; each half of the rays buffer holds this many
    uint pixelCount;         // each half of the activePixels buffer holds this many
    uint samplerSetup;       // shared/sampler.h: makeSamplerSetup of the render
    float sampleClamp;       // --clamp: largest component a sample may keep; SAMPLE_CLAMP_OFF: none
    EnvironmentParams environment; // emitterIndex NO_EMITTER: rays that leave see black
};

// Push constants: what changes from dispatch to dispatch.
struct PassParams {
    uint sampleBase;             // sample index of sample j = 0 of this pass
    uint samplesPerPass;         // k: samples per active pixel in this pass
    uint chunkStart;             // first entry of the active list in this chunk
    uint chunkPixels;            // active pixels in this chunk; slots used = chunkPixels · k
    uint bounce;                 // scattering events before the vertices this dispatch shades
    uint activeParity;           // which half of activePixels is read (the other is appended to)
    uint useActiveList;          // 0: the first pass, active pixel a is pixel a
    float adaptiveVarianceScale; // shared/adaptive.h: the driver's calibration of σ²/n
    uint recordAovs;             // 1: the render records AOVs (lib/aovs.glsl)
};

// ---------------------------------------------------------------------------------------------
// One path in flight, slot = (active pixel of the chunk) · k + (sample j of the pass).
struct PathState {
    vec3 throughput; // of the next vertex
    uint pixel;
    vec3 radiance; // gathered so far, in the reference's order of additions
    uint sampleIndex;
    vec3 lightScale;       // factor of this bounce's light-sample sum: throughput at the vertex
    float previousBsdfPdf; // solid-angle pdf of the BSDF sample that made the current ray, or
                           // PDF_NOT_LIGHT_SAMPLED (shared/path_rules.h)
    // KHR_materials_volume: the medium the current ray travels in (shared/volume.h).
    vec3 mediumCoefficient; // Beer–Lambert σ per unit length; 0 outside every volume
    // KHR_materials_dispersion (shared/dispersion.h): the path's wavelength in nm once it has
    // met dispersive glass, VKPT_NO_WAVELENGTH before. Written and read only in scenes with
    // FEATURE_DISPERSION.
    float wavelength;
};

// A ray queue entry. The rays buffer holds two queues of slotCount entries: bounce b reads half
// b & 1 and appends the next bounce's rays to the other half.
struct RayRecord {
    vec3 origin;
    uint slot;
    vec3 direction;
    uint unused0;
};

#define NO_HIT 0xffffffffu

// trace_closest's answer for ray i of the queue, at index i.
struct HitRecord {
    float t;
    float u;       // barycentric weight of v1
    float v;       // barycentric weight of v2
    uint triangle; // BVH-ordered index, NO_HIT on a miss
};

// Light sample k of ray i sits at index i·N + k, so no atomics order them and add_light_samples
// sums them in the reference's order. A segment is a shadow ray from origin to origin +
// direction (t in (0, 1)); a probe (the hemisphere estimator) is a closest-hit ray whose
// contribution is multiplied by the emission it finds.
#define SHADOW_NONE 0u
#define SHADOW_SEGMENT 1u
#define SHADOW_PROBE 2u
#define SHADOW_KIND_MASK 3u
#define SHADOW_VISIBLE 4u // set by trace_shadow: the contribution counts

struct ShadowRay {
    vec3 origin;
    uint flags; // SHADOW_* kind | SHADOW_VISIBLE
    vec3 direction;
    float tMax;
    vec3 contribution; // segment: added when unoccluded; probe: f, times Le·factor on a hit
    float factor;      // probe: cos θ / pdf
};

// Samples enter a pixel's radiance sum multiplied by 2^-32, which is exact for every sample
// above 2^-94 (about 5e-29): then even 2^32 samples of the largest float sum to a finite float.
// The host multiplies the sum back, in double.
#define ACCUMULATION_SCALE 2.3283064365386963e-10f

// One pixel's running estimate: Kahan-compensated radiance sum (× ACCUMULATION_SCALE) and
// Welford's luminance statistics, as the reference's PixelAccumulator keeps them (in double
// there), and the running means of the two halves of its samples (even and odd sample indices,
// shared/sampler.h sampleHalf): a mean rather than a scaled sum, since a half needs no more than
// float's relative precision (its use is a difference of the order of the noise).
struct PixelState {
    vec3 radianceSum;
    uint count;        // finite samples accumulated
    vec3 compensation; // Kahan's running error of radianceSum
    uint samplesTaken; // samples traced, non-finite ones included
    float luminanceMean;
    float luminanceM2;
    uint converged; // 1 once the adaptive test stopped the pixel
    uint unused0;
    vec3 evenMean;  // mean radiance of the finite samples of even index
    uint evenCount; // their count
    vec3 oddMean;   // of odd index
    uint oddCount;
};

// ---------------------------------------------------------------------------------------------
// queueCounters: 32-bit words. Ray counts are per queue half; the statistics are 64-bit
// counts kept as (low, high) pairs so that long passes cannot wrap them.
#define COUNTER_RAYS 0u        // + half: rays in that half of the queue
#define COUNTER_ACTIVE_NEXT 2u // pixels appended to the next active list
#define COUNTER_CAMERA_RAYS 4u // (low, high)
#define COUNTER_EXTENSION_RAYS 6u
#define COUNTER_SHADOW_RAYS 8u
#define COUNTER_NON_FINITE 10u     // samples discarded for a NaN or infinite value
#define COUNTER_TRUNCATED 12u      // traversals the driver's loop limit cut short
#define COUNTER_NODES_VISITED 14u  // (low, high): BVH boxes tested
#define COUNTER_TRIANGLE_TESTS 16u // (low, high)
#define COUNTER_WORDS 20u

// dispatchArgs: VkDispatchIndirectCommand triples written by prepare_dispatches.
#define DISPATCH_RAYS 0u   // one invocation per ray of the current queue
#define DISPATCH_SHADOW 3u // one invocation per light-sample record
#define DISPATCH_WORDS 8u

#ifdef __cplusplus
static_assert(sizeof(FrameParams) == 176 && offsetof(FrameParams, seed) == 80 &&
              offsetof(FrameParams, adaptiveDarkFloor) == 124 &&
              offsetof(FrameParams, samplerSetup) == 136 &&
              offsetof(FrameParams, sampleClamp) == 140 &&
              offsetof(FrameParams, environment) == 144);
static_assert(sizeof(PassParams) == 36);
static_assert(sizeof(PathState) == 64 && offsetof(PathState, radiance) == 16 &&
              offsetof(PathState, lightScale) == 32 && offsetof(PathState, previousBsdfPdf) == 44 &&
              offsetof(PathState, mediumCoefficient) == 48);
static_assert(sizeof(RayRecord) == 32 && offsetof(RayRecord, direction) == 16);
static_assert(sizeof(HitRecord) == 16);
static_assert(sizeof(ShadowRay) == 48 && offsetof(ShadowRay, tMax) == 28 &&
              offsetof(ShadowRay, factor) == 44);
static_assert(sizeof(PixelState) == 80 && offsetof(PixelState, samplesTaken) == 28 &&
              offsetof(PixelState, converged) == 40 && offsetof(PixelState, evenMean) == 48 &&
              offsetof(PixelState, oddCount) == 76);
} // namespace vkpt::gpu
#endif

#endif // VKPT_WAVEFRONT_H
