// scene_hash.cpp — FNV-1a (Fowler, Noll and Vo; the 64-bit parameters of the IETF draft
// draft-eastlake-fnv) over the arrays' bytes. Every record is a std430 struct without implicit
// padding whose unused words are value-initialised, so equal scenes give equal bytes.
#include "prepare/scene_hash.h"

#include <cstdio>
#include <span>
#include <vector>

namespace vkpt {

namespace {

class Fnv1a64 {
public:
    template <typename T> void add(std::span<const T> values) {
        addBytes(std::as_bytes(values));
        const std::uint64_t count = values.size(); // so that [a][bc] and [ab][c] differ
        addBytes(std::as_bytes(std::span<const std::uint64_t>(&count, 1)));
    }
    template <typename T> void add(const std::vector<T>& values) {
        add(std::span<const T>(values));
    }
    template <typename T> void addValue(const T& value) { add(std::span<const T>(&value, 1)); }

    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
        return text;
    }

private:
    void addBytes(std::span<const std::byte> bytes) {
        for (std::byte b : bytes) {
            hash_ ^= std::uint64_t(b);
            hash_ *= 0x100000001b3ull;
        }
    }
    std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

} // namespace

std::string sceneContentHash(const PreparedScene& scene, const gpu::Camera& camera) {
    Fnv1a64 hash;
    hash.add(scene.triangles);
    hash.add(scene.normals);
    hash.add(scene.materials);
    hash.add(scene.emitters);
    hash.addValue(scene.environment);
    hash.add(scene.environmentTexels);
    // --general fills these even for a scene that does not use them.
    if (scene.usedFeatures.textureCoordinates()) hash.add(scene.uvs);
    if (scene.usedFeatures.tangents()) hash.add(scene.tangents);
    // Instanced meshes are in their own space: the placements are part of the scene.
    if (scene.usedFeatures.instances) hash.add(scene.instances);
    if (scene.usedFeatures.textures()) {
        hash.add(scene.textures);
        hash.add(scene.texels);
    }
    hash.addValue(camera);
    return hash.hex();
}

} // namespace vkpt
