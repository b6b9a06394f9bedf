// bvh_cache.cpp — trees kept by their primitives' exact boxes, one frame to the next.
#include "prepare/bvh_cache.h"

#include <algorithm>
#include <cstring>
#include <optional>

#include "bvh/bvh_wide.h"
#include "common/phase_log.h"

namespace vkpt {

namespace {

// The bucket: FNV-1a over the count and at most 64 boxes spread over the list. The comparison of
// all the boxes decides; the bucket only has to keep different geometries apart, cheaply.
std::uint64_t hashBounds(std::span<const Aabb> bounds) {
    std::uint64_t hash = 0xcbf29ce484222325ull ^ bounds.size();
    const std::size_t step = std::max<std::size_t>(bounds.size() / 64, 1);
    for (std::size_t i = 0; i < bounds.size(); i += step) {
        const auto* bytes = reinterpret_cast<const unsigned char*>(&bounds[i]);
        for (std::size_t b = 0; b < sizeof(Aabb); ++b) {
            hash ^= bytes[b];
            hash *= 0x100000001b3ull;
        }
    }
    return hash;
}

bool sameOptions(const BvhBuildOptions& a, const BvhBuildOptions& b) {
    // threadCount does not change the tree (bvh_build.h).
    return a.binCount == b.binCount && a.maxLeafSize == b.maxLeafSize &&
           a.traversalCost == b.traversalCost && a.intersectionCost == b.intersectionCost;
}

bool sameBounds(std::span<const Aabb> a, std::span<const Aabb> b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

FlattenedBvh build(std::span<const Aabb> bounds, const BvhBuildOptions& options,
                   BuildPhases phases) {
    FlattenedBvh bvh;
    std::optional<ScopedPhase> phase;
    if (phases == BuildPhases::Logged) phase.emplace("BVH build");
    bvh.tree = buildBvh(bounds, options);
    phase.reset();
    // Renumbers the tree's leaves so that each wide node's primitives are contiguous.
    if (phases == BuildPhases::Logged) phase.emplace("BVH collapse");
    bvh.nodes = flattenWideBvh(bvh.tree);
    return bvh;
}

} // namespace

const FlattenedBvh& BvhCache::get(std::span<const Aabb> bounds, const BvhBuildOptions& options,
                                  BuildPhases phases) {
    const std::uint64_t key = hashBounds(bounds);
    auto [first, last] = entries_.equal_range(key);
    for (auto it = first; it != last; ++it) {
        Entry& entry = it->second;
        if (!sameOptions(entry.options, options) || !sameBounds(entry.bounds, bounds)) continue;
        entry.used = true;
        ++stats_.reused;
        stats_.reusedPrimitives += bounds.size();
        return entry.bvh;
    }
    Entry entry{{bounds.begin(), bounds.end()}, options, build(bounds, options, phases), true};
    ++stats_.built;
    return entries_.emplace(key, std::move(entry))->second.bvh;
}

void BvhCache::endFrame() {
    std::erase_if(entries_, [](auto& item) { return !item.second.used; });
    for (auto& item : entries_)
        item.second.used = false;
    stats_ = {};
}

FlattenedBvh buildFlattenedBvh(std::span<const Aabb> bounds, const BvhBuildOptions& options,
                               BvhCache* cache, BuildPhases phases) {
    if (cache == nullptr) return build(bounds, options, phases);
    return cache->get(bounds, options, phases);
}

} // namespace vkpt
