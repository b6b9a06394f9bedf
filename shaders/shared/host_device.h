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
using glm::atan; // atan(y, x) is GLSL's two-argument arctangent
using glm::bitCount;
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::findLSB;
using glm::floatBitsToInt;
using glm::floatBitsToUint;
using glm::floor;
using glm::fract;
using glm::greaterThan;
using glm::intBitsToFloat;
using glm::isinf;
using glm::isnan;
using glm::ivec2;
using glm::ivec3;
using glm::length;
using glm::lessThan;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::smoothstep;
using glm::uintBitsToFloat;
using glm::uvec2;
using glm::uvec3;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using std::cos;
using std::sin;
using std::sqrt;
using uint = std::uint32_t;
// Shared functions are header-only on the C++ side.
#define VKPT_FN inline
// A parameter the function reads and writes: a reference in C++, GLSL's inout.
#define VKPT_INOUT(Type) Type&
// C++ builds do not contract a·b − c·d into an FMA unless asked (-ffp-contract=off where it
// matters); GLSL needs the precise qualifier for the same guarantee.
#define VKPT_PRECISE
// The CPU side walks and shades two-level scenes whatever it is given.
#define VKPT_INSTANCES 1
#else
// Kernels are built twice where instances change them (trace_closest, trace_shadow, shade_hits):
// with -DVKPT_INSTANCES=1 for two-level scenes, and without, so that a scene of one level
// carries none of that code (lavapipe translates a whole module before it specialises it).
#ifndef VKPT_INSTANCES
#define VKPT_INSTANCES 0
#endif
#define VKPT_FN
#define VKPT_INOUT(Type) inout Type
#define VKPT_PRECISE precise
#endif

#define WORKGROUP_SIZE 64

// The largest finite float: the "no hit yet" distance on both sides (GLSL has no INFINITY).
#define VKPT_FAR 3.402823466e38f

// ---------------------------------------------------------------------------------------------
// BVH limits. A wide node's leaf child holds at most 15 primitives (4 bits of leafCounts), and a
// scene at most 2^28 primitives: the walk fetches primitive i as texels 3i..3i + 2 and
// texelFetch takes an int.
#define BVH_END 0xffffffffu // no node: the root's parent
#define BVH_MAX_LEAF_TRIANGLES 15u
#define BVH_MAX_TRIANGLES (1u << 28u)

// The device's BVH: 8-wide nodes with quantised child boxes, after Ylitie, Karras and Laine,
// "Efficient Incoherent Ray Traversal on GPUs Through Compressed Wide BVHs" (HPG 2017), in 80
// bytes (five 16-byte texels, fetched as bvhNodes texels). Child i's box is
// origin + 2^e·q for the byte q of each bound, rounded outwards when built so that it always
// holds the child. Slot s holds the child nearest for rays whose direction signs are the bits
// of s (x in bit 0, y, z), so a ray of octant o visits slots in the order s XOR o; the walk
// and its bit stack are in shared/wide_bvh.h, the layout's reasons in docs/bvh.md.
// Internal children are nodes childBase, childBase + 1, … in slot order; the primitives of
// leaf children follow one another in slot order from primitiveBase.
#define WIDE_BVH_WIDTH 8u
#define WIDE_BVH_TEXELS 5u     // 16-byte texels per node
#define WIDE_BVH_MAX_DEPTH 32u // levels below the root; the walk's bit stack holds 32 masks

struct WideBvhNode {
    uint childBase;         // node index of the first internal child
    uint parent;            // node index of the parent; BVH_END for the root
    uint slotsAndExponents; // bits 0–7: the slots holding internal children; bits 8–31: the
                            // exponents ex, ey, ez of the grid spacing 2^e, biased like a float's
    uint primitiveBase;     // index of the first primitive of the leaf children
    vec3 origin;            // the grid's origin: the node's box minimum
    uint leafCounts;        // 4 bits per slot: a leaf child's primitive count, 0 otherwise
    // Quantised bounds, one byte per slot (slot s in byte s % 4 of word s / 4 of each pair):
    // [0] lo.x lo.y, [1] lo.z hi.x, [2] hi.y hi.z.
    uvec4 quantised[3];
};

