// wavefront_kernels.h — the wavefront's kernels by name (file ↔ enum ↔ pipeline and dispatch
// label: trace_closest.comp ↔ WavefrontKernel::TraceClosest ↔ "trace_closest"), which buffers
// each one binds, and their pipelines.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "common/device_stats.h"
#include "gpu/descriptor_set.h"
#include "gpu/kernel.h"
#include "lib/wavefront.h"
#include "scene/scene_features.h"

namespace vkpt {

class Buffer;
class GpuContext;

// In the order a pass runs them.
enum class WavefrontKernel : std::uint32_t {
    GenerateCameraRays,
    PrepareDispatches,
    TraceClosest,
    ShadeHits,
    TraceShadow,
    AddLightSamples,
    Accumulate,
};
inline constexpr std::size_t kWavefrontKernelCount = 7;

std::string_view kernelName(WavefrontKernel kernel);

// The bindings (BINDING_* of lib/wavefront.h) the kernel declares and how it sees each one, from
// its list in lib/kernel_bindings.h.
std::span<const KernelBinding> kernelBindings(WavefrontKernel kernel);

// Which buffer each binding number refers to, or which chunks for a scene array split across
// several (lib/scene_arrays.glsl); a kernel's descriptor set takes its bindings from here.
struct BufferTable {
    std::array<std::vector<const Buffer*>, BINDING_COUNT> buffers{};
    std::array<std::uint32_t, BINDING_COUNT> chunkLog2{}; // elements per chunk, log2

    void set(std::uint32_t binding, const Buffer& buffer) { buffers.at(binding) = {&buffer}; }
    void setChunks(std::uint32_t binding, const std::vector<Buffer>& chunks,
                   std::uint32_t elementsLog2);
};

// The FEATURE_* specialisation constants (lib/features.glsl) for `features`.
std::vector<SpecializationConstant> featureConstants(const SceneFeatures& features);

// The SPEC_SCENE_ARRAY_* constants (lib/scene_arrays.glsl) of the bindings of `table` that have
// more than one chunk; none when every array fits one binding.
std::vector<SpecializationConstant> chunkConstants(const BufferTable& table);

// Whether the kernel's code depends on the scene's features (it includes lib/features.glsl).
bool isSpecialised(WavefrontKernel kernel);

// Which of a kernel's builds a pipeline takes: one made for the scene's feature set where there
// is one (shade_hits without the layered BSDF for Lambertian scenes; shaders/CMakeLists.txt),
// its constants folded into the module on the host (gpu/spirv_specialise.h); or, for
// comparison, the build with every feature's code as glslang wrote it, specialised by the
// driver: what the folded forms must render bit for bit.
enum class KernelBuilds { ForFeatureSet, Full };

// The SPIR-V the kernel's pipeline is made from: the build for the scene's layout (one or two
// levels) and, with KernelBuilds::ForFeatureSet, its feature set.
std::span<const std::uint32_t> kernelSpirv(WavefrontKernel kernel, const SceneFeatures& features,
                                           KernelBuilds builds = KernelBuilds::ForFeatureSet);

// The pipeline of one kernel, with the PassParams push constants, specialised for `features`
// (what the scene uses, or generalFeatures for the --general pipelines) and for the render:
// how the scene's arrays are split (chunkConstants); empty: no array is split. Whether the
// render records AOVs is a push constant (lib/aovs.glsl): both kinds of render share the
// pipelines.
KernelDesc wavefrontKernelDesc(WavefrontKernel kernel, const SceneFeatures& features,
                               const std::vector<SpecializationConstant>& renderConstants = {},
                               KernelBuilds builds = KernelBuilds::ForFeatureSet);
Kernel makeWavefrontKernel(const GpuContext& context, WavefrontKernel kernel,
                           const SceneFeatures& features,
                           const std::vector<SpecializationConstant>& renderConstants = {},
                           KernelBuilds builds = KernelBuilds::ForFeatureSet);

// A descriptor set for `kernel` with each of its bindings pointing into `table`.
DescriptorSet bindWavefrontKernel(const Kernel& kernel, WavefrontKernel id,
                                  const BufferTable& table);

// Every kernel's pipeline, in WavefrontKernel order: those an earlier render on the device made
// are taken from its memo (gpu/kernel_memo.h), the others created on one thread per core and
// kept there for the next render.
struct WavefrontKernelSet {
    std::vector<std::shared_ptr<const Kernel>> kernels;
    std::vector<bool> created; // made by this call, else taken from the memo
};
WavefrontKernelSet createWavefrontKernels(const GpuContext& context, const SceneFeatures& features,
                                          const std::vector<SpecializationConstant>& constants,
                                          KernelBuilds builds);

class EarlyPipelines;

// Every kernel's pipeline and descriptor set, created together — or taken from `early`, when
// it made them for the same features and constants.
class WavefrontPipelines {
public:
    WavefrontPipelines(const GpuContext& context, const BufferTable& table,
                       const SceneFeatures& features, KernelBuilds builds,
                       EarlyPipelines* early = nullptr);

    const Kernel& kernel(WavefrontKernel id) const { return *kernels_.kernels[index(id)]; }
    const DescriptorSet& set(WavefrontKernel id) const { return sets_[index(id)]; }
    // Wall seconds from the first pipeline's creation to the last's: what the render waited for
    // (they are created in parallel, so less than Σ Kernel::creationTime()); with pipelines
    // created early, the wait for them, if any.
    double creationSeconds() const;
    bool createdEarly() const { return createdEarly_; }
    // Each kernel's SPIR-V size and creation time, in dispatch order; 0 s for a pipeline an
    // earlier render on the device made.
    std::vector<PipelineCreation> creations() const;

private:
    static std::size_t index(WavefrontKernel id) { return static_cast<std::size_t>(id); }

    WavefrontKernelSet kernels_;
    std::vector<std::uint64_t> spirvBytes_;
    double wallSeconds_ = 0.0;
    bool createdEarly_ = false;
    std::vector<DescriptorSet> sets_;
};

} // namespace vkpt
