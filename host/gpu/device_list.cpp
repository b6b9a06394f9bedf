// device_list.cpp — enumerates physical devices, judges each, and picks one.
#include "gpu/device_list.h"

#include "gpu/instance.h"
#include "gpu/validation.h"
#include "gpu/vk_check.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>

namespace vkpt {

namespace {

// Prefers a family that can also write timestamps, so that --stats can time kernels.
std::optional<std::uint32_t> findComputeQueueFamily(VkPhysicalDevice device) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    std::optional<std::uint32_t> found;
    for (std::uint32_t i = 0; i < count; ++i) {
        if ((families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) == 0) continue;
        if (families[i].timestampValidBits > 0) return i;
        if (!found) found = i;
    }
    return found;
}

// Driver name and info exist from Vulkan 1.2 on; asking an older device is invalid usage.
void readDriverProperties(VkPhysicalDevice device, DeviceInfo& info) {
    if (info.apiVersion < VK_API_VERSION_1_2) return;
    VkPhysicalDeviceDriverProperties driver{};
    driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
    VkPhysicalDeviceProperties2 properties{};
    properties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    properties.pNext = &driver;
    vkGetPhysicalDeviceProperties2(device, &properties);
    info.driverId = driver.driverID;
    info.driverName = driver.driverName;
    info.driverInfo = driver.driverInfo;
}

// The subgroup operations every kernel uses to count and append once per subgroup
// (shaders/lib/counters.glsl); Vulkan 1.1 guarantees only the basic ones.
constexpr VkSubgroupFeatureFlags kRequiredSubgroupOperations = VK_SUBGROUP_FEATURE_BASIC_BIT |
                                                               VK_SUBGROUP_FEATURE_BALLOT_BIT |
                                                               VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;

bool hasComputeSubgroupOperations(VkPhysicalDevice device) {
    VkPhysicalDeviceSubgroupProperties subgroup{};
    subgroup.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES;
    VkPhysicalDeviceProperties2 properties{};
    properties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    properties.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(device, &properties);
    return (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) != 0 &&
           (subgroup.supportedOperations & kRequiredSubgroupOperations) ==
               kRequiredSubgroupOperations;
}

std::string rejectionReason(const DeviceInfo& info) {
    if (info.apiVersion < VK_API_VERSION_1_2) {
        return "Vulkan " + formatVulkanVersion(info.apiVersion) + " < 1.2";
    }
    if (!info.computeQueueFamily) return "no compute queue";
    if (!hasComputeSubgroupOperations(info.handle))
        return "no subgroup ballot and arithmetic in compute shaders";
    return {};
}

DeviceInfo describePhysicalDevice(VkPhysicalDevice device, std::uint32_t index) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(device, &properties);
    DeviceInfo info;
    info.index = index;
    info.handle = device;
    info.name = properties.deviceName;
    info.type = properties.deviceType;
    info.apiVersion = properties.apiVersion;
    readDriverProperties(device, info);
    info.computeQueueFamily = findComputeQueueFamily(device);
    info.rejection = rejectionReason(info);
    return info;
}

// Lower is better: the default choice when the user names no device.
int typeRank(VkPhysicalDeviceType type) {
    constexpr std::array order = {VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU,
                                  VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU,
                                  VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU, VK_PHYSICAL_DEVICE_TYPE_CPU};
    const auto found = std::find(order.begin(), order.end(), type);
    return static_cast<int>(found - order.begin());
}

std::string toLower(std::string_view text) {
    std::string lower(text);
    for (char& c : lower)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return lower;
}

bool nameMatches(const DeviceInfo& device, const std::string& substring) {
    return toLower(device.name).find(toLower(substring)) != std::string::npos;
}