// ---------------------------------------------------------------------------------------------
// Geometry, in BVH leaf order. Vertices rather than edges, so that a watertight test can
// use the same data as Möller–Trumbore (kept in intersect.h for comparison).
// A record is a triangle or, with PRIMITIVE_SPHERE set in sourceIndex, an analytic sphere:
// centre v0, radius v1.x (v2 unused). Both kinds share the BVH's leaves, so one walk meets
// both; scenes without spheres compile the sphere test out (FEATURE_SPHERES).
#define NO_EMITTER 0xffffffffu
#define NO_PRIMITIVE 0xffffffffu
#define PRIMITIVE_SPHERE 0x80000000u
// Set in sourceIndex at load time when the primitive's material is alphaMode MASK, so that a
// BVH walk knows which crossings need the alpha test without reading the material.
#define PRIMITIVE_ALPHA_MASKED 0x40000000u
#define PRIMITIVE_SOURCE_MASK 0x3fffffffu

struct Triangle {
    vec3 v0;
    uint materialIndex;
    vec3 v1;
    uint emitterIndex; // index into emitters, NO_EMITTER when the material does not emit
    vec3 v2;
    uint sourceIndex; // index in the loaded scene's triangle (or sphere) list | PRIMITIVE_*
};

VKPT_FN bool isSpherePrimitive(Triangle primitive) {
    return (primitive.sourceIndex & PRIMITIVE_SPHERE) != 0u;
}

VKPT_FN bool isAlphaMaskedPrimitive(Triangle primitive) {
    return (primitive.sourceIndex & PRIMITIVE_ALPHA_MASKED) != 0u;
}

// ---------------------------------------------------------------------------------------------
// Instances (two-level scenes, FEATURE_INSTANCES): a mesh kept once in its own space, placed by
// an affine transform. The top-level BVH (nodes from 0) has instances for leaf primitives, in
// the order of this array; each mesh's BVH follows in bvhNodes and its primitives in triangles.
// A walk meets an instance in a top-level leaf and walks the mesh's BVH with the ray in the
// mesh's space (o' = worldToObject·(o, 1), d' = worldToObject·(d, 0): not normalised, so that t
// is the same in both spaces); shading takes the hit back to world space with objectToWorld
// (normals with worldToObject's transpose, the inverse transpose). Texels 0–3 are what a walk
// reads; 3–6 what shading reads.
#define NO_INSTANCE 0xffffffffu
#define INSTANCE_MIRRORED 1u // objectToWorld has a negative determinant: the front face turns over
// Instance::material of a placement whose triangles keep their own materials (the scene's own
// geometry, a mesh of several materials).
#define INSTANCE_OWN_MATERIALS 0xffffffffu

struct Instance {
    vec4 worldToObject0; // rows of the 3×4 inverse transform
    vec4 worldToObject1;
    vec4 worldToObject2;
    uint root;           // node index of the mesh's BVH root in bvhNodes
    uint flags;          // INSTANCE_*
    uint mesh;           // index of the mesh (statistics and tests)
    uint material;       // every triangle's material (shared geometry), or INSTANCE_OWN_MATERIALS
    vec4 objectToWorld0; // rows of the 3×4 transform
    vec4 objectToWorld1;
    vec4 objectToWorld2;
};

// Shading normals, one record per triangle in the same order (w unused, kept for std430).
struct TriangleNormals {
    vec4 n0;
    vec4 n1;
    vec4 n2;
};

