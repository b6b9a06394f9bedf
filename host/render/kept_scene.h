// kept_scene.h — an animation's scene arrays kept on the device from one frame to the next
// (docs/scene-model.md, "Frames"): a frame uploads only the parts of its arrays that differ from
// the frame before's, so that a large set that does not move is uploaded once, and a frame
// whose instances moved uploads their records and the top of the node array.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "prepare/prepared_scene.h"
#include "render/device_scene.h"

namespace vkpt {

class GpuContext;

struct KeptUploadStats {
    std::uint64_t uploadedBytes = 0; // this frame's
    std::uint64_t keptBytes = 0;     // already on the device, left as they were
};

class KeptDeviceScene {
public:
    // The block of an array whose contents one hash stands for: small enough that moving a few
    // instances uploads little (the top level leads the node array), large enough that the hashes
    // of a 100-million-triangle scene stay a few thousand per array.
    static constexpr std::uint64_t kBlockBytes = std::uint64_t(256) << 10;

    // The frame's arrays on the device, freeing each host copy once it is there (as
    // uploadSceneAndRelease). An array of the same size as the frame before's keeps its
    // buffers and gets only the blocks whose contents changed (compared by a 64-bit hash of
    // each block, kept from the frame before); any other is uploaded whole.
    DeviceScene upload(GpuContext& context, PreparedScene& scene);

    // The frame's device scene back after its render, for the next frame to keep from.
    void keep(DeviceScene&& scene) { last_ = std::move(scene); }

    const KeptUploadStats& stats() const { return stats_; }

private:
    std::optional<DeviceScene> last_;
    std::vector<std::vector<std::uint64_t>> blockHashes_; // per array of the list, per block
    KeptUploadStats stats_;
};

} // namespace vkpt
