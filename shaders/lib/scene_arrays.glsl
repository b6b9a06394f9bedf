// scene_arrays.glsl — the scene's arrays as the kernels declare them, one declaration per row of
// shared/scene_array_table.h, for every includer: a kernel binds those it reads (its SCENE
// entries in lib/kernel_bindings.h), and one it never reads is not statically used. Reading an
// array that the kernel's list leaves out is therefore no compile error but a validation error
// when the pipeline is made (every GPU test runs with validation on).
//
// An array that may be split across several buffers (SPLIT) is a descriptor array of
// SCENE_ARRAY_MAX_CHUNKS bindings (uniform texel buffers or storage buffers) and one accessor,
// name##At(i), that every reader goes through. Element i lives in chunk
// i >> k at index i & (2^k − 1), where the host chooses k so that a chunk fits one binding
// (host/render/scene_arrays.cpp). Both figures are specialisation constants: with the default
// of one chunk the accessor folds to one fetch from element 0, so a scene that fits pays
// nothing; a split array costs a shift, a mask and a branch per fetch (docs/gpu.md).
// Texel arrays hold 16-byte texels; a record may straddle two chunks, which is why the split is
// per element (texel) and not per record.
#ifndef VKPT_SCENE_ARRAYS_GLSL
#define VKPT_SCENE_ARRAYS_GLSL

#include "lib/buffers.glsl"
#include "lib/wavefront.h"

// The chunk count and log2 of elements per chunk of the array at `bindingIndex`.
#define VKPT_SCENE_ARRAY_CONSTANTS(bindingIndex, name)                                             \
    layout(constant_id = SPEC_SCENE_ARRAY_CHUNKS(bindingIndex)) const uint name##Chunks = 1u;      \
    layout(constant_id = SPEC_SCENE_ARRAY_CHUNK_LOG2(bindingIndex)) const uint name##ChunkLog2 =   \
        31u;

// Element `i` of a split array whose chunk c is read by FETCH(name, c, local index). Chunks
// past the last are bound to the last one (host/render/scene_arrays.cpp), so every branch
// reads a valid descriptor. Four branches: SCENE_ARRAY_MAX_CHUNKS.
#define VKPT_SCENE_ARRAY_SELECT(name, FETCH, i)                                                    \
    if (name##Chunks == 1u) return FETCH(name, 0, i);                                              \
    uint chunk = (i) >> name##ChunkLog2;                                                           \
    uint local = (i) & ((1u << name##ChunkLog2) - 1u);                                             \
    if (chunk == 0u) return FETCH(name, 0, local);                                                 \
    if (chunk == 1u) return FETCH(name, 1, local);                                                 \
    if (chunk == 2u) return FETCH(name, 2, local);                                                 \
    return FETCH(name, 3, local);

#define VKPT_TEXEL_CHUNK(name, c, i) texelFetch(name[c], int(i))
#define VKPT_STORAGE_CHUNK(name, c, i) name##Chunk[c].values[i]

// A read-only array of 16-byte texels: uvec4 name##At(uint texel).
#define VKPT_SCENE_TEXELS(bindingIndex, name)                                                      \
    layout(set = 0, binding = bindingIndex) uniform usamplerBuffer name[SCENE_ARRAY_MAX_CHUNKS];  \
    VKPT_SCENE_ARRAY_CONSTANTS(bindingIndex, name)                                                 \
    uvec4 name##At(uint texel) {                                                                   \
        VKPT_SCENE_ARRAY_SELECT(name, VKPT_TEXEL_CHUNK, texel)                                          \
    }

// A read-only std430 array of Type: Type name##At(uint i).
#define VKPT_SCENE_STORAGE(bindingIndex, Type, name)                                               \
    layout(std430, set = 0, binding = bindingIndex) readonly buffer name##Buffer {                 \
        Type values[];                                                                             \
    }                                                                                              \
    name##Chunk[SCENE_ARRAY_MAX_CHUNKS];                                                           \
    VKPT_SCENE_ARRAY_CONSTANTS(bindingIndex, name)                                                 \
    Type name##At(uint i) {                                                                        \
        VKPT_SCENE_ARRAY_SELECT(name, VKPT_STORAGE_CHUNK, i)                                               \
    }

// One row of the table: its access and split choose the declaration. An array read whole is one
// plain buffer, read as name[i] by its own code (albedoTables, shared/albedo_lookup.h).
#define VKPT_DECLARE_TEXELS_SPLIT(bindingIndex, Type, name) VKPT_SCENE_TEXELS(bindingIndex, name)
#define VKPT_DECLARE_STORAGE_SPLIT(bindingIndex, Type, name)                                       \
    VKPT_SCENE_STORAGE(bindingIndex, Type, name)
#define VKPT_DECLARE_STORAGE_WHOLE(bindingIndex, Type, name)                                       \
    VKPT_READONLY_BUFFER(bindingIndex, Type, name)
#define VKPT_DECLARE_SCENE_ARRAY(name, Type, binding, number, access, split, member, reader,       \
                                 accessor)                                                         \
    VKPT_DECLARE_##access##_##split(binding, Type, name)

VKPT_SCENE_ARRAYS(VKPT_DECLARE_SCENE_ARRAY)

#endif // VKPT_SCENE_ARRAYS_GLSL