// Tangents for normal mapping, one record per primitive in the same order: the unit tangent of
// each corner in xyz and the bitangent sign in w (glTF's TANGENT, bitangent = w·cross(n, t)).
// Present only when a used material has a normal texture (FEATURE_NORMAL_MAPS); a primitive
// whose material has none, or a sphere, holds zeros (w = 0: no tangent frame).
struct TriangleTangents {
    vec4 t0;
    vec4 t1;
    vec4 t2;
};

// Texture coordinates (TEXCOORD_0) live in their own buffer, three vec2 per primitive in BVH
// order (triangleUvs[3i + k]), present only when the scene has textures.

// ---------------------------------------------------------------------------------------------
// Materials: glTF metallic-roughness (docs/scene-model.md). A material without the flag
// MATERIAL_METALLIC_ROUGHNESS is purely Lambertian: metallic 0 and specular 0
// (KHR_materials_specular) with no metallic-roughness texture, the "diffuse" kind, which
// scenes made only of it compile without the microfacet code.
#define MATERIAL_DOUBLE_SIDED 1u
#define MATERIAL_METALLIC_ROUGHNESS 2u
// The material has a record of its own in specularLobes (MATERIAL_SPECULAR_LOBES: specular
// textures, anisotropy or iridescence) or in materialLobes (MATERIAL_LOBES: diffuse
// transmission or dispersion). The general kernels (every feature on) may run on a scene's own
// arrays, where those are empty: the flag, not the feature, decides whether a record is read.
#define MATERIAL_SPECULAR_LOBES 4u
#define MATERIAL_LOBES 8u

#define ALPHA_MODE_OPAQUE 0u
#define ALPHA_MODE_MASK 1u
#define ALPHA_MODE_BLEND 2u

#define NO_TEXTURE 0xffffffffu

// A material's use of a texture: which one, and the KHR_texture_transform of TEXCOORD_0 as
// the first two rows of a 3×3 matrix: uv' = (dot(row0, (u, v, 1)), dot(row1, (u, v, 1))).
struct TextureSlot {
    vec3 transformRow0;
    uint texture; // index into textures, NO_TEXTURE when the factor alone applies
    vec3 transformRow1;
    uint unused0;
};

struct Material {
    vec4 baseColor; // linear RGBA factor
    vec3 emission;  // emitted radiance: emissiveFactor × KHR_materials_emissive_strength
    uint flags;     // MATERIAL_* bits
    float metallic;
    float roughness; // perceptual; the GGX α is roughness²
    float alphaCutoff;
    uint alphaMode;               // ALPHA_MODE_*
    vec3 specularColor;           // KHR_materials_specular specularColorFactor (1 when absent)
    float specular;               // KHR_materials_specular specularFactor (1 when absent)
    TextureSlot baseColorTexture; // sRGB; alpha in .a
    TextureSlot metallicRoughnessTexture; // linear; roughness in .g, metallic in .b
    TextureSlot emissiveTexture;          // sRGB
    // Normal mapping (glTF normalTexture): the tangent-space normal is
    // normalize((texel·2 − 1) · (normalScale, normalScale, 1)) in the frame of
    // triangleTangents (shared/normal_mapping.h). No texture: the interpolated normal.
    TextureSlot normalTexture; // linear; +Y of the texture along the bitangent (glTF)
    float normalScale;         // glTF normalTexture.scale
    uint normalUnused0;
    uint normalUnused1;
    uint normalUnused2;
    // KHR_materials_transmission, KHR_materials_ior and KHR_materials_volume
    // (shared/bsdf_dielectric.h, docs/scene-model.md), 64 bytes from offset 208.
    float transmission; // transmissionFactor: the share of the non-metal part that is glass
    float ior;          // index of refraction (1.5 when absent)
    float iorF0;        // ((ior − 1)/(ior + 1))², computed in double: 0.04f exactly at 1.5
    float thickness;    // thicknessFactor: 0 thin-walled, > 0 the mesh bounds a volume
    vec3 attenuationCoefficient;     // σ = −ln(attenuationColor)/attenuationDistance, per unit
    uint unusedVolume;               // keeps the vec3 16-byte aligned
    TextureSlot transmissionTexture; // linear; transmission in .r
    // KHR_materials_clearcoat and KHR_materials_sheen, the layers of bsdf.h over the base:
    // 192 bytes from offset 272 (texels 17–28). Factors multiply their textures' channels;
    // clearcoat 0 and sheenColor 0 mean no layer (the extensions' defaults).
    vec3 sheenColor;                       // sheenColorFactor, linear RGB
    float sheenRoughness;                  // sheenRoughnessFactor, perceptual
    float clearcoat;                       // clearcoatFactor
    float clearcoatRoughness;              // clearcoatRoughnessFactor, perceptual
    float clearcoatNormalScale;            // clearcoatNormalTexture.scale
    uint layersUnused;                     // keeps the texture slots on 16-byte texels
    TextureSlot clearcoatTexture;          // linear; factor in .r
    TextureSlot clearcoatRoughnessTexture; // linear; roughness in .g
    TextureSlot clearcoatNormalTexture;    // linear; the layer's own normal map (no texture:
                                           // the base's shading normal, as the extension says)
    TextureSlot sheenColorTexture;         // sRGB; colour in .rgb
    TextureSlot sheenRoughnessTexture;     // linear; roughness in .a
};

