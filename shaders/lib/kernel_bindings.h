// kernel_bindings.h — the descriptor bindings of each wavefront kernel, listed once: the kernel
// declares its storage buffers from its list (VKPT_DECLARE_BUFFERS) and host/render builds the
// kernel's pipeline layout and descriptor set from the same list, so the two cannot drift apart
// and a buffer added to a kernel needs no second edit on the host.
//
// A list is an X-macro of four entry kinds:
//   UNIFORM(binding)                       frameParams, the uniform block of lib/frame.glsl
//   SCENE(binding)                         a scene array it reads: its row of
//                                          shared/scene_array_table.h says how (texel views or
//                                          storage buffers, split or whole), for the kernel's
//                                          declaration (lib/scene_arrays.glsl) and the host's
//                                          descriptors (host/render/wavefront_kernels.cpp)
//   TEXELS(binding)                        a work array's uniform texel view of lib/records.glsl
//   BUFFER(binding, access, Type, name)    a work array's storage buffer `Type name[]`, access
//                                          READ, WRITE or READ_WRITE (readonly/writeonly in GLSL)
// lib/frame.glsl, lib/scene_arrays.glsl and lib/records.glsl declare the uniform block, the
// scene arrays and the texel views for every kernel (their functions refer to them), so in GLSL
// only BUFFER entries declare anything; those storage buffers must come before the lib/ code
// that reads them, in the order listed here.
#ifndef VKPT_KERNEL_BINDINGS_H
#define VKPT_KERNEL_BINDINGS_H

#include "lib/wavefront.h"

#define GENERATE_CAMERA_RAYS_BINDINGS(UNIFORM, SCENE, TEXELS, BUFFER)                              \
    UNIFORM(BINDING_FRAME_PARAMS)                                                                  \
    BUFFER(BINDING_ACTIVE_PIXELS, READ, uint, activePixels)                                        \
    BUFFER(BINDING_PATH_STATES, WRITE, PathState, pathStates)                                      \
    BUFFER(BINDING_RAYS, WRITE, RayRecord, rays)                                                   \
    BUFFER(BINDING_SAMPLE_FEATURES, WRITE, SampleFeatures, sampleFeatures)                         \
    BUFFER(BINDING_QUEUE_COUNTERS, READ_WRITE, uint, queueCounters)

#define PREPARE_DISPATCHES_BINDINGS(UNIFORM, SCENE, TEXELS, BUFFER)                                \
    UNIFORM(BINDING_FRAME_PARAMS)                                                                  \
    BUFFER(BINDING_QUEUE_COUNTERS, READ_WRITE, uint, queueCounters)                                \
    BUFFER(BINDING_DISPATCH_ARGS, WRITE, uint, dispatchArgs)

#define TRACE_CLOSEST_BINDINGS(UNIFORM, SCENE, TEXELS, BUFFER)                                     \
    UNIFORM(BINDING_FRAME_PARAMS)                                                                  \
    SCENE(BINDING_BVH_NODES)                                                                       \
    SCENE(BINDING_TRIANGLES)                                                                       \
    SCENE(BINDING_MATERIALS)                                                                       \
    SCENE(BINDING_TEXTURES)                                                                        \
    TEXELS(BINDING_RAY_TEXELS)                                                                     \
    SCENE(BINDING_INSTANCES)                                                                       \
    SCENE(BINDING_TRIANGLE_UVS)                                                                    \
    SCENE(BINDING_TEXTURE_TEXELS)                                                                  \
    BUFFER(BINDING_HITS, WRITE, HitRecord, hits)                                                   \
    BUFFER(BINDING_HIT_INSTANCES, WRITE, uint, hitInstances)                                       \
    BUFFER(BINDING_QUEUE_COUNTERS, READ_WRITE, uint, queueCounters)

