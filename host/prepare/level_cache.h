// level_cache.h — the bottom levels an animation's frames share (docs/scene-model.md, "Frames"):
// a level prepared for one frame (its tree, its primitives' device records in the tree's order,
// and their hashes) is taken again by the next frame whose geometry is the very same, so that
// only what moved or changed shape is prepared anew. The geometry is compared in full (positions,
// normals, texture coordinates, tangents, materials, spheres), not by a hash alone; the
// preparation is deterministic, so a level taken from the cache is the level a preparation from
// scratch gives, byte for byte.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "prepare/bvh_cache.h"
#include "prepare/gpu_primitives.h"
#include "scene/scene.h"

namespace vkpt {

// What a bottom level's records hash to (common/content_hash.h), for the scene's fingerprint
// (scene_hash.h): computed once when the level is prepared and kept with it.
struct LevelHashes {
    std::uint32_t primitiveCount = 0;
    std::uint64_t records = 0; // the records as built (emitters not yet assigned) and normals
    std::uint64_t uvs = 0;     // the texture coordinates (0 when not laid out)
    std::uint64_t tangents = 0;
};

// A level's geometry: a soup and, for the world's own level, the spheres.
struct LevelGeometry {
    const TriangleSoup& soup;
    std::span<const SceneSphere> spheres;
    std::span<const SceneMaterial> materials; // alpha-masked ones mark their primitives
};

// How it is laid out: the build's options, and which per-primitive arrays are filled.
struct LevelLayout {
    BvhBuildOptions bvh;
    bool withUvs = false;
    bool withTangents = false;
};

struct PreparedLevel {
    FlattenedBvh bvh;
    BvhStats stats; // of bvh.tree, under the layout's build options
    GpuPrimitives primitives;
    LevelHashes hashes;
};

// Builds the level's tree (through `bvhs` when given) and its records, and measures and hashes
// them.
PreparedLevel prepareLevel(const LevelGeometry& geometry, const LevelLayout& layout, BvhCache* bvhs,
                           BuildPhases phases);

struct LevelCacheStats {
    std::uint32_t prepared = 0; // levels prepared this frame
    std::uint32_t reused = 0;
    std::uint64_t reusedPrimitives = 0;
};

class LevelCache {
public:
    // The level of this geometry and layout: the kept one when an entry has exactly these, else
    // prepared (its tree through `bvhs` when given) and kept.
    const PreparedLevel& get(const LevelGeometry& geometry, const LevelLayout& layout,
                             BvhCache* bvhs, BuildPhases phases);

    // Ends a frame: levels this frame did not use are dropped, and the counts start again.
    void endFrame();

    const LevelCacheStats& stats() const { return stats_; }

private:
    // The geometry a level was prepared from, kept to compare the next frames' with.
    struct Key {
        TriangleSoup soup;
        std::vector<SceneSphere> spheres;
        std::vector<char> alphaMasked; // per material
        LevelLayout layout;
    };
    struct Entry {
        Key key;
        PreparedLevel level;
        bool used = false;
    };
    std::unordered_multimap<std::uint64_t, Entry> entries_; // by a hash of a sample of the key
    LevelCacheStats stats_;
};

} // namespace vkpt
