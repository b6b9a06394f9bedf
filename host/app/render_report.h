// render_report.h — what a finished render tells the user: a summary on stdout and, when
// asked, every figure as JSON.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/scene_setup.h"
#include "bvh/bvh_build.h"
#include "common/device_stats.h"
#include "common/phase_log.h"
#include "common/render_settings.h"
#include "common/render_stats.h"
#include "convergence/convergence.h"
#include "scene/scene_features.h"

namespace vkpt {

// What only the device executor (vkpt) has to report.
struct DeviceRunReport : DeviceRunFigures {
    std::uint32_t passes = 0;
    double setupSeconds = 0.0; // upload, buffers and pipelines, before the first pass
    bool interrupted = false;  // Ctrl-C: the image holds the passes done
};

struct RenderReport {
    std::string program; // "vkpt-ref" or "vkpt"
    std::string device;  // "CPU, 2 threads" or the Vulkan device name
    const RenderSettings* settings = nullptr;
    BvhStats bvh;
    std::size_t triangles = 0;         // primitives stored (triangles and spheres)
    std::uint64_t placedTriangles = 0; // triangles placed: more than stored with instances
    std::size_t instances = 0;
    std::size_t meshes = 0;
    std::size_t emitters = 0;
    SceneFeatures features;        // what the scene uses
    bool generalPipelines = false; // --general: built for every feature instead
    RenderStats stats;
    double loadSeconds = 0.0;
    std::uint64_t deviceMemoryBytes = 0;          // peak device memory held; 0 on the CPU
    std::optional<DeviceRunReport> deviceRun;     // vkpt only
    std::optional<ConvergenceReport> convergence; // --reference, --target-error, --time-limit
    // Where the process's time went (common/phase_log.h), up to the report, and the process's
    // wall and CPU seconds by then: filled by writeRenderReport from processPhases().
    std::vector<PhaseTime> phases;
    double processSeconds = 0.0;
    double processCpuSeconds = 0.0;
};

// What both programs know once the scene is set up: program, settings, BVH, scene counts,
// features and load time; the caller adds the device, the render's figures and the rest.
RenderReport sceneReport(const std::string& program, const RenderSettings& settings,
                         const SceneSetup& setup);

void printRenderSummary(const RenderReport& report);
void writeStatsJson(const RenderReport& report, const std::string& path);
// The summary on stdout, and the statistics JSON when --stats-json asked for it, with the
// process's phases so far.
void writeRenderReport(RenderReport report);

} // namespace vkpt
