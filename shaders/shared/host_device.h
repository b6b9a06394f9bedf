// host_device.h — every buffer layout the host and the kernels share, declared once.
// Compiled as C++ (GLM types in namespace vkpt::gpu) and as GLSL (std430 storage buffers).
// Layout rule: each vec3 is followed by a 4-byte scalar and every struct is a multiple of
// 16 bytes, so std430 and GLM agree without hand-written padding twins.
#ifndef VKPT_HOST_DEVICE_H
#define VKPT_HOST_DEVICE_H

#ifdef __cplusplus
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
namespace vkpt::gpu {
// The GLSL built-ins that shared code uses, so one spelling compiles on both sides.
using glm::abs;
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::floatBitsToInt;
using glm::floatBitsToUint;
using glm::intBitsToFloat;
using glm::length;
using glm::max;
using glm::min;
using glm::normalize;
using glm::uintBitsToFloat;
using std::cos;
using std::sin;
using std::sqrt;
using glm::ivec2;
using glm::ivec3;
using glm::uvec2;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using uint = std::uint32_t;
// Shared functions are header-only on the C++ side.
#define VKPT_FN inline
// C++ builds do not contract a·b − c·d into an FMA unless asked (-ffp-contract=off where it
// matters); GLSL needs the precise qualifier for the same guarantee.
#define VKPT_PRECISE
#else
#define VKPT_FN
#define VKPT_PRECISE precise
#endif

#define WORKGROUP_SIZE 64

// The largest finite float: the "no hit yet" distance on both sides (GLSL has no INFINITY).
#define VKPT_FAR 3.402823466e38f

// ---------------------------------------------------------------------------------------------
// BVH: nodes in depth-first order with skip ("miss") links, so traversal needs no stack:
// on a box hit an interior node continues at index + 1 (its first child); on a box miss,
// or after a leaf's triangles, traversal continues at missIndex.
#define BVH_END 0xffffffffu
// A leaf packs its triangle range into one word: count in the low bits, first triangle above.
#define BVH_LEAF_COUNT_BITS 4u
#define BVH_LEAF_COUNT_MASK 15u
#define BVH_MAX_LEAF_TRIANGLES 15u
#define BVH_MAX_TRIANGLES (1u << (32u - BVH_LEAF_COUNT_BITS))

struct BvhNode {
    vec3 boundsMin;
    uint missIndex;     // next node once this subtree is done or missed; BVH_END at the end
    vec3 boundsMax;
    uint leafTriangles; // 0 for an interior node; else (firstTriangle << 4) | triangleCount
};

VKPT_FN uint packLeafTriangles(uint firstTriangle, uint triangleCount) {
    return (firstTriangle << BVH_LEAF_COUNT_BITS) | triangleCount;
}
VKPT_FN uint leafFirstTriangle(uint leafTriangles) { return leafTriangles >> BVH_LEAF_COUNT_BITS; }
VKPT_FN uint leafTriangleCount(uint leafTriangles) { return leafTriangles & BVH_LEAF_COUNT_MASK; }

// ---------------------------------------------------------------------------------------------
// Geometry, in BVH leaf order. Vertices rather than edges, so that a watertight test can
// use the same data as Möller–Trumbore (kept in intersect.h for comparison).
#define NO_EMITTER 0xffffffffu

struct Triangle {
    vec3 v0;
    uint materialIndex;
    vec3 v1;
    uint emitterIndex; // index into emitters, NO_EMITTER when the material does not emit
    vec3 v2;
    uint sourceIndex; // index in the loaded scene's triangle list, before BVH ordering
};

// Shading normals, one record per triangle in the same order (w unused, kept for std430).
struct TriangleNormals {
    vec4 n0;
    vec4 n1;
    vec4 n2;
};

// ---------------------------------------------------------------------------------------------
// Materials: the glTF metallic-roughness parameters as loaded. Rendering is Lambertian with
// albedo baseColor.rgb for now; metallic, roughness and alpha are kept for the BSDF to come.
#define MATERIAL_DOUBLE_SIDED 1u

#define ALPHA_MODE_OPAQUE 0u
#define ALPHA_MODE_MASK 1u
#define ALPHA_MODE_BLEND 2u

struct Material {
    vec4 baseColor; // linear RGBA factor
    vec3 emission;  // emitted radiance: emissiveFactor × KHR_materials_emissive_strength
    uint flags;     // MATERIAL_* bits
    float metallic;
    float roughness;
    float alphaCutoff;
    uint alphaMode; // ALPHA_MODE_*
};

// ---------------------------------------------------------------------------------------------
// Area lights: every emitting triangle, chosen with probability proportional to its power
// (emitted luminance × area × emitting sides). cdf is inclusive, so the last entry is 1.
struct Emitter {
    uint triangleIndex;
    float area;
    float selectProbability;
    float cdf;
};

// ---------------------------------------------------------------------------------------------
// Pinhole camera. Pixel (0, 0) is the top-left; a sample at (x + u, y + v) maps to the
// direction forward + sx·right + sy·up with sx, sy on the image plane at distance 1.
struct Camera {
    vec3 position;
    float tanHalfFovY;
    vec3 right;
    float aspect; // width / height
    vec3 up;
    uint width;
    vec3 forward;
    uint height;
};

#ifdef __cplusplus
static_assert(sizeof(BvhNode) == 32 && offsetof(BvhNode, missIndex) == 12 &&
              offsetof(BvhNode, boundsMax) == 16 && offsetof(BvhNode, leafTriangles) == 28);
static_assert(sizeof(Triangle) == 48 && offsetof(Triangle, materialIndex) == 12 &&
              offsetof(Triangle, v1) == 16 && offsetof(Triangle, emitterIndex) == 28 &&
              offsetof(Triangle, v2) == 32 && offsetof(Triangle, sourceIndex) == 44);
static_assert(sizeof(TriangleNormals) == 48 && offsetof(TriangleNormals, n2) == 32);
static_assert(sizeof(Material) == 48 && offsetof(Material, emission) == 16 &&
              offsetof(Material, flags) == 28 && offsetof(Material, metallic) == 32 &&
              offsetof(Material, alphaMode) == 44);
static_assert(sizeof(Emitter) == 16 && offsetof(Emitter, cdf) == 12);
static_assert(sizeof(Camera) == 64 && offsetof(Camera, right) == 16 &&
              offsetof(Camera, up) == 32 && offsetof(Camera, width) == 44 &&
              offsetof(Camera, forward) == 48 && offsetof(Camera, height) == 60);
} // namespace vkpt::gpu
#endif

#endif // VKPT_HOST_DEVICE_H
