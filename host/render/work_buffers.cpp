// work_buffers.cpp — sizing and creating the wavefront's buffers.
#include "render/work_buffers.h"

#include <algorithm>

#include "lib/wavefront.h"

namespace vkpt {

namespace {

constexpr std::uint32_t kGpuSlots = 1u << 20;
constexpr std::uint32_t kCpuSlots = 1u << 16;

// Usage of every working buffer: kernels read and write them, the records also as texels
// (lib/records.glsl); transfers fill, upload and download them (tests inspect them too).
constexpr VkBufferUsageFlags kWorkUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
    VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

std::uint64_t recordsPerSlot(std::uint32_t lightSamples) {
    return std::max<std::uint64_t>(lightSamples, 1);
}

// The largest per-slot array (light samples or the two ray queues) decides the per-buffer cap.
std::uint64_t largestBytesPerSlot(std::uint32_t lightSamples) {
    return std::max<std::uint64_t>({sizeof(gpu::PathState), 2 * sizeof(gpu::RayRecord),
                                    recordsPerSlot(lightSamples) * sizeof(gpu::ShadowRay)});
}

std::uint64_t totalBytesPerSlot(std::uint32_t lightSamples, bool aovs) {
    return sizeof(gpu::PathState) + 2 * sizeof(gpu::RayRecord) + sizeof(gpu::HitRecord) +
           sizeof(std::uint32_t) + recordsPerSlot(lightSamples) * sizeof(gpu::ShadowRay) +
           (aovs ? sizeof(gpu::SampleFeatures) : 0);
}

Buffer makeWorkBuffer(GpuContext& context, const char* name, std::uint64_t bytes,
                      VkBufferUsageFlags extraUsage = 0) {
    return Buffer(context, {name, bytes, kWorkUsage | extraUsage, MemoryLocation::DeviceLocal});
}

} // namespace

std::uint32_t chooseSlotCount(const GpuContext& context, const SlotRequest& request) {
    const DeviceLimits& limits = context.limits();
    const bool cpu = context.deviceInfo().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
    std::uint64_t slots =
        request.requestedSlots ? request.requestedSlots : (cpu ? kCpuSlots : kGpuSlots);
    std::uint64_t bufferCap =
        std::min(limits.maxStorageBufferRange, limits.maxMemoryAllocationSize);
    slots = std::min(slots, bufferCap / largestBytesPerSlot(request.lightSamples));
    if (limits.deviceLocalHeapSize > 0)
        slots = std::min(slots, limits.deviceLocalHeapSize / 4 /
                                    totalBytesPerSlot(request.lightSamples, request.aovs));
    if (request.pathsWanted > 0) slots = std::min(slots, request.pathsWanted + WORKGROUP_SIZE - 1);
    slots = std::max<std::uint64_t>(slots / WORKGROUP_SIZE, 1) * WORKGROUP_SIZE;
    return static_cast<std::uint32_t>(slots);
}

WorkBuffers::WorkBuffers(GpuContext& context, std::uint32_t slots, std::uint32_t lightSamples,
                         std::uint32_t pixelCount, WorkExtras extras)
    : slotCount(slots), frameParams(makeWorkBuffer(context, "frameParams", sizeof(gpu::FrameParams),
                                                   VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT)),
      pathStates(
          makeWorkBuffer(context, "pathStates", std::uint64_t(slots) * sizeof(gpu::PathState))),
      rays(makeWorkBuffer(context, "rays", 2 * std::uint64_t(slots) * sizeof(gpu::RayRecord))),
      hits(makeWorkBuffer(context, "hits", std::uint64_t(slots) * sizeof(gpu::HitRecord))),
      shadowRays(makeWorkBuffer(context, "shadowRays",
                                std::uint64_t(slots) * recordsPerSlot(lightSamples) *
                                    sizeof(gpu::ShadowRay))),
      pixelStates(makeWorkBuffer(context, "pixelStates",
                                 std::uint64_t(pixelCount) * sizeof(gpu::PixelState))),
      activePixels(makeWorkBuffer(context, "activePixels",
                                  2 * std::uint64_t(pixelCount) * sizeof(std::uint32_t))),
      queueCounters(
          makeWorkBuffer(context, "queueCounters", COUNTER_WORDS * sizeof(std::uint32_t))),
      dispatchArgs(makeWorkBuffer(context, "dispatchArgs", DISPATCH_WORDS * sizeof(std::uint32_t),
                                  VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT)),
      countersReadback(context, {"queueCounters.readback", COUNTER_WORDS * sizeof(std::uint32_t),
                                 VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryLocation::Readback}) {
    if (extras.instances)
        hitInstances.emplace(
            makeWorkBuffer(context, "hitInstances", std::uint64_t(slots) * sizeof(std::uint32_t)));
    if (extras.aovs) {
        sampleFeatures.emplace(makeWorkBuffer(context, "sampleFeatures",
                                              std::uint64_t(slots) * sizeof(gpu::SampleFeatures)));
        pixelFeatures.emplace(makeWorkBuffer(
            context, "pixelFeatures", std::uint64_t(pixelCount) * sizeof(gpu::PixelFeatures)));
    }
}

void WorkBuffers::bind(BufferTable& table) const {
    table.set(BINDING_FRAME_PARAMS, frameParams);
    table.set(BINDING_PATH_STATES, pathStates);
    table.set(BINDING_PATH_STATE_TEXELS, pathStates);
    table.set(BINDING_RAYS, rays);
    table.set(BINDING_RAY_TEXELS, rays);
    table.set(BINDING_HITS, hits);
    table.set(BINDING_HIT_TEXELS, hits);
    // A scene of one level binds hits there, which its kernels, specialised without
    // instances, never touch (every binding of a layout needs a buffer).
    table.set(BINDING_HIT_INSTANCES, hitInstances ? *hitInstances : hits);
    table.set(BINDING_SHADOW_RAYS, shadowRays);
    table.set(BINDING_SHADOW_RAY_TEXELS, shadowRays);
    table.set(BINDING_PIXEL_STATES, pixelStates);
    // Likewise a render without AOVs binds buffers of its own there that its kernels, specialised
    // without them (lib/aovs.glsl), never touch.
    table.set(BINDING_SAMPLE_FEATURES, sampleFeatures ? *sampleFeatures : pathStates);
    table.set(BINDING_PIXEL_FEATURES, pixelFeatures ? *pixelFeatures : pixelStates);
    table.set(BINDING_ACTIVE_PIXELS, activePixels);
    table.set(BINDING_QUEUE_COUNTERS, queueCounters);
    table.set(BINDING_DISPATCH_ARGS, dispatchArgs);
}

} // namespace vkpt
