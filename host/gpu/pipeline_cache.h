// pipeline_cache.h — a VkPipelineCache kept in a file between runs, so that a driver that
// honours one (GPU drivers; lavapipe 22.3's cache holds only its header) compiles a kernel once
// per driver version instead of once per render. The file is vkpt's own frame (magic, size,
// FNV-1a checksum) around the driver's data; one that is damaged, truncated or made by another
// device or driver is ignored with one line on stderr, never handed to the driver.
#pragma once

#include <volk.h>

#include <cstdint>
#include <string>
#include <vector>

namespace vkpt {

struct DeviceInfo;

// Where vkpt keeps the device's cache by default: $XDG_CACHE_HOME/vkpt (else ~/.cache/vkpt),
// named by vendor, device and the driver's pipelineCacheUUID; empty when neither variable is
// set or VKPT_NO_PIPELINE_CACHE is set (to anything but 0).
std::string defaultPipelineCachePath(VkPhysicalDevice device);

// The driver's cache data from a cache file, or empty (with `problem` saying why) when the file
// is missing, damaged, or made for another device or driver.
std::vector<std::uint8_t> readPipelineCacheFile(const std::string& path, VkPhysicalDevice device,
                                                std::string& problem);

// Writes the driver's cache data in vkpt's frame, atomically (a temporary file renamed over
// `path`, its folder made if missing); false when that fails.
bool writePipelineCacheFile(const std::string& path, const std::vector<std::uint8_t>& payload);

class PipelineCache {
public:
    // An empty cache when `path` is empty; else one seeded from the file (a bad file: one line
    // on stderr naming it and why, then an empty cache).
    PipelineCache(VkDevice device, VkPhysicalDevice physicalDevice, std::string path);
    ~PipelineCache();
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;

    VkPipelineCache handle() const { return cache_; }
    const std::string& path() const { return path_; }
    // Writes the cache to its file (atomically: a temporary file renamed over it) when it holds
    // more than the file had and more than a bare header; a failed write is one line on stderr,
    // not an error (the render does not depend on it). Returns whether it wrote.
    bool save();

private:
    VkDevice device_;
    std::string path_;
    std::size_t loadedBytes_ = 0;
    VkPipelineCache cache_ = VK_NULL_HANDLE;
};

} // namespace vkpt
