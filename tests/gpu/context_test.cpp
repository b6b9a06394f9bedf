// context_test.cpp — device listing and selection, the errors a user sees when something does
// not fit, validation counting, and memory accounting.
#include "gpu_test_support.h"

#include "gpu/submit.h"
#include "gpu/vk_check.h"
#include "shared/host_device.h"
#include "vkpt_test_kernels.h"

#include <algorithm>
#include <bit>
#include <cstdio>

namespace vkpt::test::context_test {
namespace {

bool anyDeviceNamed(const std::vector<DeviceInfo>& devices, const std::string& substring) {
    for (const DeviceInfo& device : devices) {
        if (device.name.find(substring) != std::string::npos) return true;
    }
    return false;
}

TEST(VkCheck, MessageNamesExpressionResultAndPlace) {
    try {
        VKPT_VK_CHECK(VK_ERROR_DEVICE_LOST);
        FAIL() << "no exception";
    } catch (const VulkanError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("VK_ERROR_DEVICE_LOST failed: VK_ERROR_DEVICE_LOST"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("context_test.cpp:"), std::string::npos) << message;
        EXPECT_EQ(error.result(), VK_ERROR_DEVICE_LOST);
    }
    EXPECT_EQ(vkResultName(static_cast<VkResult>(-123456)), "VkResult(-123456)");
}

TEST(DeviceList, ListsEveryDeviceWithTypeVersionAndVerdict) {
    const std::vector<DeviceInfo> devices = listDevices();
    ASSERT_FALSE(devices.empty());
    for (const DeviceInfo& device : devices) {
        std::printf("%s\n", describeDevice(device).c_str());
        EXPECT_FALSE(device.name.empty());
        EXPECT_GT(device.apiVersion, 0u);
        EXPECT_EQ(device.usable(),
                  device.computeQueueFamily.has_value() && device.apiVersion >= VK_API_VERSION_1_2);
    }
}

TEST(DeviceList, ParsesIndexOrName) {
    EXPECT_EQ(parseDeviceSelection("1").index, 1u);
    EXPECT_EQ(parseDeviceSelection("llvmpipe").nameSubstring, "llvmpipe");
    EXPECT_EQ(parseDeviceSelection("1a").nameSubstring, "1a");
}

class Context : public GpuTest {};

TEST_F(Context, SelectsLlvmpipeByName) {
    if (!anyDeviceNamed(context().devices(), "llvmpipe")) GTEST_SKIP() << "no lavapipe here";
    GpuOptions options = testGpuOptions();
    options.device = parseDeviceSelection("LLVMpipe"); // case does not matter
    const GpuContext lavapipe(options);
    EXPECT_NE(lavapipe.deviceInfo().name.find("llvmpipe"), std::string::npos);
    EXPECT_EQ(lavapipe.deviceInfo().type, VK_PHYSICAL_DEVICE_TYPE_CPU);
    EXPECT_EQ(lavapipe.validationMessageCount(), 0u);
}

TEST_F(Context, UnknownDeviceNameFailsWithOneLineListingDevices) {
    GpuOptions options = testGpuOptions();
    options.device = parseDeviceSelection("no-such-gpu");
    try {
        const GpuContext failed(options);
        FAIL() << "a device matched 'no-such-gpu'";
    } catch (const VulkanError& error) {
        const std::string message = error.what();
        std::printf("%s\n", message.c_str());
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
        EXPECT_EQ(message.rfind("no Vulkan device matches 'no-such-gpu' (", 0), 0u) << message;
        EXPECT_NE(message.find(context().deviceInfo().name), std::string::npos) << message;
    }
}

TEST_F(Context, DeviceIndexOutOfRangeFails) {
    GpuOptions options = testGpuOptions();
    options.device.index = 99;
    EXPECT_THROW(GpuContext failed(options), VulkanError);
}

TEST_F(Context, RefusesStorageBufferAboveMaxStorageBufferRange) {
    const VkDeviceSize limit = context().limits().maxStorageBufferRange;
    try {
        const Buffer tooLarge = makeStorageBuffer("bvhNodes", limit + 16);
        FAIL() << "a storage buffer above maxStorageBufferRange was created";
    } catch (const VulkanError& error) {
        const std::string message = error.what();
        std::printf("%s\n", message.c_str());
        EXPECT_NE(message.find("'bvhNodes'"), std::string::npos) << message;
        EXPECT_NE(message.find("maxStorageBufferRange"), std::string::npos) << message;
        EXPECT_NE(message.find(std::to_string(limit) + " bytes"), std::string::npos) << message;
        EXPECT_NE(message.find(std::to_string(limit + 16) + " bytes"), std::string::npos)
            << message;
    }
    EXPECT_EQ(context().memoryStats().bytesInUse, 0u) << "nothing allocated for a refused buffer";
}

// Out of device memory is one line naming the size asked and the size the heap has left,
// checked before the driver is asked (lavapipe would overcommit). A first buffer takes three
// quarters of the heap; the second asks for 1 MiB more than the rest.
TEST_F(Context, RefusesBufferAboveWhatTheHeapHasLeft) {
    const VkDeviceSize heap = context().limits().deviceLocalHeapSize;
    const VkDeviceSize largest = context().limits().maxMemoryAllocationSize;
    const VkDeviceSize first = std::min(heap / 4 * 3, largest);
    const Buffer taken(context(), {"taken", first, VK_BUFFER_USAGE_TRANSFER_DST_BIT});
    const VkDeviceSize left = heap - context().memoryStats().bytesInUse;
    const VkDeviceSize asked = left + (VkDeviceSize(1) << 20);
    if (asked > largest) GTEST_SKIP() << "the rest of the heap exceeds maxMemoryAllocationSize";
    try {
        const Buffer tooLarge(context(), {"triangles", asked, VK_BUFFER_USAGE_TRANSFER_DST_BIT});
        FAIL() << "a buffer above what the heap has left was created";
    } catch (const VulkanError& error) {
        const std::string message = error.what();
        std::printf("%s\n", message.c_str());
        EXPECT_NE(message.find("'triangles'"), std::string::npos) << message;
        EXPECT_NE(message.find(std::to_string(asked) + " bytes"), std::string::npos) << message;
        EXPECT_NE(message.find(std::to_string(left) + " bytes) available"), std::string::npos)
            << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
    }
    EXPECT_EQ(context().memoryStats().bytesInUse, taken.allocationSize());
}

TEST(Validation, CountsMessages) {
    // An invalid call on purpose, in a context of its own: a buffer without usage flags
    // (VUID-VkBufferCreateInfo-usage-requiredbitmask). Proves that the fixture's "no messages"
    // check can fail.
    const GpuContext context(testGpuOptions());
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 16;
    VkBuffer buffer = VK_NULL_HANDLE;
    std::fprintf(stderr, "an expected validation error follows:\n");
    (void)vkCreateBuffer(context.device(), &info, nullptr, &buffer);
    vkDestroyBuffer(context.device(), buffer, nullptr);
    EXPECT_GE(context.validationMessageCount(), 1u);
}

TEST(Validation, SynchronizationChecksCatchAMissingBarrier) {
    // A kernel writes a buffer and a fill overwrites it with no barrier between them: a
    // write-after-write hazard that only synchronization validation sees, the same kind as a
    // download without its barrier. (Layer 1.3.239 does not report the same hazard between two
    // dispatches, so wavefront barriers are also checked by results, not only by the layer.)
    GpuContext context(testGpuOptions());
    const test_kernels::EmbeddedKernel& embedded = test_kernels::findKernel("write_indices");
    const Kernel kernel(context, {std::string(embedded.name), embedded.spirv, {{0}}, 4, {}});
    const Buffer values(context,
                        {"values", 256,
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         MemoryLocation::DeviceLocal});
    const DescriptorSet set(kernel, {{0, &values}});
    const std::uint32_t offset = 0;
    std::fprintf(stderr, "an expected synchronization hazard follows:\n");
    submitAndWait(context, "hazard", [&](VkCommandBuffer commands) {
        recordDispatch(commands, kernel, set, {1, 1, 1}, pushConstantBytes(offset));
        vkCmdFillBuffer(commands, values.handle(), 0, VK_WHOLE_SIZE, 0);
    });
    EXPECT_GE(context.validationMessageCount(), 1u);
}

TEST_F(Context, AccountsDeviceMemoryOfLiveBuffers) {
    EXPECT_EQ(context().memoryStats().bytesInUse, 0u);
    {
        const Buffer a = makeStorageBuffer("radianceSum", 1u << 20);
        const Buffer b = makeStorageBuffer("sampleCounts", 4096);
        const MemoryStats& stats = context().memoryStats();
        EXPECT_EQ(stats.bytesInUse, a.allocationSize() + b.allocationSize());
        EXPECT_GE(stats.bytesInUse, (1u << 20) + 4096u);
        EXPECT_EQ(stats.allocationsInUse, 2u);
    }
    EXPECT_EQ(context().memoryStats().bytesInUse, 0u);
    EXPECT_GE(context().memoryStats().peakBytes, (1u << 20) + 4096u);
}

// What lavapipe keys a compiled kernel on (gpu/buffer.h): never a power of two, never bits 8-15
// zero; whole texels, at least what was asked, and at most 256 bytes more.
TEST(TexelBufferSize, KeepsTheDriversKernelKeyTheSameForEverySize) {
    std::vector<VkDeviceSize> sizes;
    for (VkDeviceSize bytes = 1; bytes <= 70000; ++bytes)
        sizes.push_back(bytes);
    for (int bit = 17; bit < 40; ++bit) { // powers of two and their neighbours
        const VkDeviceSize power = VkDeviceSize(1) << bit;
        sizes.insert(sizes.end(), {power - 1, power, power + 1, power + 256});
    }
    for (VkDeviceSize bytes : sizes) {
        const VkDeviceSize size = keyStableTexelBytes(bytes);
        ASSERT_GE(size, bytes) << bytes;
        ASSERT_EQ(size % kTexelBytes, 0u) << bytes;
        ASSERT_LE(size - bytes, 256u + kTexelBytes) << bytes;
        ASSERT_FALSE(std::has_single_bit(size)) << bytes << " -> " << size;
        ASSERT_NE((size >> 8) & 0xff, 0u) << bytes << " -> " << size;
        ASSERT_EQ(keyStableTexelBytes(size), size) << bytes;
    }
    EXPECT_EQ(keyStableTexelBytes(4096), 4112u);   // a 16² image's per-pixel texels: 2^12
    EXPECT_EQ(keyStableTexelBytes(65536), 65792u); // 64²: 2^16, and bits 8-15 zero after +16
    EXPECT_EQ(keyStableTexelBytes(9216), 9216u);   // 24²: already neither
}

TEST_F(Context, TexelViewsCoverTheKeyStableSize) {
    BufferDesc desc;
    desc.name = "pathTexels";
    desc.size = 4096;
    desc.usage = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    const Buffer buffer(context(), desc);
    EXPECT_NE(buffer.texelView(), VkBufferView(VK_NULL_HANDLE));
    EXPECT_EQ(buffer.size(), 4096u); // what the caller asked; the padding is the driver's
    EXPECT_GE(buffer.allocationSize(), keyStableTexelBytes(4096));
}

TEST_F(Context, ReportsLimits) {
    const DeviceLimits& limits = context().limits();
    std::printf("device %s\n", describeDevice(context().deviceInfo()).c_str());
    std::printf("maxStorageBufferRange %s\n", formatBytes(limits.maxStorageBufferRange).c_str());
    std::printf("maxMemoryAllocationSize %s, largest device-local heap %s\n",
                formatBytes(limits.maxMemoryAllocationSize).c_str(),
                formatBytes(limits.deviceLocalHeapSize).c_str());
    std::printf("maxComputeWorkGroupInvocations %u, maxComputeWorkGroupCount %u %u %u, "
                "maxComputeWorkGroupSize %u %u %u\n",
                limits.maxComputeWorkGroupInvocations, limits.maxComputeWorkGroupCount[0],
                limits.maxComputeWorkGroupCount[1], limits.maxComputeWorkGroupCount[2],
                limits.maxComputeWorkGroupSize[0], limits.maxComputeWorkGroupSize[1],
                limits.maxComputeWorkGroupSize[2]);
    std::printf("maxPushConstantsSize %u, maxPerStageDescriptorStorageBuffers %u, "
                "minStorageBufferOffsetAlignment %llu, subgroupSize %u\n",
                limits.maxPushConstantsSize, limits.maxPerStageDescriptorStorageBuffers,
                static_cast<unsigned long long>(limits.minStorageBufferOffsetAlignment),
                limits.subgroupSize);
    std::printf("timestampPeriod %g ns, timestampValidBits %u\n", limits.timestampPeriod,
                limits.timestampValidBits);
    // Vulkan's required minimums: whatever the device, vkpt may count on these.
    EXPECT_GE(limits.maxStorageBufferRange, 1u << 27);
    EXPECT_GE(limits.maxPushConstantsSize, 128u);
    EXPECT_GE(limits.maxComputeWorkGroupInvocations, 128u);
    EXPECT_GE(limits.maxComputeWorkGroupSize[0], static_cast<std::uint32_t>(WORKGROUP_SIZE));
}

} // namespace
} // namespace vkpt::test::context_test
