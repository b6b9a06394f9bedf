// scene_array_table.h — every array of the prepared scene that the device reads, one row each,
// for the host (C++) and the kernels (GLSL). Adding an array is a row here, the code that fills
// it (host/prepare) and the code that reads it (the callers of its accessor, and a SCENE entry in
// the binding list of each kernel that reads it, lib/kernel_bindings.h); the rest follows from
// the row.
//
// X(name, Type, binding, number, access, split, member, reader, accessor):
//   name      the GLSL name and the VkBuffers' debug name ("bvhNodes", "bvhNodes[1]", ...)
//   Type      the element: a record of host_device.h, or uint, float, vec2, vec4
//   binding   its BINDING_* of descriptor set 0, which lib/wavefront.h defines as `number`
//   access    TEXELS: read as 16-byte texels through uniform texel views (records a multiple of
//             16 bytes; lib/records.glsl decodes element i with fetch<Type>(i)), faster than
//             storage reads on lavapipe (docs/gpu.md); STORAGE: a std430 storage buffer of Type
//   split     SPLIT: cut into up to SCENE_ARRAY_MAX_CHUNKS buffers when larger than one binding
//             may see (lib/scene_arrays.glsl reads element i as name##At(i)); WHOLE: one buffer
//   member    the PreparedScene member that holds it on the host, and SceneView's span of it
//   reader    VIEW: the shared code reads element i as `Type accessor(uint i ...)`, generated on
//             both sides; OWN: it has its own reader, `accessor`, written by hand (why: at its
//             row)
//
// What the rows make, and where (grep the macro's name for the expansion):
//   gpu::SceneArrayMembers<Array>  below: an `Array<Type> member` per row, the std::vectors of
//                                  PreparedScene (host/prepare/prepared_scene.h) and the spans of
//                                  gpu::SceneView (shared/scene_view.h)
//   VKPT_SCENE_VIEW_ACCESSOR       shared/scene_view.h: the C++ accessors over SceneView's spans
//   VKPT_VIEW_OF_SCENE_ARRAY       host/prepare/prepared_scene_view.cpp: makeSceneView's copies
//   VKPT_SCENE_BINDING_CONSTANT    lib/wavefront.h: BINDING_*, and BINDING_COUNT with the others
//   VKPT_SCENE_ARRAY_DESC          host/render/scene_arrays.cpp: the upload list, whose access
//                                  and split also give the descriptors of the kernels' SCENE
//                                  entries (host/render/wavefront_kernels.cpp)
//   VKPT_DECLARE_SCENE_ARRAY       lib/scene_arrays.glsl: every kernel's declarations of the
//                                  arrays, with name##At(i) for the split ones
//   VKPT_KERNEL_SCENE_ACCESSOR     lib/scene_view.glsl: the kernels' accessors
//
// The rows are in upload order (the order of the report's scene buffers). The environment's
// parameters (EnvironmentParams) are one struct, not an array: the kernels read them from
// frameParams, and PreparedScene and SceneView keep them as a member of their own.
#ifndef VKPT_SCENE_ARRAY_TABLE_H
#define VKPT_SCENE_ARRAY_TABLE_H

#include "host_device.h"

