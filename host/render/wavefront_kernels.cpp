// wavefront_kernels.cpp — the kernel table: names, bindings, pipelines and descriptor sets.
#include "render/wavefront_kernels.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <optional>
#include <string>
#include <thread>

#include "common/errors.h"
#include "gpu/context.h"
#include "lib/kernel_bindings.h"
#include "lib/wavefront.h"
#include "render/early_pipelines.h"
#include "render/scene_arrays.h"
#include "vkpt_diffuse_kernels.h"
#include "vkpt_instanced_diffuse_kernels.h"
#include "vkpt_instanced_kernels.h"
#include "vkpt_kernels.h"

namespace vkpt {

namespace {

struct KernelInfo {
    std::string_view name;
    std::vector<KernelBinding> bindings;
    bool specialised = false; // includes lib/features.glsl
};

// The entries of a lib/kernel_bindings.h list as KernelBindings, in the list's order. A scene
// array's descriptor comes from its row of shared/scene_array_table.h (sceneKernelBinding).
#define VKPT_UNIFORM_BINDING(binding) {binding, DescriptorKind::UniformBuffer},
#define VKPT_SCENE_BINDING(binding) sceneKernelBinding(binding),
#define VKPT_TEXEL_BINDING(binding) {binding, DescriptorKind::UniformTexelBuffer},
#define VKPT_STORAGE_BINDING(binding, access, Type, name) {binding, DescriptorKind::StorageBuffer},
#define VKPT_KERNEL_BINDINGS(LIST)                                                                 \
    std::vector<KernelBinding> {                                                                   \
        LIST(VKPT_UNIFORM_BINDING, VKPT_SCENE_BINDING, VKPT_TEXEL_BINDING, VKPT_STORAGE_BINDING)   \
    }

const std::array<KernelInfo, kWavefrontKernelCount>& kernelTable() {
    static const std::array<KernelInfo, kWavefrontKernelCount> table = {{
        {kernels::kGenerateCameraRaysName, VKPT_KERNEL_BINDINGS(GENERATE_CAMERA_RAYS_BINDINGS),
         true},
        {kernels::kPrepareDispatchesName, VKPT_KERNEL_BINDINGS(PREPARE_DISPATCHES_BINDINGS)},
        {kernels::kTraceClosestName, VKPT_KERNEL_BINDINGS(TRACE_CLOSEST_BINDINGS), true},
        {kernels::kShadeHitsName, VKPT_KERNEL_BINDINGS(SHADE_HITS_BINDINGS), true},
        {kernels::kTraceShadowName, VKPT_KERNEL_BINDINGS(TRACE_SHADOW_BINDINGS), true},
        {kernels::kAddLightSamplesName, VKPT_KERNEL_BINDINGS(ADD_LIGHT_SAMPLES_BINDINGS)},
        {kernels::kAccumulateName, VKPT_KERNEL_BINDINGS(ACCUMULATE_BINDINGS)},
    }};
    return table;
}

const KernelInfo& info(WavefrontKernel kernel) {
    return kernelTable().at(static_cast<std::size_t>(kernel));
}

} // namespace

std::string_view kernelName(WavefrontKernel kernel) {
    return info(kernel).name;
}

std::span<const KernelBinding> kernelBindings(WavefrontKernel kernel) {
    return info(kernel).bindings;
}

std::vector<SpecializationConstant> featureConstants(const SceneFeatures& features) {
    const std::array<bool, FEATURE_COUNT> values = features.kernelFeatures();
    std::vector<SpecializationConstant> constants;
    for (std::uint32_t id = 0; id < FEATURE_COUNT; ++id)
        constants.push_back(specializeBool(id, values[id]));
    return constants;
}

void BufferTable::setChunks(std::uint32_t binding, const std::vector<Buffer>& chunks,
                            std::uint32_t elementsLog2) {
    std::vector<const Buffer*>& entry = buffers.at(binding);
    entry.clear();
    for (const Buffer& chunk : chunks)
        entry.push_back(&chunk);
    chunkLog2.at(binding) = elementsLog2;
}

std::vector<SpecializationConstant> chunkConstants(const BufferTable& table) {
    std::vector<SpecializationConstant> constants;
    for (std::uint32_t binding = 0; binding < BINDING_COUNT; ++binding) {
        const auto chunks = static_cast<std::uint32_t>(table.buffers[binding].size());
        if (chunks <= 1) continue;
        constants.push_back({SPEC_SCENE_ARRAY_CHUNKS(binding), chunks});
        constants.push_back({SPEC_SCENE_ARRAY_CHUNK_LOG2(binding), table.chunkLog2[binding]});
    }
    return constants;
}

bool isSpecialised(WavefrontKernel kernel) {
    return info(kernel).specialised;
}

namespace {

// The layered BSDF's features: a scene with none of them shades with the Lambertian BSDF alone.
bool needsLayeredBsdf(const SceneFeatures& features) {
    const std::array<bool, FEATURE_COUNT> on = features.kernelFeatures();
    return on[FEATURE_METALLIC_ROUGHNESS] || on[FEATURE_TRANSMISSION] || on[FEATURE_CLEARCOAT] ||
           on[FEATURE_SHEEN];
}

// The kernel's build in one embedded library, if that library has one.
template <typename Library>
std::optional<std::span<const std::uint32_t>> findIn(const Library& kernels,
                                                     std::string_view name) {
    for (const auto& embedded : kernels)
        if (embedded.name == name) return embedded.spirv;
    return std::nullopt;
}

} // namespace

// A two-level scene takes the builds with the instancing code where instancing changes the
// kernel; a Lambertian scene the diffuse build of shade_hits, for its layout.
std::span<const std::uint32_t> kernelSpirv(WavefrontKernel kernel, const SceneFeatures& features,
                                           KernelBuilds builds) {
    const std::string_view name = kernelName(kernel);
    if (builds == KernelBuilds::ForFeatureSet && !needsLayeredBsdf(features)) {
        const auto diffuse = features.instances
                                 ? findIn(instanced_diffuse_kernels::embeddedKernels(), name)
                                 : findIn(diffuse_kernels::embeddedKernels(), name);
        if (diffuse) return *diffuse;
    }
    if (features.instances)
        if (const auto instanced = findIn(instanced_kernels::embeddedKernels(), name))
            return *instanced;
    return kernels::findKernel(name).spirv;
}

KernelDesc wavefrontKernelDesc(WavefrontKernel kernel, const SceneFeatures& features,
                               const std::vector<SpecializationConstant>& renderConstants,
                               KernelBuilds builds) {
    KernelDesc desc;
    desc.name = std::string(kernelName(kernel));
    desc.spirv = kernelSpirv(kernel, features, builds);
    desc.bindings = info(kernel).bindings;
    desc.pushConstantSize = sizeof(gpu::PassParams);
    desc.foldConstantsOnHost = builds == KernelBuilds::ForFeatureSet;
    if (isSpecialised(kernel)) desc.specializationConstants = featureConstants(features);
    // A constant the kernel does not declare is ignored by the driver (Vulkan spec,
    // VkSpecializationMapEntry), so every kernel gets the same render constants.
    desc.specializationConstants.insert(desc.specializationConstants.end(), renderConstants.begin(),
                                        renderConstants.end());
    return desc;
}

Kernel makeWavefrontKernel(const GpuContext& context, WavefrontKernel kernel,
                           const SceneFeatures& features,
                           const std::vector<SpecializationConstant>& renderConstants,
                           KernelBuilds builds) {
    return Kernel(context, wavefrontKernelDesc(kernel, features, renderConstants, builds));
}

DescriptorSet bindWavefrontKernel(const Kernel& kernel, WavefrontKernel id,
                                  const BufferTable& table) {
    std::vector<BufferBinding> bindings;
    for (const KernelBinding& declared : kernelBindings(id)) {
        const std::vector<const Buffer*>& buffers = table.buffers.at(declared.binding);
        VKPT_ASSERT(!buffers.empty(), "kernel '" + std::string(kernelName(id)) +
                                          "' needs binding " + std::to_string(declared.binding));
        bindings.push_back({declared.binding, buffers.front(), buffers});
    }
    return DescriptorSet(kernel, bindings);
}

namespace {

// Creates the pipelines of `descs` on up to `threads` threads, the largest modules first, so
// that the longest compile (shade_hits) starts at once and the others fill the other cores:
// the wait is about the longest compile instead of the sum. vkCreateComputePipelines may be
// called from several threads at once, and a pipeline cache created without
// VK_PIPELINE_CACHE_CREATE_EXTERNALLY_SYNCHRONIZED_BIT synchronises itself (Vulkan's threading
// rules).
std::vector<Kernel> createKernelsInParallel(const GpuContext& context,
                                            const std::vector<KernelDesc>& descs,
                                            unsigned threads) {
    std::vector<std::size_t> order(descs.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return descs[a].spirv.size() > descs[b].spirv.size();
    });
    std::vector<std::optional<Kernel>> made(descs.size());
    std::vector<std::exception_ptr> errors(descs.size());
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t k = next++; k < order.size(); k = next++) {
            const std::size_t i = order[k];
            try {
                made[i].emplace(context, descs[i]);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    };
    std::vector<std::thread> workers;
    for (unsigned t = 1; t < std::min<std::size_t>(threads, order.size()); ++t)
        workers.emplace_back(work);
    work();
    for (std::thread& worker : workers)
        worker.join();
    std::vector<Kernel> kernels;
    kernels.reserve(descs.size());
    for (std::size_t i = 0; i < descs.size(); ++i) {
        if (errors[i]) std::rethrow_exception(errors[i]);
        kernels.push_back(std::move(*made[i]));
    }
    return kernels;
}

} // namespace

