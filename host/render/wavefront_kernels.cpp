// wavefront_kernels.cpp — the kernel table: names, bindings, pipelines and descriptor sets.
#include "render/wavefront_kernels.h"

#include <chrono>
#include <string>

#include "common/errors.h"
#include "lib/kernel_bindings.h"
#include "lib/wavefront.h"
#include "render/scene_arrays.h"
#include "vkpt_instanced_kernels.h"
#include "vkpt_kernels.h"

namespace vkpt {

static_assert(kWavefrontBindingCount == BINDING_COUNT);

namespace {

struct KernelInfo {
    std::string_view name;
    std::vector<KernelBinding> bindings;
    bool specialised = false; // includes lib/features.glsl
};

// The entries of a lib/kernel_bindings.h list as KernelBindings, in the list's order.
#define VKPT_UNIFORM_BINDING(binding) {binding, DescriptorKind::UniformBuffer},
// A splittable scene array is a descriptor array (lib/scene_arrays.glsl): a SCENE storage entry,
// or a texel entry of the scene array list.
#define VKPT_TEXEL_BINDING(binding)                                                                \
    {binding, DescriptorKind::UniformTexelBuffer,                                                  \
     isSplittableSceneBinding(binding) ? SCENE_ARRAY_MAX_CHUNKS : 1u},
#define VKPT_DESCRIPTORS_READ 1u
#define VKPT_DESCRIPTORS_WRITE 1u
#define VKPT_DESCRIPTORS_READ_WRITE 1u
#define VKPT_DESCRIPTORS_SCENE SCENE_ARRAY_MAX_CHUNKS
#define VKPT_STORAGE_BINDING(binding, access, Type, name)                                          \
    {binding, DescriptorKind::StorageBuffer, VKPT_DESCRIPTORS_##access},
#define VKPT_KERNEL_BINDINGS(LIST)                                                                 \
    std::vector<KernelBinding> {                                                                   \
        LIST(VKPT_UNIFORM_BINDING, VKPT_TEXEL_BINDING, VKPT_STORAGE_BINDING)                       \
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
    for (std::uint32_t binding = 0; binding < kWavefrontBindingCount; ++binding) {
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

// The kernel's SPIR-V: its two-level build where the scene has instances and instancing changes
// the kernel, else the one-level build.
std::span<const std::uint32_t> kernelSpirv(WavefrontKernel kernel, const SceneFeatures& features) {
    const std::string_view name = kernelName(kernel);
    if (features.instances)
        for (const instanced_kernels::EmbeddedKernel& embedded :
             instanced_kernels::embeddedKernels())
            if (embedded.name == name) return embedded.spirv;
    return kernels::findKernel(name).spirv;
}

Kernel makeWavefrontKernel(const GpuContext& context, WavefrontKernel kernel,
                           const SceneFeatures& features,
                           const std::vector<SpecializationConstant>& chunks) {
    KernelDesc desc;
    desc.name = std::string(kernelName(kernel));
    desc.spirv = kernelSpirv(kernel, features);
    desc.bindings = info(kernel).bindings;
    desc.pushConstantSize = sizeof(gpu::PassParams);
    if (isSpecialised(kernel)) desc.specializationConstants = featureConstants(features);
    desc.specializationConstants.insert(desc.specializationConstants.end(), chunks.begin(),
                                        chunks.end());
    return Kernel(context, std::move(desc));
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

WavefrontPipelines::WavefrontPipelines(const GpuContext& context, const BufferTable& table,
                                       const SceneFeatures& features) {
    kernels_.reserve(kWavefrontKernelCount);
    sets_.reserve(kWavefrontKernelCount);
    const std::vector<SpecializationConstant> chunks = chunkConstants(table);
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        const auto id = static_cast<WavefrontKernel>(i);
        kernels_.push_back(makeWavefrontKernel(context, id, features, chunks));
        sets_.push_back(bindWavefrontKernel(kernels_.back(), id, table));
    }
}

double WavefrontPipelines::creationSeconds() const {
    std::chrono::nanoseconds total{0};
    for (const Kernel& kernel : kernels_)
        total += kernel.creationTime();
    return std::chrono::duration<double>(total).count();
}

} // namespace vkpt
