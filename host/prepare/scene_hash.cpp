// scene_hash.cpp — FNV-1a (Fowler, Noll and Vo; the 64-bit parameters of the IETF draft
// draft-eastlake-fnv) over 64-bit content hashes of the arrays' bytes and their sizes. Every
// record is a std430 struct without implicit padding whose unused words are value-initialised, so
// equal scenes give equal bytes.
#include "prepare/scene_hash.h"

#include <cstdio>
#include <span>
#include <vector>

#include "common/content_hash.h"
#include "common/errors.h"

namespace vkpt {

namespace {

class Fnv1a64 {
public:
    // A word: its eight bytes.
    void addWord(std::uint64_t word) {
        for (int b = 0; b < 8; ++b) {
            hash_ ^= (word >> (8 * b)) & 0xffu;
            hash_ *= 0x100000001b3ull;
        }
    }
    // An array: the content hash of its bytes, then its count (so that [a][bc] and [ab][c]
    // differ).
    template <typename T> void addArray(const std::vector<T>& values) {
        addWord(hashValues(std::span<const T>(values)));
        addWord(values.size());
    }
    template <typename T> void addValue(const T& value) {
        addWord(hashValues(std::span<const T>(&value, 1)));
    }

    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
        return text;
    }

private:
    std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

// The primitive arrays by their bottom levels' hashes, which cover them in order.
void addLevels(const PreparedScene& scene, Fnv1a64& hash) {
    std::size_t covered = 0;
    for (const LevelHashes& level : scene.levelHashes) {
        hash.addWord(level.primitiveCount);
        hash.addWord(level.records);
        // --general fills these even for a scene that does not use them.
        if (scene.usedFeatures.textureCoordinates()) hash.addWord(level.uvs);
        if (scene.usedFeatures.tangents()) hash.addWord(level.tangents);
        covered += level.primitiveCount;
    }
    VKPT_ASSERT(covered == scene.triangles.size(), "the bottom levels cover the primitives");
}

} // namespace

std::string sceneContentHash(const PreparedScene& scene, const gpu::Camera& camera) {
    Fnv1a64 hash;
    addLevels(scene, hash);
    hash.addArray(scene.materials);
    hash.addArray(scene.emitters);
    hash.addValue(scene.environment);
    hash.addArray(scene.environmentTexels);
    // Instanced meshes are in their own space: the placements are part of the scene.
    if (scene.usedFeatures.instances) hash.addArray(scene.instances);
    if (scene.usedFeatures.textures()) {
        hash.addArray(scene.textures);
        hash.addArray(scene.texels);
    }
    hash.addValue(camera);
    return hash.hex();
}

} // namespace vkpt