// "(2 devices found: 0: ...; 1: ...)", the tail of every selection error.
std::string foundDevicesSuffix(const std::vector<DeviceInfo>& devices) {
    std::string text = "(" + std::to_string(devices.size()) +
                       (devices.size() == 1 ? " device found" : " devices found");
    for (std::size_t i = 0; i < devices.size(); ++i) {
        text += (i == 0 ? ": " : "; ") + describeDevice(devices[i]);
    }
    return text + ")";
}

const DeviceInfo& requireUsable(const DeviceInfo& device) {
    if (!device.usable()) {
        throw VulkanError("Vulkan device " + describeDevice(device), VK_ERROR_INCOMPATIBLE_DRIVER);
    }
    return device;
}

const DeviceInfo& selectByIndex(const std::vector<DeviceInfo>& devices, std::uint32_t index) {
    if (index >= devices.size()) {
        throw VulkanError("no Vulkan device with index " + std::to_string(index) + " " +
                              foundDevicesSuffix(devices),
                          VK_ERROR_INCOMPATIBLE_DRIVER);
    }
    return requireUsable(devices[index]);
}

// The first usable match; a matching but unusable device is reported with its reason.
const DeviceInfo& selectByName(const std::vector<DeviceInfo>& devices, const std::string& name) {
    const DeviceInfo* rejected = nullptr;
    for (const DeviceInfo& device : devices) {
        if (!nameMatches(device, name)) continue;
        if (device.usable()) return device;
        if (!rejected) rejected = &device;
    }
    if (rejected) return requireUsable(*rejected);
    throw VulkanError("no Vulkan device matches '" + name + "' " + foundDevicesSuffix(devices),
                      VK_ERROR_INCOMPATIBLE_DRIVER);
}

const DeviceInfo& selectByType(const std::vector<DeviceInfo>& devices) {
    const DeviceInfo* best = nullptr;
    for (const DeviceInfo& device : devices) {
        if (device.usable() && (!best || typeRank(device.type) < typeRank(best->type))) {
            best = &device;
        }
    }
    if (!best) {
        throw VulkanError("no Vulkan device with a compute queue " + foundDevicesSuffix(devices),
                          VK_ERROR_INCOMPATIBLE_DRIVER);
    }
    return *best;
}

} // namespace

DeviceSelection parseDeviceSelection(std::string_view text) {
    DeviceSelection selection;
    std::uint32_t index = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), index);
    if (!text.empty() && error == std::errc() && end == text.data() + text.size()) {
        selection.index = index;
    } else {
        selection.nameSubstring = std::string(text);
    }
    return selection;
}

std::string deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "CPU";
    default:
        return "other";
    }
}

std::string describeDevice(const DeviceInfo& device) {
    std::string text = std::to_string(device.index) + ": " + device.name + " (" +
                       deviceTypeName(device.type) + ", Vulkan " +
                       formatVulkanVersion(device.apiVersion);
    if (!device.driverName.empty()) text += ", " + device.driverName + " " + device.driverInfo;
    text += ")";
    if (!device.usable()) text += ": rejected: " + device.rejection;
    return text;
}

std::vector<DeviceInfo> enumerateDevices(VkInstance instance) {
    std::uint32_t count = 0;
    VKPT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> handles(count);
    VKPT_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, handles.data()));
    std::vector<DeviceInfo> devices;
    for (std::uint32_t i = 0; i < count; ++i)
        devices.push_back(describePhysicalDevice(handles[i], i));
    return devices;
}

const DeviceInfo& selectDevice(const std::vector<DeviceInfo>& devices,
                               const DeviceSelection& selection) {
    if (selection.index) return selectByIndex(devices, *selection.index);
    if (!selection.nameSubstring.empty()) return selectByName(devices, selection.nameSubstring);
    return selectByType(devices);
}

std::vector<DeviceInfo> listDevices() {
    const Instance instance(validationRequestedByEnvironment());
    std::vector<DeviceInfo> devices = enumerateDevices(instance.handle());
    for (DeviceInfo& device : devices)
        device.handle = VK_NULL_HANDLE; // dies with the instance
    return devices;
}

} // namespace vkpt