// The GGX lobe's newer extensions, one record per material (the array specularLobes, indexed as
// materials), kept out of Material so that the record every kernel decodes stays the size it
// had before them (464 bytes; docs/benchmarks.md, "Pipeline creation and the Material record").
// The array is empty unless features.specularLobes(); only code behind
// FEATURE_SPECULAR_TEXTURES, FEATURE_ANISOTROPY or FEATURE_IRIDESCENCE reads it.
struct SpecularLobeParams {
    // KHR_materials_specular's textures: they multiply specular and specularColor. Texels 0–3.
    TextureSlot specularTexture;      // linear; strength in .a
    TextureSlot specularColorTexture; // sRGB; colour in .rgb
    // KHR_materials_anisotropy: the strength, and the rotation of the direction from the tangent
    // as its cosine and sine (computed on the host). Texels 4–6.
    float anisotropyStrength;      // anisotropyStrength; 0: isotropic
    float anisotropyRotationCos;   // cos(anisotropyRotation)
    float anisotropyRotationSin;   // sin(anisotropyRotation)
    uint anisotropyUnused;         // keeps the texture slot on a 16-byte texel
    TextureSlot anisotropyTexture; // linear; direction in .rg (as 2x − 1), strength in .b
    // KHR_materials_iridescence. Texels 7–11.
    float iridescence;                       // iridescenceFactor; 0: no film
    float iridescenceIor;                    // iridescenceIor
    float iridescenceThicknessMinimum;       // nm, at thickness texture G = 0
    float iridescenceThicknessMaximum;       // nm, at G = 1, and without the texture
    TextureSlot iridescenceTexture;          // linear; factor in .r
    TextureSlot iridescenceThicknessTexture; // linear; thickness in .g
};

// The lobes that only some scenes have, in an array of their own (materialLobes, one record per
// material, empty unless FEATURE_DIFFUSE_TRANSMISSION or FEATURE_DISPERSION), so that the
// Material record every scene reads does not grow for them: only the kernels specialised for
// those features read it.
struct MaterialLobes {
    // KHR_materials_diffuse_transmission (shared/bsdf.h): the share of the diffuse base that
    // passes to the other side, and its colour. 0: the diffuse base only reflects.
    vec3 diffuseTransmissionColor; // diffuseTransmissionColorFactor, linear RGB
    float diffuseTransmission;     // diffuseTransmissionFactor
    // KHR_materials_dispersion (shared/dispersion.h): 20/V, V the Abbe number. 0: none.
    float dispersion;
    uint unused0;
    uint unused1;
    uint unused2;
    TextureSlot diffuseTransmissionTexture;      // linear; factor in .a
    TextureSlot diffuseTransmissionColorTexture; // sRGB; colour in .rgb
};

