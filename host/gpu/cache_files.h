// cache_files.h — what vkpt's cache files share: the folder they live in, their checksum, and a
// write that a reader in another process never sees half done.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace vkpt {

// $XDG_CACHE_HOME/vkpt, else ~/.cache/vkpt; empty when neither variable is set.
std::filesystem::path vkptCacheFolder();

// Whether VKPT_NO_PIPELINE_CACHE is set to anything but 0: no cache files in vkptCacheFolder().
bool cacheFilesDisabledByEnvironment();

// FNV-1a, 64 bits, over `size` bytes, continuing from `hash` (the offset basis to start afresh).
inline constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ull;
std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = kFnvOffsetBasis);

// The whole file; empty when it cannot be read.
std::vector<std::uint8_t> readWholeFile(const std::filesystem::path& path);

// Writes `bytes` to a temporary file beside `path`, then renames it over `path`, making the
// folder when it is missing; false when any step fails (the temporary file is removed).
bool writeFileAtomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

} // namespace vkpt
