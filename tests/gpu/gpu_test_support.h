// gpu_test_support.h — what every kernel test needs: a validated GpuContext that fails the test
// on any validation message, embedded test kernels, and one-call buffer and dispatch helpers.
#pragma once

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/descriptor_set.h"
#include "gpu/dispatch.h"
#include "gpu/kernel.h"
#include "gpu/upload.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vkpt::test {

// Validation is always on; VKPT_DEVICE (an index or a name substring) picks the device.
GpuOptions testGpuOptions();

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    // Destroys the context first, so messages the layer emits at vkDestroyDevice (leaked
    // objects) count too, then requires that there were none.
    void TearDown() override;

    GpuContext& context() { return *context_; }

    // A test kernel from vkpt_test_kernels with storage buffers at bindings 0..bufferCount-1.
    Kernel makeKernel(std::string_view name, std::uint32_t bufferCount,
                      std::uint32_t pushConstantSize,
                      std::vector<SpecializationConstant> specialization = {});

    // A device-local storage buffer that uploads and downloads can reach.
    Buffer makeStorageBuffer(std::string name, VkDeviceSize size);

    template <typename T> Buffer makeStorageBuffer(std::string name, std::span<const T> values) {
        Buffer buffer = makeStorageBuffer(std::move(name), values.size_bytes());
        upload(context(), buffer, values);
        return buffer;
    }

    // Binds buffers to bindings 0, 1, ... and runs enough workgroups for `invocations`.
    void runKernel(const Kernel& kernel, const std::vector<const Buffer*>& buffers,
                   std::uint32_t invocations, std::span<const std::byte> pushConstants = {});

private:
    std::unique_ptr<GpuContext> context_;
    std::shared_ptr<const ValidationLog> validationLog_;
};

} // namespace vkpt::test
