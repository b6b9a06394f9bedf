// folded_spirv_cache.h — kernels folded for their constants (spirv_specialise.h), kept in files,
// so that a later start with the same kernel and constants reads the folded module instead of
// folding it again: SPIRV-Tools takes 30-250 ms of a thread per kernel, shade_hits the most,
// which on a device whose driver cache (pipeline_cache.h) already holds the pipelines is most
// of what creating them costs. Processes may share a folder; each file is written whole.
//
// A file is named after the kernel and a hash of what it was folded from (the passes and
// SPIRV-Tools' version, the module, the constants), and holds the constants in full, the module's
// length, a second hash of all of it and a checksum of the folded module: a file that does not
// match in every one is a miss, folded again and written over, never a wrong module.
#pragma once

#include "gpu/kernel.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace vkpt {

class FoldedSpirvCache {
public:
    // No files when `folder` is empty: every kernel is folded.
    explicit FoldedSpirvCache(std::filesystem::path folder) : folder_(std::move(folder)) {}

    // specialiseSpirv(desc): from the folder when a file there matches, else folded now and
    // written there (a failed write is not an error: the next start folds again).
    std::vector<std::uint32_t> fold(const KernelDesc& desc) const;

    const std::filesystem::path& folder() const { return folder_; }
    // The file that holds, or would hold, desc folded.
    std::filesystem::path fileFor(const KernelDesc& desc) const;

private:
    std::filesystem::path folder_;
};

// Where a context keeps folded kernels: $VKPT_KERNEL_CACHE_DIR when set (ci/test.sh gives each
// suite run one folder, shared by its processes); else, for a context with a persistent pipeline
// cache, a folder "kernels" beside its file (`pipelineCachePath`, or the default one, which
// VKPT_NO_PIPELINE_CACHE turns off); else none.
std::filesystem::path foldedSpirvCacheFolder(bool persistentPipelineCache,
                                             const std::string& pipelineCachePath);

} // namespace vkpt
