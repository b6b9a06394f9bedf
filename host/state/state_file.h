// state_file.h — a render state as an OpenEXR file: the image and the layers a denoiser and a
// compositor read (albedo, normal, depth, sample count, variance) in the channels they expect,
// plus the per-pixel moments and the metadata that merging and resuming need. The channel
// names and attributes are documented in docs/distributed.md.
#pragma once

#include <string>

#include "state/render_state.h"

namespace vkpt {

// The value of the vkpt.format attribute; a file without it is not a render state.
inline constexpr const char* kStateFormat = "vkpt render state 2";

// Writes `state` to `path` atomically (atomic_write.h); InputError naming the path on failure.
void writeStateFile(const RenderState& state, const std::string& path);

// Reads a state written by writeStateFile. Throws InputError "<path>: <reason>" for a missing,
// foreign (not OpenEXR, or OpenEXR without vkpt's metadata), truncated or inconsistent file.
RenderState readStateFile(const std::string& path);

} // namespace vkpt
