// early_pipelines.cpp — pipelines created ahead of the scene's upload (early_pipelines.h).
#include "render/early_pipelines.h"

namespace vkpt {

namespace {

// The same SPIR-V and specialisation for every kernel: the kernels' features and the build
// each picks (kernelSpirv reads the features' instancing and BSDF switches).
bool sameKernels(const SceneFeatures& a, const SceneFeatures& b, KernelBuilds builds) {
    if (a.kernelFeatures() != b.kernelFeatures()) return false;
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        const auto kernel = static_cast<WavefrontKernel>(i);
        if (kernelSpirv(kernel, a, builds).data() != kernelSpirv(kernel, b, builds).data())
            return false;
    }
    return true;
}

} // namespace

EarlyPipelines::EarlyPipelines(const GpuContext& context, const SceneFeatures& features,
                               KernelBuilds builds)
    : features_(features), builds_(builds) {
    kernels_ = std::async(std::launch::async, [&context, features, builds] {
        return createWavefrontKernels(context, features, {}, builds);
    });
}

EarlyPipelines::~EarlyPipelines() {
    if (kernels_.valid()) kernels_.wait();
}

std::optional<WavefrontKernelSet>
EarlyPipelines::take(const SceneFeatures& features,
                     const std::vector<SpecializationConstant>& constants, KernelBuilds builds) {
    // Made with no render constants: no scene array split into chunks.
    if (!kernels_.valid() || builds != builds_ || !constants.empty() ||
        !sameKernels(features, features_, builds))
        return std::nullopt;
    return kernels_.get();
}

} // namespace vkpt