WavefrontKernelSet createWavefrontKernels(const GpuContext& context, const SceneFeatures& features,
                                          const std::vector<SpecializationConstant>& constants,
                                          KernelBuilds builds) {
    WavefrontKernelSet set;
    set.kernels.resize(kWavefrontKernelCount);
    set.created.assign(kWavefrontKernelCount, false);
    std::vector<std::size_t> missing;
    std::vector<KernelDesc> descs;
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        KernelDesc desc =
            wavefrontKernelDesc(static_cast<WavefrontKernel>(i), features, constants, builds);
        set.kernels[i] = context.kernelMemo().find(desc);
        if (set.kernels[i]) continue;
        missing.push_back(i);
        descs.push_back(std::move(desc));
    }
    std::vector<Kernel> made =
        createKernelsInParallel(context, descs, std::max(1u, std::thread::hardware_concurrency()));
    for (std::size_t k = 0; k < missing.size(); ++k) {
        set.kernels[missing[k]] = context.kernelMemo().keep(std::move(made[k]));
        set.created[missing[k]] = true;
    }
    return set;
}

// The render constants are the chunked arrays' (chunkConstants): none for a scene with no
// chunked array, as EarlyPipelines makes them.
WavefrontPipelines::WavefrontPipelines(const GpuContext& context, const BufferTable& table,
                                       const SceneFeatures& features, KernelBuilds builds,
                                       EarlyPipelines* early) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<SpecializationConstant> constants = chunkConstants(table);
    std::optional<WavefrontKernelSet> made =
        early ? early->take(features, constants, builds) : std::nullopt;
    createdEarly_ = made.has_value();
    kernels_ =
        made ? std::move(*made) : createWavefrontKernels(context, features, constants, builds);
    wallSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // At once, so that a render stopped later still leaves its compiles for the next one.
    context.pipelineCache().save();
    sets_.reserve(kWavefrontKernelCount);
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        const auto id = static_cast<WavefrontKernel>(i);
        spirvBytes_.push_back(kernelSpirv(id, features, builds).size_bytes());
        sets_.push_back(bindWavefrontKernel(kernel(id), id, table));
    }
}

std::vector<PipelineCreation> WavefrontPipelines::creations() const {
    std::vector<PipelineCreation> result;
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        const double seconds =
            kernels_.created[i]
                ? std::chrono::duration<double>(kernels_.kernels[i]->creationTime()).count()
                : 0.0;
        result.push_back(
            {std::string(kernelName(static_cast<WavefrontKernel>(i))), spirvBytes_[i], seconds});
    }
    return result;
}

double WavefrontPipelines::creationSeconds() const {
    return wallSeconds_;
}

} // namespace vkpt
