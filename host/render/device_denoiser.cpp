// device_denoiser.cpp — upload, one submission of every iteration, download (device_denoiser.h).
#include "render/device_denoiser.h"

#include "common/errors.h"
#include "gpu/barriers.h"
#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/descriptor_set.h"
#include "gpu/dispatch.h"
#include "gpu/submit.h"
#include "gpu/upload.h"
#include "shared/host_device.h"
#include "vkpt_denoise_kernels.h"

namespace vkpt {

namespace {

Kernel makeDenoiseKernel(const GpuContext& context, std::string_view name,
                         std::uint32_t bufferCount) {
    const denoise_kernels::EmbeddedKernel& embedded = denoise_kernels::findKernel(name);
    KernelDesc desc;
    desc.name = std::string(embedded.name);
    desc.spirv = embedded.spirv;
    for (std::uint32_t binding = 0; binding < bufferCount; ++binding)
        desc.bindings.push_back({binding, DescriptorKind::StorageBuffer});
    desc.pushConstantSize = sizeof(gpu::DenoiseParams);
    return Kernel(context, std::move(desc));
}

Buffer makeDenoiseBuffer(GpuContext& context, const char* name, VkDeviceSize bytes) {
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                         VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    return Buffer(context, {name, bytes, usage, MemoryLocation::DeviceLocal});
}

} // namespace

DeviceDenoiser::DeviceDenoiser(GpuContext& context)
    : context_(context), demodulate_(makeDenoiseKernel(context, "demodulate_radiance", 2)),
      filter_(makeDenoiseKernel(context, "filter_radiance", 3)) {}

std::string DeviceDenoiser::where() const {
    return context_.deviceInfo().name;
}

std::vector<glm::vec3> DeviceDenoiser::denoise(const std::vector<gpu::DenoisePixel>& pixels,
                                               std::uint32_t width, std::uint32_t height,
                                               const DenoiseSettings& settings) {
    VKPT_ASSERT(pixels.size() == std::size_t(width) * height, "one input per pixel");
    VKPT_ASSERT(settings.iterations > 0, "at least one iteration");
    const std::uint32_t count = width * height;
    const Buffer denoisePixels =
        makeDenoiseBuffer(context_, "denoisePixels", count * sizeof(gpu::DenoisePixel));
    upload(context_, denoisePixels, std::span<const gpu::DenoisePixel>(pixels));
    const Buffer iterates[2] = {
        makeDenoiseBuffer(context_, "denoiseValues", count * sizeof(gpu::DenoiseValue)),
        makeDenoiseBuffer(context_, "denoiseValues", count * sizeof(gpu::DenoiseValue))};
    const DescriptorSet demodulateSet(demodulate_, {{0, &denoisePixels}, {1, &iterates[0]}});
    const DescriptorSet filterSets[2] = {
        DescriptorSet(filter_, {{0, &denoisePixels}, {1, &iterates[0]}, {2, &iterates[1]}}),
        DescriptorSet(filter_, {{0, &denoisePixels}, {1, &iterates[1]}, {2, &iterates[0]}})};
    const WorkgroupCount groups{workgroupsFor(count, WORKGROUP_SIZE), 1, 1};
    submitAndWait(context_, "denoise", [&](VkCommandBuffer commands) {
        const gpu::DenoiseParams first = denoiseParams(settings, width, height, 0);
        recordDispatch(commands, demodulate_, demodulateSet, groups, pushConstantBytes(first));
        // The iterations, then the last pass that only chooses (denoiseParams, step 0).
        for (std::uint32_t iteration = 0; iteration <= settings.iterations; ++iteration) {
            recordComputeToComputeBarrier(commands);
            const gpu::DenoiseParams params = denoiseParams(settings, width, height, iteration);
            recordDispatch(commands, filter_, filterSets[iteration % 2], groups,
                           pushConstantBytes(params));
        }
    });
    const auto result =
        download<gpu::DenoiseValue>(context_, iterates[(settings.iterations + 1) % 2], count);
    std::vector<glm::vec3> radiance(count);
    for (std::size_t i = 0; i < count; ++i)
        radiance[i] = glm::vec3(result[i].chosen);
    return radiance;
}

} // namespace vkpt
