// kernel.h — Kernel: one compute pipeline made from embedded SPIR-V, with its descriptor set
// layout (buffers in set 0), push-constant range and specialisation constants. The pipeline's
// debug name is the kernel's name, as are its dispatch labels.
#pragma once

#include <volk.h>

#include <bit>
#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vkpt {

class GpuContext;

// A 32-bit specialisation constant (uint, int, float or bool in GLSL), set by constant_id.
struct SpecializationConstant {
    std::uint32_t id = 0;
    std::uint32_t value = 0;
};
inline SpecializationConstant specializeFloat(std::uint32_t id, float value) {
    return {id, std::bit_cast<std::uint32_t>(value)};
}
inline SpecializationConstant specializeBool(std::uint32_t id, bool value) {
    return {id, value ? VK_TRUE : VK_FALSE};
}

// How a kernel sees a buffer: GLSL `buffer` blocks (read and write), `uniform` blocks (small,
// read-only data every invocation reads alike) or `usamplerBuffer`s (read-only arrays fetched
// at each invocation's own index, see texel_view.h).
enum class DescriptorKind : std::uint32_t { StorageBuffer, UniformBuffer, UniformTexelBuffer };

struct KernelBinding {
    std::uint32_t binding = 0; // in set 0
    DescriptorKind kind = DescriptorKind::StorageBuffer;
    // Descriptors at this binding: more than one for a GLSL array of them (a scene array split
    // across several buffers, lib/scene_arrays.glsl), indexed only by constants.
    std::uint32_t count = 1;
};

VkDescriptorType descriptorTypeOf(DescriptorKind kind);

struct KernelDesc {
    std::string name;                     // "trace_closest", the .comp file's stem
    std::span<const std::uint32_t> spirv; // from the embedded kernel library
    std::vector<KernelBinding> bindings;
    std::uint32_t pushConstantSize = 0; // bytes, a multiple of 4; 0 for none
    std::vector<SpecializationConstant> specializationConstants;
    // true: the constants are folded into the module on the host and the driver gets none
    // (spirv_specialise.h); false: the module as built, specialised by the driver (the reference
    // that folding must render bit for bit).
    bool foldConstantsOnHost = true;
};

class Kernel {
public:
    // Throws VulkanError when the device cannot take the push constants or the number of
    // descriptors of a kind, or when the driver rejects the SPIR-V.
    Kernel(const GpuContext& context, KernelDesc desc);
    ~Kernel();
    Kernel(Kernel&& other) noexcept;
    Kernel& operator=(Kernel&&) = delete;
    Kernel(const Kernel&) = delete;
    Kernel& operator=(const Kernel&) = delete;

    const GpuContext& context() const { return *context_; }
    const KernelDesc& desc() const { return desc_; }
    const std::string& name() const { return desc_.name; }
    const std::vector<KernelBinding>& bindings() const { return desc_.bindings; }
    std::uint32_t pushConstantSize() const { return desc_.pushConstantSize; }
    VkPipeline pipeline() const { return pipeline_; }
    VkPipelineLayout pipelineLayout() const { return pipelineLayout_; }
    VkDescriptorSetLayout setLayout() const { return setLayout_; }
    // Wall time of folding the constants into the SPIR-V (spirv_specialise.h),
    // vkCreateShaderModule and vkCreateComputePipelines: the driver's compile.
    std::chrono::nanoseconds creationTime() const { return creationTime_; }

private:
    void checkLimits() const;
    void checkDescriptorCount(DescriptorKind kind, const char* what, const char* limitName,
                              std::uint32_t limit) const;
    void createLayouts();
    void createPipeline();
    void destroy() noexcept;

    const GpuContext* context_;
    KernelDesc desc_;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    std::chrono::nanoseconds creationTime_{0};
};

} // namespace vkpt
