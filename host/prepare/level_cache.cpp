// level_cache.cpp — bottom levels kept by their exact geometry, one frame to the next.
#include "prepare/level_cache.h"

#include <algorithm>
#include <cstring>
#include <optional>

#include "common/content_hash.h"

namespace vkpt {

namespace {

template <typename T> std::uint64_t hashOf(const std::vector<T>& values) {
    return hashValues(std::span<const T>(values));
}

LevelHashes hashLevel(const GpuPrimitives& primitives) {
    LevelHashes hashes;
    hashes.primitiveCount = static_cast<std::uint32_t>(primitives.records.size());
    hashes.records = hashOf(primitives.records) ^ std::rotl(hashOf(primitives.normals), 1);
    hashes.uvs = hashOf(primitives.uvs);
    hashes.tangents = hashOf(primitives.tangents);
    return hashes;
}

std::vector<char> alphaMaskedMaterials(std::span<const SceneMaterial> materials) {
    std::vector<char> masked(materials.size());
    std::transform(materials.begin(), materials.end(), masked.begin(),
                   [](const SceneMaterial& m) { return char(m.alphaMode == AlphaMode::Mask); });
    return masked;
}

template <typename T> bool sameBytes(std::span<const T> a, std::span<const T> b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

template <typename T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return sameBytes(std::span<const T>(a), std::span<const T>(b));
}

bool sameSoup(const TriangleSoup& a, const TriangleSoup& b) {
    return sameBytes(a.materialIndices, b.materialIndices) && sameBytes(a.positions, b.positions) &&
           sameBytes(a.normals, b.normals) && sameBytes(a.texcoords, b.texcoords) &&
           sameBytes(a.tangents, b.tangents);
}

bool sameLayout(const LevelLayout& a, const LevelLayout& b) {
    // threadCount does not change the tree (bvh_build.h).
    return a.withUvs == b.withUvs && a.withTangents == b.withTangents &&
           a.bvh.binCount == b.bvh.binCount && a.bvh.maxLeafSize == b.bvh.maxLeafSize &&
           a.bvh.traversalCost == b.bvh.traversalCost &&
           a.bvh.intersectionCost == b.bvh.intersectionCost;
}

// The bucket: the counts and at most 64 positions spread over the soup. The comparison of the
// whole geometry decides; the bucket only has to keep different geometries apart, cheaply.
std::uint64_t bucketOf(const LevelGeometry& geometry) {
    const std::vector<glm::vec3>& positions = geometry.soup.positions;
    std::vector<glm::vec3> sample;
    const std::size_t step = std::max<std::size_t>(positions.size() / 64, 1);
    for (std::size_t i = 0; i < positions.size(); i += step)
        sample.push_back(positions[i]);
    const std::uint64_t counts[2] = {positions.size(), geometry.spheres.size()};
    return hashValues(std::span<const glm::vec3>(sample)) ^
           std::rotl(hashValues(std::span<const std::uint64_t>(counts)), 1);
}

} // namespace

PreparedLevel prepareLevel(const LevelGeometry& geometry, const LevelLayout& layout, BvhCache* bvhs,
                           BuildPhases phases) {
    PreparedLevel level;
    level.bvh = buildFlattenedBvh(primitiveBounds(geometry.soup, geometry.spheres), layout.bvh,
                                  bvhs, phases);
    level.stats = computeBvhStats(level.bvh.tree, layout.bvh);
    level.primitives = makeGpuPrimitives(geometry.soup, geometry.spheres, geometry.materials,
                                         level.bvh.tree, layout.withUvs, layout.withTangents);
    level.hashes = hashLevel(level.primitives);
    return level;
}

const PreparedLevel& LevelCache::get(const LevelGeometry& geometry, const LevelLayout& layout,
                                     BvhCache* bvhs, BuildPhases phases) {
    const std::uint64_t bucket = bucketOf(geometry);
    const std::vector<char> alphaMasked = alphaMaskedMaterials(geometry.materials);
    auto [first, last] = entries_.equal_range(bucket);
    for (auto it = first; it != last; ++it) {
        Entry& entry = it->second;
        if (!sameLayout(entry.key.layout, layout) || entry.key.alphaMasked != alphaMasked ||
            !sameBytes(std::span<const SceneSphere>(entry.key.spheres), geometry.spheres) ||
            !sameSoup(entry.key.soup, geometry.soup))
            continue;
        entry.used = true;
        ++stats_.reused;
        stats_.reusedPrimitives += entry.level.hashes.primitiveCount;
        return entry.level;
    }
    Key key{geometry.soup, {geometry.spheres.begin(), geometry.spheres.end()}, alphaMasked, layout};
    Entry entry{std::move(key), prepareLevel(geometry, layout, bvhs, phases), true};
    ++stats_.prepared;
    return entries_.emplace(bucket, std::move(entry))->second.level;
}

void LevelCache::endFrame() {
    std::erase_if(entries_, [](auto& item) { return !item.second.used; });
    for (auto& item : entries_)
        item.second.used = false;
    stats_ = {};
}

} // namespace vkpt
