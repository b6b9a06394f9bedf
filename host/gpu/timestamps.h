// timestamps.h — GpuTimer: per-kernel GPU times from a timestamp query pool, for --stats.
// A no-op on devices whose compute queue has no timestamps.
#pragma once

#include <volk.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vkpt {

class GpuContext;

struct KernelTime {
    std::string label; // usually the kernel's name
    std::uint64_t nanoseconds = 0;
};

class GpuTimer {
public:
    // Room for `capacity` timed intervals per recording.
    GpuTimer(const GpuContext& context, std::uint32_t capacity, std::string_view name = "gpuTimer");
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    bool enabled() const { return pool_ != VK_NULL_HANDLE; }

    // Resets the queries; record it before the first begin() of each submission.
    void recordReset(VkCommandBuffer commands);
    // Each begin/end pair brackets the commands to time. Timestamps are taken at the compute
    // stage, so an interval starts when earlier compute work has finished and consecutive
    // intervals do not overlap.
    void recordBegin(VkCommandBuffer commands, std::string_view label);
    void recordEnd(VkCommandBuffer commands);

    // The intervals of the last recording; call once its submission has completed.
    std::vector<KernelTime> results() const;

private:
    const GpuContext* context_;
    std::uint32_t capacity_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    std::vector<std::string> labels_;
    bool open_ = false;
};

} // namespace vkpt
