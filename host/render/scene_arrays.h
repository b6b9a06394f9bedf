// scene_arrays.h — the list of the scene's device arrays (one entry per row of
// shared/scene_array_table.h: name, binding, how kernels read it, where it lives in
// PreparedScene) and their upload, split into chunks where an array is larger than one binding
// may see (lib/scene_arrays.glsl reads the chunks).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <volk.h>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/kernel.h"
#include "prepare/prepared_scene.h"

namespace vkpt {

class GpuContext;

// How kernels read an array: 16-byte texels through uniform texel views, or a storage buffer.
enum class SceneArrayAccess : std::uint32_t { Texels, Storage };

// One entry of the list in scene_arrays.cpp: a row of shared/scene_array_table.h.
struct SceneArrayDesc {
    const char* name;      // the buffers' debug name and the GLSL name: "bvhNodes"
    std::uint32_t binding; // its BINDING_*
    SceneArrayAccess access;
    // Whether the kernels read it through lib/scene_arrays.glsl (a descriptor array of
    // SCENE_ARRAY_MAX_CHUNKS); the others are read as one buffer by shared code and must fit.
    bool splittable;
    std::uint64_t elementBytes; // the unit a chunk holds a power of two of: a texel or a value
    std::span<const std::byte> (*bytes)(const PreparedScene& scene);
    void (*release)(PreparedScene& scene); // frees the host copy
};

std::span<const SceneArrayDesc> sceneArrayList();

// The scene array at `binding`; nullptr when that binding is not a scene array's.
const SceneArrayDesc* findSceneArray(std::uint32_t binding);

// Whether `binding` is a splittable scene array (its kernels declare SCENE_ARRAY_MAX_CHUNKS
// descriptors there).
bool isSplittableSceneBinding(std::uint32_t binding);

// How a kernel sees the scene array at `binding` (a SCENE entry of lib/kernel_bindings.h):
// uniform texel buffers or storage buffers, SCENE_ARRAY_MAX_CHUNKS of them where the array may
// be split. InternalError when `binding` is not a scene array's.
KernelBinding sceneKernelBinding(std::uint32_t binding);

// The most bytes one chunk of an array read through `access` may hold on this device: the
// binding's range (maxTexelBufferElements texels, maxStorageBufferRange) and
// maxMemoryAllocationSize. For splittable arrays uploadSceneArray lowers it further to the
// environment variable VKPT_TEST_BINDING_BYTES when that is set: a hook for tests, which makes
// small scenes take the split path.
VkDeviceSize sceneChunkByteLimit(const DeviceLimits& limits, SceneArrayAccess access);

// How an array of `elementCount` elements of `elementBytes` is cut: chunks of 2^chunkLog2
// elements (the last one shorter). One chunk when it fits whole.
struct ChunkPlan {
    std::uint32_t chunkLog2 = 31;
    std::uint32_t chunkCount = 1;
};
ChunkPlan planChunks(std::uint64_t elementCount, std::uint64_t elementBytes,
                     VkDeviceSize chunkByteLimit);

// One array on the device: its chunks (none when the scene lacks it) and their size.
struct SceneArray {
    const SceneArrayDesc* desc = nullptr;
    std::vector<Buffer> chunks;
    std::uint32_t chunkLog2 = 31; // elements per chunk, log2

    std::uint64_t allocationBytes() const;
};

// Uploads one array, chunk by chunk, through staging buffers of at most 64 MiB. Throws
// VulkanError naming the array, its size and the limit when it needs more chunks than the
// kernels have descriptors for (or a chunk at all, if it is not splittable).
SceneArray uploadSceneArray(GpuContext& context, const SceneArrayDesc& desc,
                            std::span<const std::byte> bytes);

} // namespace vkpt
