// bvh_cache.h — the bottom-level BVHs an animation's frames share (docs/scene-model.md,
// "Frames"): a tree built for one frame is taken again by the next frame whose primitives have
// the very same boxes, so that only geometry that moved is built anew. The build is deterministic
// (bvh_build.h: the tree does not depend on the thread count), so a tree taken from the cache is
// the tree a build from scratch would give, node for node: frames render exactly as from scratch.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "bvh/bvh_build.h"
#include "shared/host_device.h"

namespace vkpt {

// A tree as prepare lays it out: the binary tree with its leaves renumbered by flattenWideBvh,
// and its wide device nodes numbered from 0.
struct FlattenedBvh {
    BvhTree tree;
    std::vector<gpu::WideBvhNode> nodes;
};

struct BvhCacheStats {
    std::uint32_t built = 0; // trees built this frame
    std::uint32_t reused = 0;
    std::uint64_t reusedPrimitives = 0;
};

// Whether a build is logged as the phases "BVH build" and "BVH collapse" (a scene's one tree),
// or not (each of a two-level scene's many bottom levels, timed together by the caller).
enum class BuildPhases { Logged, Silent };

class BvhCache {
public:
    // The flattened tree over `bounds` built with `options`: the cached one when an entry has
    // exactly these boxes and options (compared in full, not by a hash alone), else built and kept.
    const FlattenedBvh& get(std::span<const Aabb> bounds, const BvhBuildOptions& options,
                            BuildPhases phases);

    // Ends a frame: trees this frame did not use are dropped (a moving mesh's old shapes would
    // otherwise pile up), and the counts start again.
    void endFrame();

    const BvhCacheStats& stats() const { return stats_; }

private:
    struct Entry {
        std::vector<Aabb> bounds;
        BvhBuildOptions options;
        FlattenedBvh bvh;
        bool used = false;
    };
    std::unordered_multimap<std::uint64_t, Entry> entries_;
    BvhCacheStats stats_;
};

// Builds over `bounds` and flattens, through `cache` when given.
FlattenedBvh buildFlattenedBvh(std::span<const Aabb> bounds, const BvhBuildOptions& options,
                               BvhCache* cache, BuildPhases phases = BuildPhases::Logged);

} // namespace vkpt
