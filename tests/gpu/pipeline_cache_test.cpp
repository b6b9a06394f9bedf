// pipeline_cache_test.cpp — the pipeline cache file: what vkpt writes it takes back for the same
// device and driver, and any other file (damaged, truncated, another device's, not a cache) is
// refused with a reason and never reaches the driver; a context whose file is bad still builds
// kernels, and a driver that keeps nothing (lavapipe) gets no file.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "../support/test_directory.h"
#include "gpu_test_support.h"
#include "vkpt_test_kernels.h"

namespace vkpt::test::pipeline_cache_test {
namespace {

class PipelineCacheFile : public TestDirectory {
protected:
    PipelineCacheFile() : TestDirectory("vkpt_pipeline_cache") {}

    void SetUp() override {
        TestDirectory::SetUp();
        context_ = std::make_unique<GpuContext>(testGpuOptions());
    }
    void TearDown() override {
        const auto log = context_->validationLog();
        context_.reset();
        EXPECT_EQ(log->messageCount(), 0u) << "validation messages (printed on stderr)";
        TestDirectory::TearDown();
    }

    VkPhysicalDevice device() const { return context_->physicalDevice(); }

    // What a driver's vkGetPipelineCacheData starts with for this device, then some data.
    std::vector<std::uint8_t> payloadForThisDevice() const {
        VkPhysicalDeviceProperties p{};
        vkGetPhysicalDeviceProperties(device(), &p);
        std::vector<std::uint8_t> payload(16 + VK_UUID_SIZE);
        const std::uint32_t header[4] = {std::uint32_t(payload.size()),
                                         VK_PIPELINE_CACHE_HEADER_VERSION_ONE, p.vendorID,
                                         p.deviceID};
        std::memcpy(payload.data(), header, sizeof(header));
        std::memcpy(payload.data() + 16, p.pipelineCacheUUID, VK_UUID_SIZE);
        for (int i = 0; i < 64; ++i)
            payload.push_back(std::uint8_t(i * 37));
        return payload;
    }

    std::string readBack(const std::string& file) const {
        std::string problem;
        const std::vector<std::uint8_t> data = readPipelineCacheFile(file, device(), problem);
        EXPECT_TRUE(data.empty() || problem.empty());
        return data.empty() ? problem : "read";
    }

    void writeBytes(const std::string& file, const std::vector<char>& bytes) const {
        std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    }

    std::unique_ptr<GpuContext> context_;
};

TEST_F(PipelineCacheFile, TakesBackWhatItWroteForThisDevice) {
    const std::vector<std::uint8_t> payload = payloadForThisDevice();
    ASSERT_TRUE(writePipelineCacheFile(path("sub/cache.bin"), payload));
    std::string problem;
    EXPECT_EQ(readPipelineCacheFile(path("sub/cache.bin"), device(), problem), payload);
    EXPECT_EQ(problem, "");
    EXPECT_EQ(readBack(path("missing.bin")), ""); // no file yet: nothing to say
}

TEST_F(PipelineCacheFile, RefusesDamagedTruncatedForeignAndOtherFiles) {
    const std::vector<std::uint8_t> payload = payloadForThisDevice();
    ASSERT_TRUE(writePipelineCacheFile(path("good.bin"), payload));
    const std::vector<char> good = bytesOf(path("good.bin"));

    std::vector<char> damaged = good;
    damaged[damaged.size() - 5] ^= 1;
    writeBytes(path("damaged.bin"), damaged);
    EXPECT_EQ(readBack(path("damaged.bin")), "damaged (checksum mismatch)");

    writeBytes(path("truncated.bin"), {good.begin(), good.end() - 10});
    EXPECT_EQ(readBack(path("truncated.bin")), "truncated");

    std::vector<std::uint8_t> foreign = payload;
    foreign[16] ^= 0xff; // another pipelineCacheUUID: another driver build
    ASSERT_TRUE(writePipelineCacheFile(path("foreign.bin"), foreign));
    EXPECT_EQ(readBack(path("foreign.bin")), "made by another device or driver version");

    writeBytes(path("text.bin"), {'h', 'e', 'l', 'l', 'o'});
    EXPECT_EQ(readBack(path("text.bin")), "not a vkpt pipeline cache");
}

// A bad file costs one line and an empty cache; the kernels still build through it. lavapipe
// keeps nothing in its cache, so saving writes no file over the bad one.
TEST_F(PipelineCacheFile, ABadFileIsIgnoredWithOneLine) {
    writeBytes(path("cache.bin"), {'n', 'o', 't', ' ', 'a', ' ', 'c', 'a', 'c', 'h', 'e'});
    GpuOptions options = testGpuOptions();
    options.persistentPipelineCache = true;
    options.pipelineCachePath = path("cache.bin");
    testing::internal::CaptureStderr();
    auto cached = std::make_unique<GpuContext>(options);
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_EQ(said, "vkpt: pipeline cache " + path("cache.bin") +
                        ": not a vkpt pipeline cache; starting an empty one\n");
    const test_kernels::EmbeddedKernel& embedded = test_kernels::findKernel("write_indices");
    KernelDesc desc;
    desc.name = std::string(embedded.name);
    desc.spirv = embedded.spirv;
    desc.bindings.push_back({0, DescriptorKind::StorageBuffer});
    desc.pushConstantSize = 4;
    {
        Kernel kernel(*cached, std::move(desc));
        EXPECT_NE(kernel.pipeline(), VkPipeline(VK_NULL_HANDLE));
    }
    const bool wrote = cached->pipelineCache().save();
    if (cached->deviceInfo().type == VK_PHYSICAL_DEVICE_TYPE_CPU) {
        EXPECT_FALSE(wrote);
    }
    if (!wrote) {
        EXPECT_EQ(bytesOf(path("cache.bin")).size(), 11u);
    } else {
        EXPECT_EQ(readBack(path("cache.bin")), "read"); // a GPU's cache, written in our frame
    }
    const auto log = cached->validationLog();
    cached.reset();
    EXPECT_EQ(log->messageCount(), 0u);
}

} // namespace
} // namespace vkpt::test::pipeline_cache_test