#define SHADE_HITS_BINDINGS(UNIFORM, SCENE, TEXELS, BUFFER)                                        \
    UNIFORM(BINDING_FRAME_PARAMS)                                                                  \
    SCENE(BINDING_TRIANGLES)                                                                       \
    SCENE(BINDING_TRIANGLE_NORMALS)                                                                \
    SCENE(BINDING_TRIANGLE_TANGENTS)                                                               \
    SCENE(BINDING_MATERIALS)                                                                       \
    SCENE(BINDING_SPECULAR_LOBES)                                                                  \
    SCENE(BINDING_MATERIAL_LOBES)                                                                  \
    SCENE(BINDING_TEXTURES)                                                                        \
    SCENE(BINDING_EMITTERS)                                                                        \
    SCENE(BINDING_LIGHT_TREE)                                                                      \
    TEXELS(BINDING_PATH_STATE_TEXELS)                                                              \
    TEXELS(BINDING_RAY_TEXELS)                                                                     \
    TEXELS(BINDING_HIT_TEXELS)                                                                     \
    SCENE(BINDING_INSTANCES)                                                                       \
    BUFFER(BINDING_HIT_INSTANCES, READ, uint, hitInstances)                                        \
    SCENE(BINDING_TRIANGLE_UVS)                                                                    \
    SCENE(BINDING_TEXTURE_TEXELS)                                                                  \
    SCENE(BINDING_EMITTER_CDF)                                                                     \
    SCENE(BINDING_ENVIRONMENT_TEXELS)                                                              \
    SCENE(BINDING_ENVIRONMENT_CDF)                                                                 \
    SCENE(BINDING_ALBEDO_TABLES)                                                                   \
    BUFFER(BINDING_PATH_STATES, WRITE, PathState, pathStates)                                      \
    BUFFER(BINDING_RAYS, WRITE, RayRecord, rays)                                                   \
    BUFFER(BINDING_SHADOW_RAYS, WRITE, ShadowRay, shadowRays)                                      \
    BUFFER(BINDING_SAMPLE_FEATURES, WRITE, SampleFeatures, sampleFeatures)                         \
    BUFFER(BINDING_QUEUE_COUNTERS, READ_WRITE, uint, queueCounters)

#define TRACE_SHADOW_BINDINGS(UNIFORM, SCENE, TEXELS, BUFFER)                                      \
    UNIFORM(BINDING_FRAME_PARAMS)                                                                  \
    SCENE(BINDING_BVH_NODES)                                                                       \
    SCENE(BINDING_TRIANGLES)                                                                       \
    SCENE(BINDING_MATERIALS)                                                                       \
    SCENE(BINDING_TEXTURES)                                                                        \
    TEXELS(BINDING_SHADOW_RAY_TEXELS)                                                              \
    SCENE(BINDING_INSTANCES)                                                                       \
    SCENE(BINDING_TRIANGLE_UVS)                                                                    \
    SCENE(BINDING_TEXTURE_TEXELS)                                                                  \
    SCENE(BINDING_ENVIRONMENT_TEXELS)                                                              \
    SCENE(BINDING_ENVIRONMENT_CDF)                                                                 \
    BUFFER(BINDING_SHADOW_RAYS, WRITE, ShadowRay, shadowRays)                                      \
    BUFFER(BINDING_QUEUE_COUNTERS, READ_WRITE, uint, queueCounters)

#define ADD_LIGHT_SAMPLES_BINDINGS(UNIFORM, SCENE, TEXELS, BUFFER)                                 \
    UNIFORM(BINDING_FRAME_PARAMS)                                                                  \
    TEXELS(BINDING_PATH_STATE_TEXELS)                                                              \
    TEXELS(BINDING_RAY_TEXELS)                                                                     \
    TEXELS(BINDING_SHADOW_RAY_TEXELS)                                                              \
    BUFFER(BINDING_PATH_STATES, WRITE, PathState, pathStates)                                      \
    BUFFER(BINDING_QUEUE_COUNTERS, READ, uint, queueCounters)

#define ACCUMULATE_BINDINGS(UNIFORM, SCENE, TEXELS, BUFFER)                                        \
    UNIFORM(BINDING_FRAME_PARAMS)                                                                  \
    TEXELS(BINDING_PATH_STATE_TEXELS)                                                              \
    BUFFER(BINDING_PIXEL_STATES, READ_WRITE, PixelState, pixelStates)                              \
    BUFFER(BINDING_SAMPLE_FEATURES, READ, SampleFeatures, sampleFeatures)                          \
    BUFFER(BINDING_PIXEL_FEATURES, READ_WRITE, PixelFeatures, pixelFeatures)                       \
    BUFFER(BINDING_ACTIVE_PIXELS, WRITE, uint, activePixels)                                       \
    BUFFER(BINDING_QUEUE_COUNTERS, READ_WRITE, uint, queueCounters)

#ifndef __cplusplus
#include "lib/buffers.glsl"
#include "lib/scene_arrays.glsl"

// The GLSL side of a list: one block per BUFFER entry, nothing for the others.
#define VKPT_NO_DECLARATION(binding)
#define VKPT_STORAGE_READ(binding, Type, name) VKPT_READONLY_BUFFER(binding, Type, name)
#define VKPT_STORAGE_WRITE(binding, Type, name) VKPT_WRITEONLY_BUFFER(binding, Type, name)
#define VKPT_STORAGE_READ_WRITE(binding, Type, name) VKPT_BUFFER(binding, Type, name)
#define VKPT_DECLARE_STORAGE(binding, access, Type, name) VKPT_STORAGE_##access(binding, Type, name)
#define VKPT_DECLARE_BUFFERS(LIST)                                                                 \
    LIST(VKPT_NO_DECLARATION, VKPT_NO_DECLARATION, VKPT_NO_DECLARATION, VKPT_DECLARE_STORAGE)
#endif

#endif // VKPT_KERNEL_BINDINGS_H
