// early_pipelines.h — the wavefront kernels' pipelines created on worker threads while the host
// still builds the BVH and uploads the scene, so that the driver's compiles overlap that work
// instead of following it (they need the scene's features alone, known once it is loaded).
#pragma once

#include <future>
#include <optional>
#include <vector>

#include "gpu/kernel.h"
#include "render/wavefront_kernels.h"
#include "scene/scene_features.h"

namespace vkpt {

class GpuContext;

class EarlyPipelines {
public:
    // Starts at once. The kernels are specialised for `features` and no scene array split into
    // chunks, which holds for every scene whose arrays each fit one binding; they serve renders
    // with AOVs and without alike.
    EarlyPipelines(const GpuContext& context, const SceneFeatures& features, KernelBuilds builds);
    // Waits for the workers; what they made stays in the device's memo, taken or not.
    ~EarlyPipelines();
    EarlyPipelines(const EarlyPipelines&) = delete;
    EarlyPipelines& operator=(const EarlyPipelines&) = delete;

    // The kernels, when they were made for these very inputs (after waiting for the workers;
    // a failed creation is rethrown, as creating them again would fail too). None when the
    // inputs differ — a scene array split into chunks, or features the prepared scene settled
    // otherwise, such as its emitter count — and the caller then creates its own.
    std::optional<WavefrontKernelSet> take(const SceneFeatures& features,
                                           const std::vector<SpecializationConstant>& constants,
                                           KernelBuilds builds);

private:
    SceneFeatures features_;
    KernelBuilds builds_;
    std::future<WavefrontKernelSet> kernels_;
};

} // namespace vkpt
