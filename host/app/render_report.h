// render_report.h — what a finished render tells the user: a summary on stdout and, when
// asked, every figure as JSON.
#pragma once

#include <string>

#include "bvh/bvh_build.h"
#include "common/render_settings.h"
#include "common/render_stats.h"

namespace vkpt {

struct RenderReport {
    std::string program;      // "vkpt-ref" or "vkpt"
    std::string device;       // "CPU, 2 threads" or the Vulkan device name
    const RenderSettings* settings = nullptr;
    BvhStats bvh;
    std::size_t triangles = 0;
    std::size_t emitters = 0;
    RenderStats stats;
    double loadSeconds = 0.0;
    std::uint64_t deviceMemoryBytes = 0; // 0 on the CPU
};

void printRenderSummary(const RenderReport& report);
void writeStatsJson(const RenderReport& report, const std::string& path);

} // namespace vkpt
