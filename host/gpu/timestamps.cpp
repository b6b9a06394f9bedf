// timestamps.cpp — timestamp queries turned into labelled nanoseconds.
#include "gpu/timestamps.h"

#include "common/errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"

#include <cmath>

namespace vkpt {

GpuTimer::GpuTimer(const GpuContext& context, std::uint32_t capacity, std::string_view name)
    : context_(&context), capacity_(capacity) {
    if (!context.timestampsSupported() || capacity == 0) return;
    VkQueryPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = 2 * capacity;
    VKPT_VK_CHECK(vkCreateQueryPool(context.device(), &info, nullptr, &pool_));
    context.setDebugName(pool_, name);
}

GpuTimer::~GpuTimer() {
    if (pool_ != VK_NULL_HANDLE) vkDestroyQueryPool(context_->device(), pool_, nullptr);
}

void GpuTimer::recordReset(VkCommandBuffer commands) {
    labels_.clear();
    open_ = false;
    if (enabled()) vkCmdResetQueryPool(commands, pool_, 0, 2 * capacity_);
}

void GpuTimer::recordBegin(VkCommandBuffer commands, std::string_view label) {
    VKPT_ASSERT(!open_, "GpuTimer: begin '" + std::string(label) + "' inside another interval");
    VKPT_ASSERT(labels_.size() < capacity_,
                "GpuTimer: more than " + std::to_string(capacity_) + " intervals");
    const auto query = static_cast<std::uint32_t>(2 * labels_.size());
    labels_.emplace_back(label);
    open_ = true;
    if (enabled()) {
        vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, pool_, query);
    }
}

void GpuTimer::recordEnd(VkCommandBuffer commands) {
    VKPT_ASSERT(open_, "GpuTimer: end without begin");
    open_ = false;
    const auto query = static_cast<std::uint32_t>(2 * labels_.size() - 1);
    if (enabled()) {
        vkCmdWriteTimestamp(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, pool_, query);
    }
}

std::vector<KernelTime> GpuTimer::results() const {
    VKPT_ASSERT(!open_, "GpuTimer: results with an interval still open");
    if (!enabled() || labels_.empty()) return {};
    std::vector<std::uint64_t> ticks(2 * labels_.size());
    VKPT_VK_CHECK(vkGetQueryPoolResults(
        context_->device(), pool_, 0, static_cast<std::uint32_t>(ticks.size()),
        ticks.size() * sizeof(std::uint64_t), ticks.data(), sizeof(std::uint64_t),
        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    // Counters may wrap at timestampValidBits; subtracting modulo 2^bits undoes one wrap.
    const std::uint32_t bits = context_->limits().timestampValidBits;
    const std::uint64_t mask = bits >= 64 ? ~0ull : (1ull << bits) - 1;
    const double period = context_->limits().timestampPeriod;
    std::vector<KernelTime> times;
    for (std::size_t i = 0; i < labels_.size(); ++i) {
        const std::uint64_t elapsed = (ticks[2 * i + 1] - ticks[2 * i]) & mask;
        times.push_back({labels_[i], static_cast<std::uint64_t>(
                                         std::llround(static_cast<double>(elapsed) * period))});
    }
    return times;
}

} // namespace vkpt
