// content_hash.h — a fast 64-bit hash of bytes, for telling contents apart: the blocks an
// animation's frames upload again (render/kept_scene.h) and the parts of a scene's fingerprint
// (prepare/scene_hash.h). Not cryptographic: it identifies, it does not authenticate.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace vkpt {

// Four lanes of 8-byte words, each word multiplied, rotated and multiplied into its lane (the
// round of the xxHash64 design, Collet 2014; four independent lanes so that the multiplications
// overlap), then the lanes, the length and the tail mixed together. A changed word changes the
// hash but for a chance of about 2^-64; several bytes a cycle where FNV-1a takes one a few.
inline std::uint64_t hashBytes(std::span<const std::byte> bytes) {
    constexpr std::uint64_t kPrime1 = 0x9e3779b185ebca87ull;
    constexpr std::uint64_t kPrime2 = 0xc2b2ae3d27d4eb4full;
    auto round = [](std::uint64_t lane, std::uint64_t word) {
        return std::rotl(lane + word * kPrime2, 31) * kPrime1;
    };
    std::uint64_t lanes[4] = {kPrime1 + kPrime2, kPrime2, 0, 0 - kPrime1};
    std::size_t i = 0;
    for (; i + 32 <= bytes.size(); i += 32) {
        std::uint64_t words[4];
        std::memcpy(words, bytes.data() + i, 32);
        for (int k = 0; k < 4; ++k)
            lanes[k] = round(lanes[k], words[k]);
    }
    std::uint64_t hash = std::rotl(lanes[0], 1) + std::rotl(lanes[1], 7) + std::rotl(lanes[2], 12) +
                         std::rotl(lanes[3], 18) + bytes.size();
    for (; i < bytes.size(); ++i)
        hash = std::rotl(hash ^ (std::uint64_t(bytes[i]) * kPrime1), 11) * kPrime2;
    hash ^= hash >> 33;
    hash *= kPrime2;
    return hash ^ (hash >> 29);
}

template <typename T> std::uint64_t hashValues(std::span<const T> values) {
    return hashBytes(std::as_bytes(values));
}

} // namespace vkpt
