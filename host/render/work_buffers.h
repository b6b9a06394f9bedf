// work_buffers.h — the wavefront's working set: path states, the double-buffered ray queue,
// hits, light-sample records, per-pixel estimates, the active pixel lists, counters and the
// indirect dispatch arguments; and how many path slots the device can afford.
#pragma once

#include <cstdint>
#include <optional>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "render/wavefront_kernels.h"

namespace vkpt {

struct SlotRequest {
    std::uint32_t lightSamples = 1;   // light-sample records per slot
    std::uint64_t pathsWanted = 0;    // pixels × spp: more slots than this would sit idle
    std::uint32_t requestedSlots = 0; // 0: choose from the device
    bool aovs = false;                // each slot also holds its sample's features
};

// Slots in flight: 2^20 on a GPU, 2^16 on a CPU device (lavapipe runs them on a few cores,
// where more buys nothing but memory), then bounded so that every per-slot buffer fits
// maxStorageBufferRange and maxMemoryAllocationSize and all of them a quarter of the
// device-local heap; never more than the render needs. A multiple of WORKGROUP_SIZE.
std::uint32_t chooseSlotCount(const GpuContext& context, const SlotRequest& request);

// What a render adds to the working set beyond the paths, queues and pixel estimates.
struct WorkExtras {
    bool instances = false; // the scene has two levels: hits say which instance they found
    bool aovs = false;      // the render records AOVs: features per slot and per pixel
};

struct WorkBuffers {
    WorkBuffers(GpuContext& context, std::uint32_t slotCount, std::uint32_t lightSamples,
                std::uint32_t pixelCount, WorkExtras extras = {});

    std::uint32_t slotCount;
    Buffer frameParams;                   // FrameParams
    Buffer pathStates;                    // PathState per slot
    Buffer rays;                          // RayRecord, two queues of slotCount
    Buffer hits;                          // HitRecord per ray of the current queue
    std::optional<Buffer> hitInstances;   // uint per hit: its instance (two-level scenes only)
    Buffer shadowRays;                    // ShadowRay, lightSamples per ray of the current queue
    Buffer pixelStates;                   // PixelState per pixel
    std::optional<Buffer> sampleFeatures; // SampleFeatures per slot (renders with AOVs only)
    std::optional<Buffer> pixelFeatures;  // PixelFeatures per pixel (renders with AOVs only)
    Buffer activePixels;                  // uint, two lists of pixelCount
    Buffer queueCounters;                 // COUNTER_WORDS uints
    Buffer dispatchArgs;                  // DISPATCH_WORDS uints: VkDispatchIndirectCommands
    Buffer countersReadback; // host-visible copy of queueCounters, written at the end of a pass

    // Points every work binding of `table` (storage and texel bindings alike) at its buffer.
    void bind(BufferTable& table) const;
};

} // namespace vkpt