// A path's wavelength before it meets dispersive glass (PathState, shared/dispersion.h).
#define VKPT_NO_WAVELENGTH 0.0f

// ---------------------------------------------------------------------------------------------
// Textures: RGBA8 texels packed one per uint (R in the low byte, as unpackUnorm4x8 reads
// them) in one storage buffer, each texture a row-major block starting at texelOffset, row 0
// at v = 0. No descriptor indexing is needed, so lavapipe can run it; the limit is the
// storage buffer's size (docs/scene-model.md).
#define TEXTURE_WRAP_REPEAT 0u
#define TEXTURE_WRAP_CLAMP 1u
#define TEXTURE_WRAP_MIRROR 2u
#define TEXTURE_FILTER_NEAREST 16u // sampler bit; bilinear otherwise

struct TextureInfo {
    uint texelOffset;
    uint width;
    uint height;
    uint samplerBits; // wrapS | wrapT << 2 | TEXTURE_FILTER_NEAREST ("sampler" is a GLSL type)
};

// ---------------------------------------------------------------------------------------------
// Emitters: everything next-event estimation samples. Emitting triangles and spheres,
// KHR_lights_punctual lights and the environment, chosen with probability proportional to
// their power; the inclusive selection CDF is a separate buffer (emitterCdf), absent when
// the scene has one emitter.
#define EMITTER_TRIANGLE 0u
#define EMITTER_SPHERE 1u
#define EMITTER_POINT 2u
#define EMITTER_SPOT 3u
#define EMITTER_DIRECTIONAL 4u
#define EMITTER_ENVIRONMENT 5u

struct Emitter {
    vec3 position;  // point and spot lights
    uint kind;      // EMITTER_*
    vec3 direction; // spot and directional lights: unit, the way the light travels
    uint primitive; // triangle and sphere emitters: BVH-ordered index into triangles
    vec3 intensity; // point and spot: candela × colour; directional: lux × colour
    float range;    // point and spot: KHR_lights_punctual range, 0 when unlimited
    float area;     // triangle and sphere emitters
    float selectProbability;
    float cosInnerCone; // spot lights
    float cosOuterCone;
};

// The light BVH (shared/light_tree.h, host/prepare/light_tree.h): a binary tree over the
// emitters that a shading point walks from the root, choosing each child by an importance that
// weighs its power, distance and orientation (Conty Estevez and Kulla 2018; pbrt-v4 section
// 12.6.3), in place of the power CDF. Node i < emitter count is emitter i's leaf (power 0 and
// no parent for an emitter that is never chosen), the root is node `emitter count`, the other
// inner nodes follow it. Parent links let the pmf of a given emitter be recomputed for MIS.
#define LIGHT_NODE_LEAF 1u      // an emitter; child0 is its index
#define LIGHT_NODE_TWO_SIDED 2u // some emitter below emits on both sides of its axis
#define LIGHT_NODE_BY_POWER                                                                        \
    4u // the children are chosen by power alone (infinite lights, and
       // the root's split between them and the rest)
#define NO_LIGHT_NODE 0xffffffffu

struct LightTreeNode {
    vec3 boundsMin;
    float power; // Σ of the emitters' powers below (luminance), their selection weight
    vec3 boundsMax;
    float cosThetaO; // the cone of emission normals around axis: cos θo
    vec3 axis;       // unit
    float cosThetaE; // the spread of emission about each normal: cos θe
    uint child0;     // inner: the first child; leaf: the emitter
    uint child1;     // inner: the second child, NO_LIGHT_NODE when there is one
    uint parent;     // NO_LIGHT_NODE at the root and for emitters outside the tree
    uint flags;      // LIGHT_NODE_*
};

