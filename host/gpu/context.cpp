// context.cpp — device selection and creation: one compute queue, one command pool.
#include "gpu/context.h"

#include "gpu/vk_check.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace vkpt {

namespace {

DeviceLimits readLimits(const DeviceInfo& device) {
    VkPhysicalDeviceSubgroupProperties subgroup{};
    subgroup.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES;
    VkPhysicalDeviceMaintenance3Properties maintenance3{};
    maintenance3.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES;
    maintenance3.pNext = &subgroup;
    VkPhysicalDeviceProperties2 properties{};
    properties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    properties.pNext = &maintenance3;
    vkGetPhysicalDeviceProperties2(device.handle, &properties);

    const VkPhysicalDeviceLimits& limits = properties.properties.limits;
    DeviceLimits result;
    result.maxStorageBufferRange = limits.maxStorageBufferRange;
    result.maxMemoryAllocationSize = maintenance3.maxMemoryAllocationSize;
    result.minStorageBufferOffsetAlignment = limits.minStorageBufferOffsetAlignment;
    result.maxPushConstantsSize = limits.maxPushConstantsSize;
    result.maxPerStageDescriptorStorageBuffers = limits.maxPerStageDescriptorStorageBuffers;
    result.maxUniformBufferRange = limits.maxUniformBufferRange;
    result.maxPerStageDescriptorUniformBuffers = limits.maxPerStageDescriptorUniformBuffers;
    result.maxTexelBufferElements = limits.maxTexelBufferElements;
    result.maxPerStageDescriptorSampledImages = limits.maxPerStageDescriptorSampledImages;
    result.maxComputeWorkGroupInvocations = limits.maxComputeWorkGroupInvocations;
    std::copy_n(limits.maxComputeWorkGroupCount, 3, result.maxComputeWorkGroupCount.begin());
    std::copy_n(limits.maxComputeWorkGroupSize, 3, result.maxComputeWorkGroupSize.begin());
    result.subgroupSize = subgroup.subgroupSize;
    result.timestampPeriod = limits.timestampPeriod;
    return result;
}

VkDeviceSize largestDeviceLocalHeap(const VkPhysicalDeviceMemoryProperties& memory) {
    VkDeviceSize largest = 0;
    for (std::uint32_t i = 0; i < memory.memoryHeapCount; ++i) {
        if ((memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) != 0) {
            largest = std::max(largest, memory.memoryHeaps[i].size);
        }
    }
    return largest;
}

std::uint32_t readTimestampValidBits(const DeviceInfo& device) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device.handle, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device.handle, &count, families.data());
    return families[*device.computeQueueFamily].timestampValidBits;
}

// Vulkan requires VK_KHR_portability_subset to be enabled wherever it is offered (MoltenVK).
bool offersPortabilitySubset(VkPhysicalDevice device) {
    std::uint32_t count = 0;
    VKPT_VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VKPT_VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()));
    return std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, "VK_KHR_portability_subset") == 0;
    });
}

} // namespace

GpuContext::GpuContext(const GpuOptions& options)
    : instance_(options.validation || validationRequestedByEnvironment()),
      devices_(enumerateDevices(instance_.handle())),
      deviceInfo_(selectDevice(devices_, options.device)), limits_(readLimits(deviceInfo_)),
      foldedSpirvCache_(
          foldedSpirvCacheFolder(options.persistentPipelineCache, options.pipelineCachePath)) {
    limits_.timestampValidBits = readTimestampValidBits(deviceInfo_);
    vkGetPhysicalDeviceMemoryProperties(deviceInfo_.handle, &memory_);
    limits_.deviceLocalHeapSize = largestDeviceLocalHeap(memory_);
    createDevice();
    try {
        setDebugName(device_, deviceInfo_.name);
        setDebugName(queue_, "computeQueue");
        createCommandPool();
        std::string cachePath;
        if (options.persistentPipelineCache)
            cachePath = options.pipelineCachePath.empty()
                            ? defaultPipelineCachePath(deviceInfo_.handle)
                            : options.pipelineCachePath;
        pipelineCache_ =
            std::make_unique<PipelineCache>(device_, deviceInfo_.handle, std::move(cachePath));
    } catch (...) {
        if (commandPool_) vkDestroyCommandPool(device_, commandPool_, nullptr);
        vkDestroyDevice(device_, nullptr);
        throw;
    }
}

GpuContext::~GpuContext() {
    // Nothing may still run when its pool and device go; vkpt waits on fences, so this is cheap.
    vkDeviceWaitIdle(device_);
    kernelMemo_->clear();
    pipelineCache_.reset();
    vkDestroyCommandPool(device_, commandPool_, nullptr);
    vkDestroyDevice(device_, nullptr);
}

void GpuContext::createDevice() {
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = queueFamily();
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    std::vector<const char*> extensions;
    if (offersPortabilitySubset(deviceInfo_.handle))
        extensions.push_back("VK_KHR_portability_subset");

    VkDeviceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VKPT_VK_CHECK(vkCreateDevice(deviceInfo_.handle, &info, nullptr, &device_));
    vkGetDeviceQueue(device_, queueFamily(), 0, &queue_);
}

void GpuContext::createCommandPool() {
    VkCommandPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    // Command buffers are short-lived (one submission each), so the pool says so.
    info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    info.queueFamilyIndex = queueFamily();
    VKPT_VK_CHECK(vkCreateCommandPool(device_, &info, nullptr, &commandPool_));
    setDebugName(commandPool_, "commandPool");
}

} // namespace vkpt
