// wavefront_kernels.cpp — the kernel table: names, bindings, pipelines and descriptor sets.
#include "render/wavefront_kernels.h"

#include <chrono>
#include <string>

#include "common/errors.h"
#include "lib/wavefront.h"
#include "vkpt_kernels.h"

namespace vkpt {

static_assert(kWavefrontBindingCount == BINDING_COUNT);

namespace {

struct KernelInfo {
    std::string_view name;
    std::vector<std::uint32_t> bindings;
    bool specialised = false; // includes lib/features.glsl
};

// Must list exactly the buffers each .comp file declares (a missing one is a validation error).
const std::array<KernelInfo, kWavefrontKernelCount>& kernelTable() {
    static const std::array<KernelInfo, kWavefrontKernelCount> table = {{
        {kernels::kGenerateCameraRaysName,
         {BINDING_FRAME_PARAMS, BINDING_ACTIVE_PIXELS, BINDING_PATH_STATES, BINDING_RAYS,
          BINDING_QUEUE_COUNTERS}},
        {kernels::kPrepareDispatchesName,
         {BINDING_FRAME_PARAMS, BINDING_QUEUE_COUNTERS, BINDING_DISPATCH_ARGS}},
        {kernels::kTraceClosestName,
         {BINDING_FRAME_PARAMS, BINDING_BVH_NODES, BINDING_TRIANGLES, BINDING_TRIANGLE_TEXELS,
          BINDING_TRIANGLE_UVS,
          BINDING_MATERIALS, BINDING_TEXTURES, BINDING_TEXTURE_TEXELS, BINDING_RAYS, BINDING_HITS,
          BINDING_QUEUE_COUNTERS},
         true},
        {kernels::kShadeHitsName,
         {BINDING_FRAME_PARAMS, BINDING_TRIANGLES, BINDING_TRIANGLE_NORMALS, BINDING_TRIANGLE_UVS,
          BINDING_MATERIALS, BINDING_TEXTURES, BINDING_TEXTURE_TEXELS, BINDING_EMITTERS,
          BINDING_EMITTER_CDF, BINDING_ENVIRONMENT_TEXELS, BINDING_ENVIRONMENT_CDF,
          BINDING_PATH_STATES, BINDING_RAYS, BINDING_HITS, BINDING_SHADOW_RAYS,
          BINDING_QUEUE_COUNTERS},
         true},
        {kernels::kTraceShadowName,
         {BINDING_FRAME_PARAMS, BINDING_BVH_NODES, BINDING_TRIANGLES, BINDING_TRIANGLE_TEXELS,
          BINDING_TRIANGLE_UVS,
          BINDING_MATERIALS, BINDING_TEXTURES, BINDING_TEXTURE_TEXELS, BINDING_ENVIRONMENT_TEXELS,
          BINDING_ENVIRONMENT_CDF, BINDING_SHADOW_RAYS, BINDING_QUEUE_COUNTERS},
         true},
        {kernels::kAddLightSamplesName,
         {BINDING_FRAME_PARAMS, BINDING_PATH_STATES, BINDING_RAYS, BINDING_SHADOW_RAYS,
          BINDING_QUEUE_COUNTERS}},
        {kernels::kAccumulateName,
         {BINDING_FRAME_PARAMS, BINDING_PATH_STATES, BINDING_PIXEL_STATES, BINDING_ACTIVE_PIXELS,
          BINDING_QUEUE_COUNTERS}},
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

std::span<const std::uint32_t> kernelBindings(WavefrontKernel kernel) {
    return info(kernel).bindings;
}

DescriptorKind bindingKind(std::uint32_t binding) {
    switch (binding) {
    case BINDING_FRAME_PARAMS:
        return DescriptorKind::UniformBuffer;
    case BINDING_BVH_NODES:
    case BINDING_TRIANGLE_TEXELS:
        return DescriptorKind::UniformTexelBuffer;
    default:
        return DescriptorKind::StorageBuffer;
    }
}

std::vector<SpecializationConstant> featureConstants(const SceneFeatures& features) {
    const std::array<bool, FEATURE_COUNT> values = features.kernelFeatures();
    std::vector<SpecializationConstant> constants;
    for (std::uint32_t id = 0; id < FEATURE_COUNT; ++id)
        constants.push_back(specializeBool(id, values[id]));
    return constants;
}

bool isSpecialised(WavefrontKernel kernel) {
    return info(kernel).specialised;
}

Kernel makeWavefrontKernel(const GpuContext& context, WavefrontKernel kernel,
                           const SceneFeatures& features) {
    const kernels::EmbeddedKernel& embedded = kernels::findKernel(kernelName(kernel));
    KernelDesc desc;
    desc.name = std::string(embedded.name);
    desc.spirv = embedded.spirv;
    for (std::uint32_t binding : info(kernel).bindings)
        desc.bindings.push_back({binding, bindingKind(binding)});
    desc.pushConstantSize = sizeof(gpu::PassParams);
    if (isSpecialised(kernel)) desc.specializationConstants = featureConstants(features);
    return Kernel(context, std::move(desc));
}

DescriptorSet bindWavefrontKernel(const Kernel& kernel, WavefrontKernel id,
                                  const BufferTable& table) {
    std::vector<BufferBinding> bindings;
    for (std::uint32_t binding : kernelBindings(id)) {
        const Buffer* buffer = table.buffers.at(binding);
        VKPT_ASSERT(buffer != nullptr, "kernel '" + std::string(kernelName(id)) +
                                           "' needs binding " + std::to_string(binding));
        bindings.push_back({binding, buffer});
    }
    return DescriptorSet(kernel, bindings);
}

WavefrontPipelines::WavefrontPipelines(const GpuContext& context, const BufferTable& table,
                                       const SceneFeatures& features) {
    kernels_.reserve(kWavefrontKernelCount);
    sets_.reserve(kWavefrontKernelCount);
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        const auto id = static_cast<WavefrontKernel>(i);
        kernels_.push_back(makeWavefrontKernel(context, id, features));
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
