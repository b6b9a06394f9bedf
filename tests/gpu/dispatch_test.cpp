// dispatch_test.cpp — the host layer's own path: upload and download, push constants,
// specialisation constants, indirect dispatch, timestamps and pipeline creation time.
#include "gpu_test_support.h"

#include "gpu/barriers.h"
#include "gpu/submit.h"
#include "gpu/timestamps.h"
#include "kernel_test_io.h"

#include <chrono>
#include <cstdio>
#include <numeric>

namespace vkpt::test::dispatch_test {
namespace {

class Dispatch : public GpuTest {};

TEST_F(Dispatch, UploadThenDownloadReturnsTheSameBytes) {
    std::vector<std::uint32_t> values(10000);
    std::iota(values.begin(), values.end(), 0xC0FFEE00u);
    const Buffer buffer = makeStorageBuffer("values", std::span<const std::uint32_t>(values));
    EXPECT_EQ(download<std::uint32_t>(context(), buffer, values.size()), values);
    // A range in the middle, at an offset.
    const std::vector<std::uint32_t> part = {1, 2, 3};
    upload(context(), buffer, std::span<const std::uint32_t>(part), 40);
    EXPECT_EQ(download<std::uint32_t>(context(), buffer, 3, 40), part);
}

TEST_F(Dispatch, PushAndSpecializationConstantsReachTheKernel) {
    const Buffer values = makeStorageBuffer("values", 1000 * sizeof(std::uint32_t));
    const Kernel kernel = makeKernel("write_indices", 1, sizeof(std::uint32_t), {{0, 3}});
    const std::uint32_t offset = 7;
    runKernel(kernel, {&values}, 1000, pushConstantBytes(offset));
    const auto result = download<std::uint32_t>(context(), values, 1000);
    for (std::uint32_t i = 0; i < 1000; ++i)
        ASSERT_EQ(result[i], 3 * i + 7) << i;
}

TEST_F(Dispatch, IndirectDispatchReadsWorkgroupCountFromBuffer) {
    const Buffer values = makeStorageBuffer("values", 1024 * sizeof(std::uint32_t));
    fillBuffer(context(), values, 0xFFFFFFFFu);
    const VkDispatchIndirectCommand groups{3, 1, 1}; // 3 × 64 of the 1024 invocations
    const Buffer arguments(context(),
                           {"dispatchArguments", sizeof groups,
                            VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            MemoryLocation::DeviceLocal});
    upload(context(), arguments, std::span<const VkDispatchIndirectCommand>(&groups, 1));
    const Kernel kernel = makeKernel("write_indices", 1, sizeof(std::uint32_t));
    const DescriptorSet set(kernel, {{0, &values}});
    const std::uint32_t offset = 0;
    submitAndWait(context(), "indirect", [&](VkCommandBuffer commands) {
        recordDispatchIndirect(commands, kernel, set, arguments, 0, pushConstantBytes(offset));
    });
    const auto result = download<std::uint32_t>(context(), values, 1024);
    for (std::uint32_t i = 0; i < 1024; ++i) {
        ASSERT_EQ(result[i], i < 3 * 64 ? i : 0xFFFFFFFFu) << i;
    }
}

TEST_F(Dispatch, TimerReportsOneLabelledTimePerInterval) {
    const Buffer values = makeStorageBuffer("values", (1u << 20) * sizeof(std::uint32_t));
    const Kernel kernel = makeKernel("write_indices", 1, sizeof(std::uint32_t));
    const DescriptorSet set(kernel, {{0, &values}});
    GpuTimer timer(context(), 4);
    const std::uint32_t offset = 0;
    submitAndWait(context(), "timed", [&](VkCommandBuffer commands) {
        timer.recordReset(commands);
        for (int i = 0; i < 2; ++i) {
            timer.recordBegin(commands, kernel.name());
            recordDispatch(commands, kernel, set, {(1u << 20) / 64, 1, 1},
                           pushConstantBytes(offset));
            timer.recordEnd(commands);
            recordComputeToComputeBarrier(commands);
        }
    });
    const std::vector<KernelTime> times = timer.results();
    if (!context().timestampsSupported()) {
        EXPECT_TRUE(times.empty());
        GTEST_SKIP() << "no timestamps on this device's compute queue";
    }
    ASSERT_EQ(times.size(), 2u);
    for (const KernelTime& time : times) {
        std::printf("%s: %.3f ms\n", time.label.c_str(),
                    static_cast<double>(time.nanoseconds) * 1e-6);
        EXPECT_EQ(time.label, "write_indices");
        EXPECT_GT(time.nanoseconds, 0u);
    }
}

// Not a pass/fail timing: prints what pipeline creation costs on this device, for deciding how
// many specialised pipelines a scene can afford.
TEST_F(Dispatch, ReportsPipelineCreationTimes) {
    struct Layout {
        const char* name;
        std::uint32_t buffers;
        std::uint32_t pushConstantSize;
    };
    const Layout layouts[] = {{"count_loop_iterations", 1, 32},
                              {"read_layouts", LAYOUT_BUFFER_COUNT, 0},
                              {"run_intersect", 2, 4},
                              {"run_rng", 2, 4},
                              {"run_sampling", 2, 4},
                              {"write_indices", 1, 4},
                              {"write_layouts", LAYOUT_BUFFER_COUNT, 0}};
    for (const Layout& layout : layouts) {
        const Kernel kernel = makeKernel(layout.name, layout.buffers, layout.pushConstantSize);
        std::printf("%-22s pipeline created in %7.3f ms\n", layout.name,
                    static_cast<double>(kernel.creationTime().count()) * 1e-6);
        EXPECT_GT(kernel.creationTime().count(), 0);
    }
}

// Some drivers compile at the first dispatch rather than in vkCreateComputePipelines (lavapipe
// builds its LLVM variant then); printed, not checked, like the test above.
TEST_F(Dispatch, ReportsFirstDispatchCost) {
    const Kernel kernel = makeKernel("run_sampling", 2, sizeof(std::uint32_t));
    const Buffer samplingInputs = makeStorageBuffer("samplingInputs", 64 * 64);
    const Buffer samplingOutputs = makeStorageBuffer("samplingOutputs", 64 * 96);
    const std::uint32_t count = 64;
    for (int run = 0; run < 3; ++run) {
        const auto start = std::chrono::steady_clock::now();
        runKernel(kernel, {&samplingInputs, &samplingOutputs}, count, pushConstantBytes(count));
        const std::chrono::duration<double, std::milli> elapsed =
            std::chrono::steady_clock::now() - start;
        std::printf("run_sampling dispatch %d of 64 invocations: %.3f ms\n", run + 1,
                    elapsed.count());
    }
}

TEST_F(Dispatch, DescriptorSetCanBePointedAtAnotherBuffer) {
    const Buffer first = makeStorageBuffer("raysIn", 64 * sizeof(std::uint32_t));
    const Buffer second = makeStorageBuffer("raysOut", 64 * sizeof(std::uint32_t));
    const Kernel kernel = makeKernel("write_indices", 1, sizeof(std::uint32_t));
    DescriptorSet set(kernel, {{0, &first}});
    set.update({{0, &second}});
    const std::uint32_t offset = 100;
    submitAndWait(context(), "rebound", [&](VkCommandBuffer commands) {
        recordDispatch(commands, kernel, set, {1, 1, 1}, pushConstantBytes(offset));
    });
    EXPECT_EQ(download<std::uint32_t>(context(), second, 1)[0], 100u);
}

} // namespace
} // namespace vkpt::test::dispatch_test
