// barriers.h — the few memory dependencies a compute-only program needs, named by what they
// order. Global memory barriers: on the hardware vkpt targets they cost the same as buffer
// barriers and cannot forget a buffer.
#pragma once

#include <volk.h>

namespace vkpt {

// Shader writes of earlier dispatches → shader reads/writes and indirect-argument reads of
// later ones (between wavefront stages, and after a stage writes the next one's counts).
void recordComputeToComputeBarrier(VkCommandBuffer commands);

// Copies and fills → shader reads/writes and indirect-argument reads (after uploads).
void recordTransferToComputeBarrier(VkCommandBuffer commands);

// Shader writes and copies → copies (before a download or a copy between buffers).
void recordComputeToTransferBarrier(VkCommandBuffer commands);

// Shader writes and copies → host reads of mapped memory (the end of a download).
void recordDeviceToHostBarrier(VkCommandBuffer commands);

} // namespace vkpt
