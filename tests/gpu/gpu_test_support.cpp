// gpu_test_support.cpp — the validated fixture and helpers of the kernel tests.
#include "gpu_test_support.h"

#include "gpu/submit.h"
#include "shared/host_device.h"
#include "vkpt_test_kernels.h"

#include <cstdlib>

namespace vkpt::test {

GpuOptions testGpuOptions() {
    GpuOptions options;
    options.validation = true;
    if (const char* device = std::getenv("VKPT_DEVICE")) {
        options.device = parseDeviceSelection(device);
    }
    return options;
}

void GpuTest::SetUp() {
    context_ = std::make_unique<GpuContext>(testGpuOptions());
    validationLog_ = context_->validationLog();
    ASSERT_NE(validationLog_, nullptr);
}

void GpuTest::TearDown() {
    context_.reset();
    if (!validationLog_) return; // SetUp failed and said why
    EXPECT_EQ(validationLog_->messageCount(), 0u) << "validation messages (printed on stderr)";
}

Kernel GpuTest::makeKernel(std::string_view name, std::uint32_t bufferCount,
                           std::uint32_t pushConstantSize,
                           std::vector<SpecializationConstant> specialization) {
    const test_kernels::EmbeddedKernel& embedded = test_kernels::findKernel(name);
    KernelDesc desc;
    desc.name = std::string(embedded.name);
    desc.spirv = embedded.spirv;
    for (std::uint32_t binding = 0; binding < bufferCount; ++binding) {
        desc.bindings.push_back({binding, DescriptorKind::StorageBuffer});
    }
    desc.pushConstantSize = pushConstantSize;
    desc.specializationConstants = std::move(specialization);
    return Kernel(context(), std::move(desc));
}

Buffer GpuTest::makeStorageBuffer(std::string name, VkDeviceSize size) {
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    return Buffer(context(), {std::move(name), size, usage, MemoryLocation::DeviceLocal});
}

void GpuTest::runKernel(const Kernel& kernel, const std::vector<const Buffer*>& buffers,
                        std::uint32_t invocations, std::span<const std::byte> pushConstants) {
    std::vector<BufferBinding> bindings;
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        bindings.push_back({static_cast<std::uint32_t>(i), buffers[i]});
    }
    const DescriptorSet set(kernel, bindings);
    const WorkgroupCount groups{workgroupsFor(invocations, WORKGROUP_SIZE), 1, 1};
    submitAndWait(context(), kernel.name(), [&](VkCommandBuffer commands) {
        recordDispatch(commands, kernel, set, groups, pushConstants);
    });
}

} // namespace vkpt::test
