// device_stats.h — what only a render on a Vulkan device has to report (vkpt --stats): GPU time
// per kernel and the device memory of each scene buffer. Plain figures without Vulkan, so that
// the report (host/app) takes them as the executor (host/render) produces them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkpt {

// One kernel's GPU time over a whole render, summed from timestamp queries.
struct KernelTimeTotal {
    std::string kernel; // the dispatch label: "trace_closest", ...
    std::uint64_t dispatches = 0;
    std::uint64_t nanoseconds = 0;

    double seconds() const { return double(nanoseconds) * 1e-9; }
};

// What creating one kernel's pipeline cost (vkCreateShaderModule + vkCreateComputePipelines):
// the SPIR-V the driver had to take in, and the time it took.
struct PipelineCreation {
    std::string kernel;           // "shade_hits", ...
    std::uint64_t spirvBytes = 0; // of the build the render chose (docs/gpu.md, "Pipelines")
    double seconds = 0.0;
};

// The device memory one of a scene's arrays holds, so that a specialised render and a
// --general one can be compared.
struct SceneBufferBytes {
    std::string name;          // the buffer's debug name: "bvhNodes", ..., "absentData"
    std::uint64_t bytes = 0;   // its allocation, alignment included (all its chunks together)
    std::uint32_t buffers = 1; // more than one for an array split across bindings
};

// Everything a render on a device reports beyond what every executor does: the wavefront
// renderer's result carries it and the report prints it as it stands.
struct DeviceRunFigures {
    std::uint32_t slotCount = 0;              // path slots
    std::vector<KernelTimeTotal> kernelTimes; // empty unless kernels were timed (--stats)
    std::uint64_t truncatedTraversals = 0;    // walks a driver loop limit cut short; must be 0
    // Wall time of creating every kernel's pipeline (vkCreateShaderModule +
    // vkCreateComputePipelines, on several threads), before the first pass: what specialisation
    // costs or saves (lavapipe compiles its LLVM code at the first dispatch, so there it
    // measures the SPIR-V → NIR stage only); each kernel's own time is in pipelineCreations.
    double pipelineCreationSeconds = 0.0;
    std::vector<PipelineCreation> pipelineCreations; // per kernel
    bool pipelinesCreatedEarly = false; // while the scene was prepared: the wait is what is left
    std::vector<SceneBufferBytes> sceneBuffers; // the scene's buffers, as uploaded: vkpt uploads
                                                // only the arrays the scene has
    std::uint64_t sceneBufferBytes = 0;         // Σ sceneBuffers
};

} // namespace vkpt
