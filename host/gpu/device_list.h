// device_list.h — what Vulkan devices exist, which of them vkpt can use and why not, and which
// one to take (vk-bootstrap style: every rejection has a reason a user can read).
#pragma once

#include <volk.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vkpt {

struct DeviceInfo {
    std::uint32_t index = 0; // position in vkEnumeratePhysicalDevices
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    std::uint32_t apiVersion = 0;
    VkDriverId driverId{};  // 0 when the device cannot say (below Vulkan 1.2)
    std::string driverName; // "llvmpipe", "NVIDIA", ...
    std::string driverInfo; // "Mesa 22.3.6 (LLVM 15.0.6)", ...
    std::optional<std::uint32_t> computeQueueFamily;
    std::string rejection; // why vkpt cannot use the device; empty when it can

    bool usable() const { return rejection.empty(); }
};

// How the user picked a device: by index, by a case-insensitive name substring, or neither
// (then the best type wins: discrete, integrated, virtual, CPU).
struct DeviceSelection {
    std::optional<std::uint32_t> index;
    std::string nameSubstring;
};

// "--device 1" selects by index, "--device llvmpipe" by name.
DeviceSelection parseDeviceSelection(std::string_view text);

// "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other".
std::string deviceTypeName(VkPhysicalDeviceType type);

// "0: llvmpipe (LLVM 15.0.6, 256 bits) (CPU, Vulkan 1.3.230, llvmpipe Mesa 22.3.6 ...)" and,
// for a rejected device, ": rejected: <reason>".
std::string describeDevice(const DeviceInfo& device);

// Every physical device of `instance`, each with its rejection reason if any.
std::vector<DeviceInfo> enumerateDevices(VkInstance instance);

// The device to use; throws VulkanError naming what was found when nothing fits.
const DeviceInfo& selectDevice(const std::vector<DeviceInfo>& devices,
                               const DeviceSelection& selection);

// Lists the devices through a temporary instance (for `vkpt --list-devices` and tests),
// validated when VKPT_VALIDATION=1. The handles are null: they die with that instance.
std::vector<DeviceInfo> listDevices();

} // namespace vkpt
