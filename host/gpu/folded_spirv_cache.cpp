// folded_spirv_cache.cpp — the file: "vkptfk01", the second source hash (u64), the source module's
// words (u32), the constants (u32 count, then id and value each), the folded module's words
// (u32) and FNV-1a 64 of its bytes (u64), then the folded module.
#include "gpu/folded_spirv_cache.h"

#include "gpu/cache_files.h"
#include "gpu/spirv_specialise.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace vkpt {

namespace {

constexpr char kFoldedMagic[8] = {'v', 'k', 'p', 't', 'f', 'k', '0', '1'};
constexpr std::uint32_t kSpirvMagicNumber = 0x07230203;
// A second hash of the same bytes from another starting point: a file must match both.
constexpr std::uint64_t kSecondBasis = kFnvOffsetBasis ^ 0x9e3779b97f4a7c15ull;

std::uint64_t foldedSourceHash(const KernelDesc& desc, std::uint64_t basis) {
    const std::string passes = specialiseSpirvVersion();
    std::uint64_t hash = fnv1a(passes.data(), passes.size(), basis);
    hash = fnv1a(desc.spirv.data(), desc.spirv.size_bytes(), hash);
    for (const SpecializationConstant& constant : desc.specializationConstants) {
        hash = fnv1a(&constant.id, sizeof(constant.id), hash);
        hash = fnv1a(&constant.value, sizeof(constant.value), hash);
    }
    return hash;
}

// Appends `value`'s bytes.
template <typename T> void putBytes(std::vector<std::uint8_t>& out, const T& value) {
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(&value);
    out.insert(out.end(), bytes, bytes + sizeof(T));
}

// Reads the next value; false past the end.
class FoldedFileReader {
public:
    explicit FoldedFileReader(const std::vector<std::uint8_t>& bytes) : bytes_(bytes) {}
    template <typename T> bool get(T& value) {
        if (bytes_.size() - offset_ < sizeof(T)) return false;
        std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
        offset_ += sizeof(T);
        return true;
    }
    std::size_t left() const { return bytes_.size() - offset_; }
    const std::uint8_t* here() const { return bytes_.data() + offset_; }

private:
    const std::vector<std::uint8_t>& bytes_;
    std::size_t offset_ = 0;
};

std::vector<std::uint8_t> encodeFoldedFile(const KernelDesc& desc,
                                           const std::vector<std::uint32_t>& folded) {
    std::vector<std::uint8_t> out(std::begin(kFoldedMagic), std::end(kFoldedMagic));
    putBytes(out, foldedSourceHash(desc, kSecondBasis));
    putBytes(out, std::uint32_t(desc.spirv.size()));
    putBytes(out, std::uint32_t(desc.specializationConstants.size()));
    for (const SpecializationConstant& constant : desc.specializationConstants) {
        putBytes(out, constant.id);
        putBytes(out, constant.value);
    }
    putBytes(out, std::uint32_t(folded.size()));
    putBytes(out, fnv1a(folded.data(), folded.size() * sizeof(std::uint32_t)));
    const auto* words = reinterpret_cast<const std::uint8_t*>(folded.data());
    out.insert(out.end(), words, words + folded.size() * sizeof(std::uint32_t));
    return out;
}

// The folded module the file holds for `desc`; empty when it holds anything else.
std::vector<std::uint32_t> decodeFoldedFile(const std::vector<std::uint8_t>& file,
                                            const KernelDesc& desc) {
    FoldedFileReader in(file);
    char magic[sizeof(kFoldedMagic)];
    std::uint64_t hash = 0;
    std::uint32_t sourceWords = 0, constants = 0;
    for (char& c : magic)
        if (!in.get(c)) return {};
    if (std::memcmp(magic, kFoldedMagic, sizeof(kFoldedMagic)) != 0 || !in.get(hash) ||
        hash != foldedSourceHash(desc, kSecondBasis) || !in.get(sourceWords) ||
        sourceWords != desc.spirv.size() || !in.get(constants) ||
        constants != desc.specializationConstants.size())
        return {};
    for (const SpecializationConstant& constant : desc.specializationConstants) {
        SpecializationConstant stored;
        if (!in.get(stored.id) || !in.get(stored.value) || stored.id != constant.id ||
            stored.value != constant.value)
            return {};
    }
    std::uint32_t foldedWords = 0;
    std::uint64_t checksum = 0;
    if (!in.get(foldedWords) || !in.get(checksum) ||
        in.left() != std::size_t(foldedWords) * sizeof(std::uint32_t) || foldedWords < 5 ||
        fnv1a(in.here(), in.left()) != checksum)
        return {};
    std::vector<std::uint32_t> folded(foldedWords);
    std::memcpy(folded.data(), in.here(), in.left());
    if (folded.front() != kSpirvMagicNumber) return {};
    return folded;
}

} // namespace

std::filesystem::path FoldedSpirvCache::fileFor(const KernelDesc& desc) const {
    char hash[17];
    std::snprintf(hash, sizeof(hash), "%016llx",
                  static_cast<unsigned long long>(foldedSourceHash(desc, kFnvOffsetBasis)));
    return folder_ / (desc.name + "-" + hash + ".spv");
}

std::vector<std::uint32_t> FoldedSpirvCache::fold(const KernelDesc& desc) const {
    if (folder_.empty()) return specialiseSpirv(desc);
    const std::filesystem::path file = fileFor(desc);
    std::vector<std::uint32_t> folded = decodeFoldedFile(readWholeFile(file), desc);
    if (!folded.empty()) return folded;
    folded = specialiseSpirv(desc);
    writeFileAtomically(file, encodeFoldedFile(desc, folded));
    return folded;
}

std::filesystem::path foldedSpirvCacheFolder(bool persistentPipelineCache,
                                             const std::string& pipelineCachePath) {
    if (const char* folder = std::getenv("VKPT_KERNEL_CACHE_DIR"); folder && *folder) return folder;
    if (!persistentPipelineCache) return {};
    if (!pipelineCachePath.empty())
        return std::filesystem::path(pipelineCachePath).parent_path() / "kernels";
    if (cacheFilesDisabledByEnvironment()) return {};
    const std::filesystem::path folder = vkptCacheFolder();
    return folder.empty() ? folder : folder / "kernels";
}

} // namespace vkpt
