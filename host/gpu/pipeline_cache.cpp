// pipeline_cache.cpp — the file: "vkptpc01", payload bytes (u64), FNV-1a 64 of the payload (u64),
// then the payload, which is vkGetPipelineCacheData's output (its own header first: length,
// version, vendor, device, pipelineCacheUUID; Vulkan spec, vkGetPipelineCacheData).
#include "gpu/pipeline_cache.h"

#include "gpu/cache_files.h"
#include "gpu/vk_check.h"

#include <cstdio>
#include <cstring>

namespace vkpt {

namespace {

constexpr char kMagic[8] = {'v', 'k', 'p', 't', 'p', 'c', '0', '1'};
constexpr std::size_t kFrameBytes = sizeof(kMagic) + 2 * sizeof(std::uint64_t);
// Vulkan's header: length, version (u32 each), vendorID, deviceID, then the 16-byte UUID.
constexpr std::size_t kVulkanHeaderBytes = 16 + VK_UUID_SIZE;

std::uint32_t readU32(const std::uint8_t* p) {
    std::uint32_t v;
    std::memcpy(&v, p, sizeof(v));
    return v;
}

std::uint64_t readU64(const std::uint8_t* p) {
    std::uint64_t v;
    std::memcpy(&v, p, sizeof(v));
    return v;
}

VkPhysicalDeviceProperties propertiesOf(VkPhysicalDevice device) {
    VkPhysicalDeviceProperties properties{};
    vkGetPhysicalDeviceProperties(device, &properties);
    return properties;
}

std::string hex(const std::uint8_t* bytes, std::size_t count) {
    static const char digits[] = "0123456789abcdef";
    std::string text;
    for (std::size_t i = 0; i < count; ++i) {
        text += digits[bytes[i] >> 4];
        text += digits[bytes[i] & 15];
    }
    return text;
}

} // namespace

std::string defaultPipelineCachePath(VkPhysicalDevice device) {
    if (cacheFilesDisabledByEnvironment()) return "";
    const std::filesystem::path folder = vkptCacheFolder();
    if (folder.empty()) return "";
    const VkPhysicalDeviceProperties p = propertiesOf(device);
    char name[64];
    std::snprintf(name, sizeof(name), "pipelines-%04x-%04x-", p.vendorID, p.deviceID);
    return (folder / (name + hex(p.pipelineCacheUUID, VK_UUID_SIZE) + ".bin")).string();
}

std::vector<std::uint8_t> readPipelineCacheFile(const std::string& path, VkPhysicalDevice device,
                                                std::string& problem) {
    if (!std::filesystem::exists(path)) return {}; // none yet: nothing to say
    const std::vector<std::uint8_t> file = readWholeFile(path);
    if (file.size() < kFrameBytes || std::memcmp(file.data(), kMagic, sizeof(kMagic)) != 0) {
        problem = "not a vkpt pipeline cache";
        return {};
    }
    const std::uint64_t size = readU64(file.data() + sizeof(kMagic));
    const std::uint64_t checksum = readU64(file.data() + sizeof(kMagic) + sizeof(std::uint64_t));
    if (size != file.size() - kFrameBytes || size < kVulkanHeaderBytes) {
        problem = "truncated";
        return {};
    }
    const std::uint8_t* payload = file.data() + kFrameBytes;
    if (fnv1a(payload, size) != checksum) {
        problem = "damaged (checksum mismatch)";
        return {};
    }
    const VkPhysicalDeviceProperties p = propertiesOf(device);
    if (readU32(payload) < kVulkanHeaderBytes ||
        readU32(payload + 4) != VK_PIPELINE_CACHE_HEADER_VERSION_ONE ||
        readU32(payload + 8) != p.vendorID || readU32(payload + 12) != p.deviceID ||
        std::memcmp(payload + 16, p.pipelineCacheUUID, VK_UUID_SIZE) != 0) {
        problem = "made by another device or driver version";
        return {};
    }
    return {payload, payload + size};
}

PipelineCache::PipelineCache(VkDevice device, VkPhysicalDevice physicalDevice, std::string path)
    : device_(device), path_(std::move(path)) {
    std::vector<std::uint8_t> initial;
    if (!path_.empty()) {
        std::string problem;
        initial = readPipelineCacheFile(path_, physicalDevice, problem);
        if (!problem.empty())
            std::fprintf(stderr, "vkpt: pipeline cache %s: %s; starting an empty one\n",
                         path_.c_str(), problem.c_str());
    }
    loadedBytes_ = initial.size();
    VkPipelineCacheCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
    info.initialDataSize = initial.size();
    info.pInitialData = initial.empty() ? nullptr : initial.data();
    VKPT_VK_CHECK(vkCreatePipelineCache(device_, &info, nullptr, &cache_));
}

PipelineCache::~PipelineCache() {
    vkDestroyPipelineCache(device_, cache_, nullptr);
}

bool writePipelineCacheFile(const std::string& path, const std::vector<std::uint8_t>& payload) {
    std::vector<std::uint8_t> data(kFrameBytes + payload.size());
    const std::uint64_t payloadBytes = payload.size();
    const std::uint64_t checksum = fnv1a(payload.data(), payload.size());
    std::memcpy(data.data(), kMagic, sizeof(kMagic));
    std::memcpy(data.data() + sizeof(kMagic), &payloadBytes, sizeof(payloadBytes));
    std::memcpy(data.data() + sizeof(kMagic) + sizeof(payloadBytes), &checksum, sizeof(checksum));
    if (!payload.empty()) std::memcpy(data.data() + kFrameBytes, payload.data(), payload.size());
    return writeFileAtomically(path, data);
}

bool PipelineCache::save() {
    if (path_.empty()) return false;
    std::size_t size = 0;
    VKPT_VK_CHECK(vkGetPipelineCacheData(device_, cache_, &size, nullptr));
    // A bare header (lavapipe) or nothing new: no file to write.
    if (size <= kVulkanHeaderBytes || size <= loadedBytes_) return false;
    std::vector<std::uint8_t> payload(size);
    VKPT_VK_CHECK(vkGetPipelineCacheData(device_, cache_, &size, payload.data()));
    payload.resize(size);
    if (!writePipelineCacheFile(path_, payload)) {
        std::fprintf(stderr, "vkpt: pipeline cache %s: cannot write it; going on without\n",
                     path_.c_str());
        return false;
    }
    loadedBytes_ = size;
    return true;
}

} // namespace vkpt