// clang-format off
#define VKPT_SCENE_ARRAYS(X)                                                                       \
    /* name              Type              binding                     number access  split     */ \
    /*   member          reader accessor                                                        */ \
    /* The walk's nodes, 5 texels each, read as texels by its own code (shared/wide_bvh.h) */      \
    X(bvhNodes,          WideBvhNode,      BINDING_BVH_NODES,           1, TEXELS,  SPLIT,         \
      nodes,             OWN,  bvhNodeTexel)                                                       \
    /* Triangles and spheres (PRIMITIVE_SPHERE), in BVH order, as are the next three */            \
    X(triangles,         Triangle,         BINDING_TRIANGLES,           2, TEXELS,  SPLIT,         \
      triangles,         VIEW, scenePrimitive)                                                     \
    X(triangleNormals,   TriangleNormals,  BINDING_TRIANGLE_NORMALS,    3, TEXELS,  SPLIT,         \
      normals,           VIEW, sceneNormals)                                                       \
    /* Empty unless features.tangents() (normal maps) */                                           \
    X(triangleTangents,  TriangleTangents, BINDING_TRIANGLE_TANGENTS,  24, TEXELS,  SPLIT,         \
      tangents,          VIEW, sceneTangents)                                                      \
    X(materials,         Material,         BINDING_MATERIALS,           4, TEXELS,  SPLIT,         \
      materials,         VIEW, sceneMaterial)                                                      \
    /* One per material; empty unless features.specularLobes() (specular textures, anisotropy, \
       iridescence), so that the Material record stays small (host_device.h) */                  \
    X(specularLobes,     SpecularLobeParams, BINDING_SPECULAR_LOBES,  31, TEXELS,  SPLIT,         \
      specularLobes,     VIEW, sceneSpecularLobes)                                                 \
    /* One per material; empty unless features.diffuseTransmission or features.dispersion */     \
    X(materialLobes,     MaterialLobes,    BINDING_MATERIAL_LOBES,     32, STORAGE, SPLIT,         \
      materialLobes,     VIEW, sceneMaterialLobes)                                                 \
    X(emitters,          Emitter,          BINDING_EMITTERS,            5, TEXELS,  SPLIT,         \
      emitters,          VIEW, sceneEmitter)                                                       \
    /* The light BVH; empty unless features.lightTree */                                           \
    X(lightTree,         LightTreeNode,    BINDING_LIGHT_TREE,         30, TEXELS,  SPLIT,         \
      lightTree,         VIEW, sceneLightTreeNode)                                                 \
    /* Two-level scenes (features.instances): the top level's leaves, in its order */              \
    X(instances,         Instance,         BINDING_INSTANCES,          26, TEXELS,  SPLIT,         \
      instances,         VIEW, sceneInstance)                                                      \
    /* 3 per primitive; empty unless features.textureCoordinates() */                              \
    X(triangleUvs,       vec2,             BINDING_TRIANGLE_UVS,       14, STORAGE, SPLIT,         \
      uvs,               VIEW, sceneUv)                                                            \
    X(textures,          TextureInfo,      BINDING_TEXTURES,           15, TEXELS,  SPLIT,         \
      textures,          VIEW, sceneTexture)                                                       \
    /* The inclusive selection CDF; empty unless features.emitterCdf() */                          \
    X(emitterCdf,        float,            BINDING_EMITTER_CDF,        17, STORAGE, SPLIT,         \
      emitterCdf,        VIEW, sceneEmitterCdf)                                                    \
    /* Every texture's RGBA8 texels, one uint each (TextureInfo says where) */                     \
    X(textureTexels,     uint,             BINDING_TEXTURE_TEXELS,     16, STORAGE, SPLIT,         \
      texels,            VIEW, sceneTextureTexel)                                                  \
    /* The environment map's RGB (w unused), row 0 at the top */                                   \
    X(environmentTexels, vec4,             BINDING_ENVIRONMENT_TEXELS, 18, STORAGE, SPLIT,         \
      environmentTexels, VIEW, sceneEnvironmentTexel)                                              \
    /* Its sampling CDF: height rows of width conditional entries, then the marginal */            \
    X(environmentCdf,    float,            BINDING_ENVIRONMENT_CDF,    19, STORAGE, SPLIT,         \
      environmentCdf,    VIEW, sceneEnvironmentCdf)                                                \
    /* The layered BSDF's tables (shared/albedo_lookup.h); empty unless                            \
       features.metallicRoughnessMaterials. Their own reader, because the reference reads the    \
       constants compiled into it, not a scene array; a fixed 48.5 KiB, so never split. */        \
    X(albedoTables,      float,            BINDING_ALBEDO_TABLES,      25, STORAGE, WHOLE,         \
      albedoTables,      OWN,  albedoEntry)
// clang-format on

#ifdef __cplusplus
namespace vkpt::gpu {

// One member per row, `Array<Type> member`: PreparedScene holds the arrays as std::vectors,
// SceneView as spans over them. A template, so that the rows' types resolve here, in
// vkpt::gpu, for both.
template <template <class> class Array> struct SceneArrayMembers {
#define VKPT_SCENE_ARRAY_MEMBER(name, Type, binding, number, access, split, member, reader,        \
                                accessor)                                                          \
    Array<Type> member;
    VKPT_SCENE_ARRAYS(VKPT_SCENE_ARRAY_MEMBER)
#undef VKPT_SCENE_ARRAY_MEMBER
};

} // namespace vkpt::gpu
#endif

#endif // VKPT_SCENE_ARRAY_TABLE_H