// The environment seen by rays that leave the scene: a constant radiance, or an
// equirectangular map (environmentTexels, width × height RGB, row 0 at the top, +Y up)
// times `radiance`, importance sampled by the luminance × sin θ CDF in environmentCdf:
// height rows of width conditional entries, then the height marginal entries.
struct EnvironmentParams {
    vec3 radiance; // constant colour, or the map's scale
    uint width;    // 0: no map
    uint height;
    uint emitterIndex; // NO_EMITTER: no environment
    uint unused0;
    uint unused1;
};

// ---------------------------------------------------------------------------------------------
// Features a kernel is specialised for: the constant_id of each specialisation constant
// (bool). A scene's pipelines set exactly the features it uses; --general sets all of them.
#define FEATURE_METALLIC_ROUGHNESS 0
#define FEATURE_TEXTURES 1
#define FEATURE_ALPHA_MASK 2
#define FEATURE_SPHERES 3
#define FEATURE_PUNCTUAL_LIGHTS 4
#define FEATURE_ENVIRONMENT 5
#define FEATURE_ENVIRONMENT_MAP 6
#define FEATURE_EMITTER_CDF 7
#define FEATURE_DOUBLE_SIDED 8
#define FEATURE_NORMAL_MAPS 9
#define FEATURE_TRANSMISSION 10 // transmission, a volume, or an ior other than 1.5
#define FEATURE_CLEARCOAT 11
#define FEATURE_SHEEN 12
#define FEATURE_INSTANCES 13  // a two-level BVH: meshes placed by instances
#define FEATURE_LIGHT_TREE 14 // emitters chosen by the light BVH (lightTree), not the power CDF
#define FEATURE_SPECULAR_TEXTURES 15    // KHR_materials_specular textures on a GGX material
#define FEATURE_ANISOTROPY 16           // KHR_materials_anisotropy on a GGX material
#define FEATURE_IRIDESCENCE 17          // KHR_materials_iridescence on a GGX material
#define FEATURE_DIFFUSE_TRANSMISSION 18 // KHR_materials_diffuse_transmission (materialLobes)
#define FEATURE_DISPERSION 19           // KHR_materials_dispersion: paths carry a wavelength
#define FEATURE_COUNT 20

// ---------------------------------------------------------------------------------------------
// The camera (shared/camera.h). Pixel (0, 0) is the top-left; a sample at (x + u, y + v) has
// image-plane coordinates sx (right, scaled by aspect) and sy (up) in [-1, 1]. A perspective
// camera (pinhole) shoots from position along forward + tanHalfFovY·(sx·right + sy·up); an
// orthographic one along forward from position + orthoHalfHeight·(sx·right + sy·up).
#define CAMERA_PERSPECTIVE 0u
#define CAMERA_ORTHOGRAPHIC 1u

struct Camera {
    vec3 position;
    float tanHalfFovY; // perspective: tan(yfov / 2)
    vec3 right;
    float aspect; // width / height
    vec3 up;
    uint width;
    vec3 forward;
    uint height;
    uint projection;       // CAMERA_*
    float orthoHalfHeight; // orthographic: glTF ymag, the view's half-height in world units
    uint unused0;
    uint unused1;
};

#ifdef __cplusplus
static_assert(sizeof(WideBvhNode) == 80 && offsetof(WideBvhNode, origin) == 16 &&
              offsetof(WideBvhNode, leafCounts) == 28 && offsetof(WideBvhNode, quantised) == 32);
static_assert(sizeof(Triangle) == 48 && offsetof(Triangle, materialIndex) == 12 &&
              offsetof(Triangle, v1) == 16 && offsetof(Triangle, emitterIndex) == 28 &&
              offsetof(Triangle, v2) == 32 && offsetof(Triangle, sourceIndex) == 44);
static_assert(sizeof(TriangleNormals) == 48 && offsetof(TriangleNormals, n2) == 32);
static_assert(sizeof(Instance) == 112 && offsetof(Instance, root) == 48 &&
              offsetof(Instance, flags) == 52 && offsetof(Instance, objectToWorld0) == 64);
