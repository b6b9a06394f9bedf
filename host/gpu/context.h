// context.h — GpuContext: the instance, the chosen device, its one compute queue and command
// pool, the limits vkpt respects, and the accounting every buffer reports to.
#pragma once

#include "gpu/debug_utils.h"
#include "gpu/device_list.h"
#include "gpu/folded_spirv_cache.h"
#include "gpu/instance.h"
#include "gpu/kernel_memo.h"
#include "gpu/memory.h"
#include "gpu/pipeline_cache.h"

#include <volk.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace vkpt {

struct GpuOptions {
    // Enables VK_LAYER_KHRONOS_validation; the environment variable VKPT_VALIDATION=1 does too.
    bool validation = false;
    DeviceSelection device;
    // The pipeline cache file (gpu/pipeline_cache.h): empty for none (tests); vkpt passes
    // defaultPipelineCachePath unless --no-cache.
    bool persistentPipelineCache = false;
    std::string pipelineCachePath; // with persistentPipelineCache; empty: the default path
};

// The properties vkpt checks before it asks for something the device cannot do.
struct DeviceLimits {
    VkDeviceSize maxStorageBufferRange = 0;   // largest storage buffer a kernel can bind
    VkDeviceSize maxMemoryAllocationSize = 0; // largest single allocation
    VkDeviceSize minStorageBufferOffsetAlignment = 0;
    std::uint32_t maxPushConstantsSize = 0;
    std::uint32_t maxPerStageDescriptorStorageBuffers = 0;
    VkDeviceSize maxUniformBufferRange = 0;
    std::uint32_t maxPerStageDescriptorUniformBuffers = 0;
    std::uint32_t maxTexelBufferElements = 0;             // elements one texel view may see
    std::uint32_t maxPerStageDescriptorSampledImages = 0; // uniform texel buffers count here
    std::uint32_t maxComputeWorkGroupInvocations = 0;
    std::array<std::uint32_t, 3> maxComputeWorkGroupCount{};
    std::array<std::uint32_t, 3> maxComputeWorkGroupSize{};
    std::uint32_t subgroupSize = 0;
    VkDeviceSize deviceLocalHeapSize = 0; // the largest DEVICE_LOCAL heap: all vkpt may hold
    float timestampPeriod = 0.0f;         // nanoseconds per timestamp tick
    std::uint32_t timestampValidBits = 0; // of the compute queue family; 0: no timestamps
};

class GpuContext {
public:
    // Creates the instance (with validation if asked), selects a device (throws VulkanError
    // listing every device and why it was rejected when none fits) and creates the device with
    // one compute queue and a command pool.
    explicit GpuContext(const GpuOptions& options = {});
    ~GpuContext();
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;

    VkInstance instance() const { return instance_.handle(); }
    VkPhysicalDevice physicalDevice() const { return deviceInfo_.handle; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queueFamily() const { return *deviceInfo_.computeQueueFamily; }
    VkCommandPool commandPool() const { return commandPool_; }

    const DeviceInfo& deviceInfo() const { return deviceInfo_; }
    // Every device the instance reported, the chosen one included.
    const std::vector<DeviceInfo>& devices() const { return devices_; }
    const DeviceLimits& limits() const { return limits_; }
    const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return memory_; }
    bool timestampsSupported() const { return limits_.timestampValidBits > 0; }

    bool validationEnabled() const { return instance_.validationEnabled(); }
    // Validation warnings and errors so far; tests require 0.
    std::size_t validationMessageCount() const { return instance_.validationMessageCount(); }
    // Outlives the context, so a test can still count what the layer says at vkDestroyDevice.
    std::shared_ptr<const ValidationLog> validationLog() const { return instance_.validationLog(); }
    bool debugUtilsEnabled() const { return instance_.debugUtilsEnabled(); }

    // Names a Vulkan object for validation messages and captures; a no-op without debug utils.
    template <typename Handle> void setDebugName(Handle handle, std::string_view name) const {
        setObjectName(debugUtilsEnabled(), device_, objectTypeOf(handle),
                      reinterpret_cast<std::uint64_t>(handle), name);
    }

    // Every kernel's pipeline goes through it; a file-backed one when GpuOptions asked.
    PipelineCache& pipelineCache() const { return *pipelineCache_; }
    // Kernels folded for their constants, kept between runs (folded_spirv_cache.h).
    const FoldedSpirvCache& foldedSpirvCache() const { return foldedSpirvCache_; }

    // The pipelines renders on this device have made, for the next render that needs them.
    KernelMemo& kernelMemo() const { return *kernelMemo_; }

    MemoryAccounting& memoryAccounting() { return memoryAccounting_; }
    const MemoryStats& memoryStats() const { return memoryAccounting_.stats(); }

private:
    void createDevice();
    void createCommandPool();

    Instance instance_;
    std::vector<DeviceInfo> devices_;
    DeviceInfo deviceInfo_;
    DeviceLimits limits_;
    VkPhysicalDeviceMemoryProperties memory_{};
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool commandPool_ = VK_NULL_HANDLE;
    std::unique_ptr<PipelineCache> pipelineCache_;
    FoldedSpirvCache foldedSpirvCache_;
    std::unique_ptr<KernelMemo> kernelMemo_ = std::make_unique<KernelMemo>();
    MemoryAccounting memoryAccounting_;
};

} // namespace vkpt
