// kernel.cpp — compute pipeline creation from SPIR-V, timed.
#include "gpu/kernel.h"

#include "common/errors.h"
#include "gpu/context.h"
#include "gpu/spirv_specialise.h"
#include "gpu/vk_check.h"

#include <utility>

namespace vkpt {

namespace {

// Frees the shader module once the pipeline holds what it needs (or creation failed).
struct ShaderModule {
    VkDevice device;
    VkShaderModule handle = VK_NULL_HANDLE;
    ~ShaderModule() { vkDestroyShaderModule(device, handle, nullptr); }
};

// The VkSpecializationInfo of `constants` with the arrays it points into: one 32-bit value
// per constant, packed in order.
class Specialization {
public:
    explicit Specialization(const std::vector<SpecializationConstant>& constants) {
        for (const SpecializationConstant& constant : constants) {
            const auto offset = static_cast<std::uint32_t>(values_.size() * sizeof(std::uint32_t));
            entries_.push_back({constant.id, offset, sizeof(std::uint32_t)});
            values_.push_back(constant.value);
        }
        info_.mapEntryCount = static_cast<std::uint32_t>(entries_.size());
        info_.pMapEntries = entries_.data();
        info_.dataSize = values_.size() * sizeof(std::uint32_t);
        info_.pData = values_.data();
    }
    Specialization(const Specialization&) = delete;
    Specialization& operator=(const Specialization&) = delete;

    const VkSpecializationInfo* info() const { return entries_.empty() ? nullptr : &info_; }

private:
    std::vector<std::uint32_t> values_;
    std::vector<VkSpecializationMapEntry> entries_;
    VkSpecializationInfo info_{};
};

} // namespace

VkDescriptorType descriptorTypeOf(DescriptorKind kind) {
    switch (kind) {
    case DescriptorKind::StorageBuffer:
        return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case DescriptorKind::UniformBuffer:
        return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case DescriptorKind::UniformTexelBuffer:
        return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    }
    return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

Kernel::Kernel(const GpuContext& context, KernelDesc desc)
    : context_(&context), desc_(std::move(desc)) {
    VKPT_ASSERT(!desc_.spirv.empty(), "kernel '" + desc_.name + "' has no SPIR-V");
    VKPT_ASSERT(desc_.pushConstantSize % 4 == 0,
                "kernel '" + desc_.name + "': push constant size not a multiple of 4");
    checkLimits();
    try {
        createLayouts();
        createPipeline();
    } catch (...) {
        destroy();
        throw;
    }
}

void Kernel::checkLimits() const {
    const DeviceLimits& limits = context_->limits();
    if (desc_.pushConstantSize > limits.maxPushConstantsSize) {
        throw VulkanError("kernel '" + desc_.name + "' needs " +
                              std::to_string(desc_.pushConstantSize) +
                              " bytes of push constants; this device's maxPushConstantsSize is " +
                              std::to_string(limits.maxPushConstantsSize),
                          VK_ERROR_FEATURE_NOT_PRESENT);
    }
    checkDescriptorCount(DescriptorKind::StorageBuffer, "storage buffers",
                         "maxPerStageDescriptorStorageBuffers",
                         limits.maxPerStageDescriptorStorageBuffers);
    checkDescriptorCount(DescriptorKind::UniformBuffer, "uniform buffers",
                         "maxPerStageDescriptorUniformBuffers",
                         limits.maxPerStageDescriptorUniformBuffers);
    checkDescriptorCount(DescriptorKind::UniformTexelBuffer, "uniform texel buffers",
                         "maxPerStageDescriptorSampledImages",
                         limits.maxPerStageDescriptorSampledImages);
}

void Kernel::checkDescriptorCount(DescriptorKind kind, const char* what, const char* limitName,
                                  std::uint32_t limit) const {
    std::uint32_t count = 0;
    for (const KernelBinding& binding : desc_.bindings)
        if (binding.kind == kind) count += binding.count;
    if (count <= limit) return;
    throw VulkanError("kernel '" + desc_.name + "' binds " + std::to_string(count) + " " + what +
                          "; this device's " + limitName + " is " + std::to_string(limit),
                      VK_ERROR_FEATURE_NOT_PRESENT);
}

void Kernel::createLayouts() {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const KernelBinding& binding : desc_.bindings) {
        bindings.push_back({binding.binding, descriptorTypeOf(binding.kind), binding.count,
                            VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    }
    VkDescriptorSetLayoutCreateInfo setInfo{};
    setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    setInfo.bindingCount = static_cast<std::uint32_t>(bindings.size());
    setInfo.pBindings = bindings.data();
    VKPT_VK_CHECK(vkCreateDescriptorSetLayout(context_->device(), &setInfo, nullptr, &setLayout_));
    context_->setDebugName(setLayout_, desc_.name + ".setLayout");

    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, desc_.pushConstantSize};
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout_;
    layoutInfo.pushConstantRangeCount = desc_.pushConstantSize > 0 ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    VKPT_VK_CHECK(
        vkCreatePipelineLayout(context_->device(), &layoutInfo, nullptr, &pipelineLayout_));
    context_->setDebugName(pipelineLayout_, desc_.name + ".layout");
}

void Kernel::createPipeline() {
    const auto start = std::chrono::steady_clock::now();
    // Folded on the host, the driver gets the module without the code the constants switch
    // off and no specialisation info (spirv_specialise.h); else the module as built, and the
    // constants with it.
    const bool fold = desc_.foldConstantsOnHost && !desc_.specializationConstants.empty();
    std::vector<std::uint32_t> folded;
    std::span<const std::uint32_t> spirv = desc_.spirv;
    if (fold) {
        folded = context_->foldedSpirvCache().fold(desc_);
        spirv = folded;
    }
    VkShaderModuleCreateInfo moduleInfo{};
    moduleInfo.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    moduleInfo.codeSize = spirv.size_bytes();
    moduleInfo.pCode = spirv.data();
    ShaderModule module{context_->device()};
    VKPT_VK_CHECK(vkCreateShaderModule(context_->device(), &moduleInfo, nullptr, &module.handle));
    context_->setDebugName(module.handle, desc_.name);

    const Specialization specialization(fold ? std::vector<SpecializationConstant>{}
                                             : desc_.specializationConstants);
    VkComputePipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.handle;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = specialization.info();
    info.layout = pipelineLayout_;
    VKPT_VK_CHECK(vkCreateComputePipelines(context_->device(), context_->pipelineCache().handle(),
                                           1, &info, nullptr, &pipeline_));
    creationTime_ = std::chrono::steady_clock::now() - start;
    context_->setDebugName(pipeline_, desc_.name);
}

void Kernel::destroy() noexcept {
    if (context_ == nullptr) return;
    const VkDevice device = context_->device();
    vkDestroyPipeline(device, pipeline_, nullptr);
    vkDestroyPipelineLayout(device, pipelineLayout_, nullptr);
    vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
}

Kernel::~Kernel() {
    destroy();
}

Kernel::Kernel(Kernel&& other) noexcept
    : context_(std::exchange(other.context_, nullptr)), desc_(std::move(other.desc_)),
      setLayout_(std::exchange(other.setLayout_, VK_NULL_HANDLE)),
      pipelineLayout_(std::exchange(other.pipelineLayout_, VK_NULL_HANDLE)),
      pipeline_(std::exchange(other.pipeline_, VK_NULL_HANDLE)),
      creationTime_(other.creationTime_) {}

} // namespace vkpt
