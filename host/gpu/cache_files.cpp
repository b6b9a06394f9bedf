// cache_files.cpp — the cache folder, FNV-1a, and atomic writes (temporary file, then rename).
#include "gpu/cache_files.h"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace vkpt {

std::filesystem::path vkptCacheFolder() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "vkpt";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "vkpt";
    return {};
}

bool cacheFilesDisabledByEnvironment() {
    const char* value = std::getenv("VKPT_NO_PIPELINE_CACHE");
    return value && *value && std::strcmp(value, "0") != 0;
}

std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash) {
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < size; ++i)
        hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    return hash;
}

std::vector<std::uint8_t> readWholeFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool writeFileAtomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    // The process and a count make the temporary name unique: threads of one process may
    // write files of one folder at once.
    static std::atomic<unsigned> written{0};
    const std::filesystem::path temporary = path.string() + ".tmp" +
                                            std::to_string(static_cast<long>(getpid())) + "." +
                                            std::to_string(written.fetch_add(1));
    std::error_code error;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), error);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        if (!out) error = std::make_error_code(std::errc::io_error);
    }
    if (!error) std::filesystem::rename(temporary, path, error);
    if (!error) return true;
    std::filesystem::remove(temporary, error);
    return false;
}

} // namespace vkpt
