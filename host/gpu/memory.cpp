// memory.cpp — memory type choice and device-memory accounting.
#include "gpu/memory.h"

#include "gpu/vk_check.h"

#include <algorithm>
#include <cstdio>
#include <optional>

namespace vkpt {

namespace {

std::optional<std::uint32_t> findType(const VkPhysicalDeviceMemoryProperties& properties,
                                      std::uint32_t allowedTypes, VkMemoryPropertyFlags wanted) {
    for (std::uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
        const bool allowed = (allowedTypes & (1u << i)) != 0;
        const VkMemoryPropertyFlags flags = properties.memoryTypes[i].propertyFlags;
        if (allowed && (flags & wanted) == wanted) return i;
    }
    return std::nullopt;
}

} // namespace

std::string memoryLocationName(MemoryLocation location) {
    switch (location) {
    case MemoryLocation::DeviceLocal:
        return "device-local";
    case MemoryLocation::Upload:
        return "upload";
    case MemoryLocation::Readback:
        return "readback";
    }
    return "unknown";
}

std::uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& properties,
                               std::uint32_t allowedTypes, MemoryLocation location) {
    constexpr VkMemoryPropertyFlags kHost =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    std::optional<std::uint32_t> type;
    switch (location) {
    case MemoryLocation::DeviceLocal:
        type = findType(properties, allowedTypes, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        if (!type) type = findType(properties, allowedTypes, 0);
        break;
    case MemoryLocation::Upload:
        type = findType(properties, allowedTypes, kHost);
        break;
    case MemoryLocation::Readback:
        type = findType(properties, allowedTypes, kHost | VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
        if (!type) type = findType(properties, allowedTypes, kHost);
        break;
    }
    if (!type) {
        char mask[16];
        std::snprintf(mask, sizeof mask, "0x%x", allowedTypes);
        throw VulkanError("no " + memoryLocationName(location) +
                              " memory type among the allowed types " + mask,
                          VK_ERROR_OUT_OF_DEVICE_MEMORY);
    }
    return *type;
}

void MemoryAccounting::recordAllocation(std::uint64_t bytes) {
    stats_.bytesInUse += bytes;
    stats_.peakBytes = std::max(stats_.peakBytes, stats_.bytesInUse);
    ++stats_.allocationsInUse;
    ++stats_.allocationCount;
}

void MemoryAccounting::recordFree(std::uint64_t bytes) {
    stats_.bytesInUse -= bytes;
    --stats_.allocationsInUse;
}

std::string formatBytes(std::uint64_t bytes) {
    char mebibytes[32];
    std::snprintf(mebibytes, sizeof mebibytes, "%.1f MiB",
                  static_cast<double>(bytes) / (1024.0 * 1024.0));
    return std::string(mebibytes) + " (" + std::to_string(bytes) + " bytes)";
}

} // namespace vkpt
