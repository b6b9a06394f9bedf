// instance.cpp — volk initialisation and instance creation with optional validation.
#include "gpu/instance.h"

#include "gpu/vk_check.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace vkpt {

namespace {

// volkInitialize dlopens libvulkan; once per process is enough.
void loadVulkanLoader() {
    static const VkResult result = volkInitialize();
    if (result != VK_SUCCESS) {
        throw VulkanError("no Vulkan loader found (install libvulkan1 and a driver, e.g. "
                          "mesa-vulkan-drivers)",
                          result);
    }
    const std::uint32_t loaderVersion = volkGetInstanceVersion();
    if (loaderVersion < VK_API_VERSION_1_2) {
        throw VulkanError("the Vulkan loader supports Vulkan " +
                              formatVulkanVersion(loaderVersion) +
                              "; vkpt needs 1.2 (update libvulkan1)",
                          VK_ERROR_INCOMPATIBLE_DRIVER);
    }
}

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    VKPT_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    VKPT_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    return std::any_of(layers.begin(), layers.end(), [name](const VkLayerProperties& layer) {
        return std::strcmp(layer.layerName, name) == 0;
    });
}

// Extensions of the loader and implicit layers, or of the named layer.
bool hasInstanceExtension(const char* layer, const char* name) {
    std::uint32_t count = 0;
    VKPT_VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VKPT_VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()));
    return std::any_of(extensions.begin(), extensions.end(),
                       [name](const VkExtensionProperties& extension) {
                           return std::strcmp(extension.extensionName, name) == 0;
                       });
}

bool hasInstanceExtension(const char* name, bool validation) {
    return hasInstanceExtension(nullptr, name) ||
           (validation && hasInstanceExtension(kValidationLayerName, name));
}

} // namespace

std::string formatVulkanVersion(std::uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version)) + "." +
           std::to_string(VK_API_VERSION_PATCH(version));
}

Instance::Instance(bool validation) {
    loadVulkanLoader();
    if (validation && !hasLayer(kValidationLayerName)) {
        throw VulkanError(std::string("validation requested but ") + kValidationLayerName +
                              " is not installed (install vulkan-validationlayers)",
                          VK_ERROR_LAYER_NOT_PRESENT);
    }
    debugUtils_ = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, validation);
    if (validation && !debugUtils_) {
        throw VulkanError("validation requested but VK_EXT_debug_utils is not available",
                          VK_ERROR_EXTENSION_NOT_PRESENT);
    }
    if (validation) validationLog_ = std::make_shared<ValidationLog>();
    createInstance();
    // Instance-level loading only: device commands then go through the loader's trampolines,
    // which stay valid for every instance and device a process creates (listDevices() makes a
    // second instance beside a live context, tests make several contexts).
    volkLoadInstance(instance_);
    if (validation) createMessenger();
}

void Instance::createInstance() {
    const bool validation = validationEnabled();
    std::vector<const char*> extensions;
    if (debugUtils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    // MoltenVK and other portability drivers are listed only when asked for.
    const bool portability =
        hasInstanceExtension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME, false);
    if (portability) extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    const bool validationFeatures =
        validation &&
        hasInstanceExtension(kValidationLayerName, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    if (validationFeatures) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    const char* layers[] = {kValidationLayerName};

    VkApplicationInfo application{};
    application.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    application.pApplicationName = "vkpt";
    application.pEngineName = "vkpt";
    application.apiVersion = VK_API_VERSION_1_2;

    // Synchronization validation catches missing barriers between transfers and kernels, a
    // bug class that core validation cannot see.
    const VkValidationFeatureEnableEXT enabledChecks[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{};
    features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enabledChecks;
    // Chained into instance creation so that its messages are caught too.
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{};
    if (validation) messengerInfo = validationLog_->messengerCreateInfo();
    if (validationFeatures) messengerInfo.pNext = &features;

    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pNext = validation ? &messengerInfo : nullptr;
    info.flags = portability ? VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR : 0;
    info.pApplicationInfo = &application;
    info.enabledLayerCount = validation ? 1 : 0;
    info.ppEnabledLayerNames = layers;
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VKPT_VK_CHECK(vkCreateInstance(&info, nullptr, &instance_));
}

void Instance::createMessenger() {
    const VkDebugUtilsMessengerCreateInfoEXT info = validationLog_->messengerCreateInfo();
    const VkResult result = vkCreateDebugUtilsMessengerEXT(instance_, &info, nullptr, &messenger_);
    if (result != VK_SUCCESS) {
        vkDestroyInstance(instance_, nullptr);
        throwVulkanError(result, "vkCreateDebugUtilsMessengerEXT", __FILE__, __LINE__);
    }
}

Instance::~Instance() {
    if (messenger_ != VK_NULL_HANDLE)
        vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
    vkDestroyInstance(instance_, nullptr);
}

} // namespace vkpt
