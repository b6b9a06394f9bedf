// reference_cache.cpp — reference images cached between trade-study runs.
#include "study/reference_cache.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.h"
#include "image/image_io.h"

namespace vkpt {

namespace {

namespace fs = std::filesystem;

// FNV-1a, 64 bits: enough to tell scenes and settings apart, not a security measure.
struct Fnv1a {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    void add(const void* data, std::size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i)
            hash = (hash ^ bytes[i]) * 0x100000001b3ull;
    }
    void add(const std::string& text) { add(text.data(), text.size()); }
};

std::string settingsKey(const RenderSettings& s) {
    std::ostringstream key;
    key << "v" << kReferenceCacheVersion << " " << s.width << "x" << s.height << " spp "
        << s.samplesPerPixel << " seed " << s.seed << " depth " << s.maxDepth << " rr "
        << s.rrStartDepth << " integrator " << int(s.integrator) << " sampling "
        << int(s.lightSampling) << " lights " << s.lightSamples << " filter " << int(s.pathFilter)
        << " camera " << (s.cameraIndex ? *s.cameraIndex : -1);
    if (s.clamp != 0.0f) key << " clamp " << s.clamp; // absent when off: older keys stay valid
    return key.str();
}

void hashFile(Fnv1a& fnv, const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot read the scene file");
    char buffer[1 << 16];
    while (in.read(buffer, sizeof(buffer)) || in.gcount() > 0)
        fnv.add(buffer, std::size_t(in.gcount()));
}

std::string descriptionPath(const std::string& pfmPath) {
    return fs::path(pfmPath).replace_extension(".txt").string();
}

void writeDescription(const std::string& path, const ReferenceInfo& info) {
    std::ofstream out(path);
    out << "renderer " << info.renderer << "\nspp " << info.spp << "\nmaxDepth " << info.maxDepth
        << "\nseconds " << info.seconds << "\nestimatedRelMse " << info.estimatedRelMse << "\n";
    if (!out) throw InputError(path + ": cannot write");
}

bool readDescription(const std::string& path, ReferenceInfo& info) {
    std::ifstream in(path);
    std::string line;
    int found = 0;
    while (std::getline(in, line)) {
        const std::size_t space = line.find(' ');
        if (space == std::string::npos) continue;
        const std::string name = line.substr(0, space), value = line.substr(space + 1);
        std::istringstream v(value);
        if (name == "renderer") info.renderer = value, ++found;
        if (name == "spp") v >> info.spp, ++found;
        if (name == "maxDepth") v >> info.maxDepth, ++found;
        if (name == "seconds") v >> info.seconds, ++found;
        if (name == "estimatedRelMse") v >> info.estimatedRelMse, ++found;
    }
    return found == 5;
}

} // namespace

std::string defaultCacheDirectory() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return (fs::path(xdg) / "vkpt").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (fs::path(home) / ".cache" / "vkpt").string();
    throw InputError("neither XDG_CACHE_HOME nor HOME is set: give the cache with --cache DIR");
}

std::string referenceCachePath(const std::string& directory, const RenderSettings& settings,
                               StudyReference kind) {
    Fnv1a fnv;
    hashFile(fnv, settings.scenePath);
    fnv.add(settingsKey(settings));
    char name[256];
    std::snprintf(name, sizeof(name), "%s-%ux%u-%s-%uspp-%016llx.pfm",
                  fs::path(settings.scenePath).stem().string().c_str(), settings.width,
                  settings.height, referenceName(kind), settings.samplesPerPixel,
                  (unsigned long long)fnv.hash);
    return (fs::path(directory) / "references" / name).string();
}

std::optional<CachedReference> readCachedReference(const std::string& pfmPath) {
    std::error_code error;
    if (!fs::exists(pfmPath, error) || !fs::exists(descriptionPath(pfmPath), error))
        return std::nullopt;
    CachedReference cached;
    if (!readDescription(descriptionPath(pfmPath), cached.info)) return std::nullopt;
    try {
        cached.image = readPfm(pfmPath);
    } catch (const InputError&) {
        return std::nullopt; // a damaged cache entry is made again
    }
    cached.info.cached = true;
    cached.info.path = pfmPath;
    return cached;
}

void writeCachedReference(const std::string& pfmPath, const Image& image,
                          const ReferenceInfo& info) {
    fs::create_directories(fs::path(pfmPath).parent_path());
    const std::string temporaryPfm = pfmPath + ".partial.pfm";
    const std::string description = descriptionPath(pfmPath);
    writePfm(image, temporaryPfm);
    writeDescription(description + ".partial", info);
    fs::rename(temporaryPfm, pfmPath);
    fs::rename(description + ".partial", description);
}

} // namespace vkpt