static_assert(sizeof(TextureSlot) == 32 && offsetof(TextureSlot, texture) == 12 &&
              offsetof(TextureSlot, transformRow1) == 16);
static_assert(offsetof(Material, emission) == 16 && offsetof(Material, flags) == 28 &&
              offsetof(Material, metallic) == 32 && offsetof(Material, alphaMode) == 44 &&
              offsetof(Material, specularColor) == 48 && offsetof(Material, specular) == 60 &&
              offsetof(Material, baseColorTexture) == 64 &&
              offsetof(Material, metallicRoughnessTexture) == 96 &&
              offsetof(Material, emissiveTexture) == 128);
static_assert(sizeof(TriangleTangents) == 48 && offsetof(TriangleTangents, t2) == 32);
static_assert(offsetof(Material, normalTexture) == 160 && offsetof(Material, normalScale) == 192);
static_assert(offsetof(Material, transmission) == 208 && offsetof(Material, thickness) == 220 &&
              offsetof(Material, attenuationCoefficient) == 224 &&
              offsetof(Material, transmissionTexture) == 240);
static_assert(sizeof(Material) == 464);
static_assert(sizeof(SpecularLobeParams) == 192 &&
              offsetof(SpecularLobeParams, specularColorTexture) == 32 &&
              offsetof(SpecularLobeParams, anisotropyStrength) == 64 &&
              offsetof(SpecularLobeParams, anisotropyTexture) == 80 &&
              offsetof(SpecularLobeParams, iridescence) == 112 &&
              offsetof(SpecularLobeParams, iridescenceTexture) == 128 &&
              offsetof(SpecularLobeParams, iridescenceThicknessTexture) == 160);
static_assert(offsetof(Material, sheenColor) == 272 && offsetof(Material, sheenRoughness) == 284 &&
              offsetof(Material, clearcoat) == 288 &&
              offsetof(Material, clearcoatRoughness) == 292 &&
              offsetof(Material, clearcoatNormalScale) == 296 &&
              offsetof(Material, clearcoatTexture) == 304 &&
              offsetof(Material, clearcoatRoughnessTexture) == 336 &&
              offsetof(Material, clearcoatNormalTexture) == 368 &&
              offsetof(Material, sheenColorTexture) == 400 &&
              offsetof(Material, sheenRoughnessTexture) == 432);
static_assert(sizeof(MaterialLobes) == 96 && offsetof(MaterialLobes, dispersion) == 16 &&
              offsetof(MaterialLobes, diffuseTransmissionTexture) == 32 &&
              offsetof(MaterialLobes, diffuseTransmissionColorTexture) == 64);
static_assert(sizeof(TextureInfo) == 16);
static_assert(sizeof(Emitter) == 64 && offsetof(Emitter, direction) == 16 &&
              offsetof(Emitter, primitive) == 28 && offsetof(Emitter, intensity) == 32 &&
              offsetof(Emitter, range) == 44 && offsetof(Emitter, area) == 48 &&
              offsetof(Emitter, cosOuterCone) == 60);
static_assert(sizeof(LightTreeNode) == 64 && offsetof(LightTreeNode, axis) == 32 &&
              offsetof(LightTreeNode, child0) == 48 && offsetof(LightTreeNode, flags) == 60);
static_assert(sizeof(EnvironmentParams) == 32 && offsetof(EnvironmentParams, width) == 12 &&
              offsetof(EnvironmentParams, emitterIndex) == 20);
static_assert(offsetof(Camera, right) == 16 && offsetof(Camera, up) == 32 &&
              offsetof(Camera, width) == 44 && offsetof(Camera, forward) == 48 &&
              offsetof(Camera, height) == 60);
static_assert(sizeof(Camera) == 80 && offsetof(Camera, projection) == 64 &&
              offsetof(Camera, orthoHalfHeight) == 68);
} // namespace vkpt::gpu
#endif

#endif // VKPT_HOST_DEVICE_H
