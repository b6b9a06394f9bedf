// device_stats.h — what only a render on a Vulkan device has to report (vkpt --stats): GPU time
// per kernel and the device memory of each scene buffer. Plain figures without Vulkan, so that
// the report (host/app) takes them as the executor (host/render) produces them.
#pragma once

#include <cstdint>
#include <string>

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

} // namespace vkpt
