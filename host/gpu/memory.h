// memory.h — where a buffer's memory lives, how a memory type is chosen for it, and how much
// device memory vkpt holds (reported by --stats).
#pragma once

#include <volk.h>

#include <cstdint>
#include <string>

namespace vkpt {

enum class MemoryLocation {
    DeviceLocal, // kernels' working data; filled by upload through a staging buffer
    Upload,      // host writes, device reads: staging for uploads
    Readback,    // device writes, host reads: staging for downloads
};

// "device-local", "upload", "readback".
std::string memoryLocationName(MemoryLocation location);

// The best memory type among `allowedTypes` (VkMemoryRequirements::memoryTypeBits):
// DeviceLocal prefers DEVICE_LOCAL and takes any allowed type if none is; Upload needs
// HOST_VISIBLE | HOST_COHERENT (so no flushes) and Readback prefers HOST_CACHED on top of that.
// Throws VulkanError when no allowed type qualifies.
std::uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& properties,
                               std::uint32_t allowedTypes, MemoryLocation location);

struct MemoryStats {
    std::uint64_t bytesInUse = 0; // device memory held now, all locations
    std::uint64_t peakBytes = 0;  // the most ever held at once
    std::uint64_t allocationsInUse = 0;
    std::uint64_t allocationCount = 0; // allocations made so far
};

// Counts every vkAllocateMemory and vkFreeMemory of the context's buffers. Not thread-safe:
// vkpt creates buffers from one thread.
class MemoryAccounting {
public:
    void recordAllocation(std::uint64_t bytes);
    void recordFree(std::uint64_t bytes);
    const MemoryStats& stats() const { return stats_; }

private:
    MemoryStats stats_;
};

// "128.0 MiB (134217728 bytes)": sizes in messages a user can read and a developer can check.
std::string formatBytes(std::uint64_t bytes);

} // namespace vkpt
