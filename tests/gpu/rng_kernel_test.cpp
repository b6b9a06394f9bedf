// rng_kernel_test.cpp — the device draws exactly the random numbers the CPU reference draws:
// shared/rng.h and shared/sampler.h (both samplers) are integer-only up to one exact int→float
// conversion, so bits and floats must agree bit for bit on every input.
#include "gpu_test_support.h"
#include "kernel_test_io.h"
#include "shared/sampler.h"

#include <bit>
#include <random>

namespace vkpt::test::rng_kernel_test {
namespace {

using gpu::test::RngInput;
using gpu::test::RngOutput;

// A sampler setup for key i: both kinds, image sides from 1 to 2^17 (past the 16 Morton bits a
// coordinate keeps) and spp from 1 to 2^32 - 1 (block exponents up to the 31-bit limit).
std::uint32_t samplerSetupFor(std::uint32_t i, std::uint32_t width, std::uint32_t spp) {
    const std::uint32_t kind = i % 5 == 0 ? SAMPLER_INDEPENDENT : SAMPLER_SOBOL;
    return gpu::makeSamplerSetup(kind, width, width / 3 + 1, spp);
}

// Edge values of every argument first (zero, all ones, the bounce and dimension field limits,
// dimensions beyond 255 that the mask must fold), then uniformly random keys.
std::vector<RngInput> makeRngInputs(std::size_t count) {
    const std::uint32_t edges[] = {0u,        1u,         255u,        256u,
                                   0xffffffu, 0x1000000u, 0x7fffffffu, 0xffffffffu};
    std::vector<RngInput> inputs;
    for (std::uint32_t a : edges) {
        for (std::uint32_t b : edges) {
            const std::uint32_t width = (b & 0x1ffffu) + 1u;
            const std::uint32_t i = std::uint32_t(inputs.size());
            inputs.push_back({a, b, a ^ b, b, a, samplerSetupFor(i, width, a | 1u), width, 0});
        }
    }
    std::mt19937 random(20240611u);
    const auto next = [&random](std::uint32_t bound) {
        return static_cast<std::uint32_t>(random() % bound); // mt19937 words are 32-bit
    };
    while (inputs.size() < count) {
        const std::uint32_t width = next(1u << next(18u)) + 1u;
        const std::uint32_t setup =
            samplerSetupFor(std::uint32_t(inputs.size()), width, next(0xffffffffu) + 1u);
        inputs.push_back({next(0xffffffffu), next(0xffffffffu), next(4096u), next(64u), next(300u),
                          setup, width, 0});
    }
    return inputs;
}

class RngKernel : public GpuTest {};

TEST_F(RngKernel, BitsAndFloatsMatchCpuExactly) {
    constexpr std::uint32_t kCount = 1u << 17; // 131072 keys
    const std::vector<RngInput> inputs = makeRngInputs(kCount);
    const Buffer rngInputs = makeStorageBuffer("rngInputs", std::span<const RngInput>(inputs));
    const Buffer rngOutputs = makeStorageBuffer("rngOutputs", kCount * sizeof(RngOutput));
    const Kernel kernel = makeKernel("run_rng", 2, sizeof(std::uint32_t));
    runKernel(kernel, {&rngInputs, &rngOutputs}, kCount, pushConstantBytes(kCount));
    const auto outputs = download<RngOutput>(context(), rngOutputs, kCount);

    std::size_t bitMismatches = 0;
    std::size_t floatMismatches = 0;
    std::size_t sampledMismatches = 0;
    for (std::uint32_t i = 0; i < kCount; ++i) {
        const RngInput& k = inputs[i];
        const gpu::uvec4 bits =
            gpu::randomBits(k.seed, k.pixel, k.sampleIndex, k.bounce, k.dimension);
        const gpu::vec4 floats =
            gpu::randomFloats(k.seed, k.pixel, k.sampleIndex, k.bounce, k.dimension);
        const gpu::vec4 sampled = gpu::sampleFloats(k.samplerSetup, k.width, k.seed, k.pixel,
                                                    k.sampleIndex, k.bounce, k.dimension);
        for (int c = 0; c < 4; ++c) {
            if (std::bit_cast<std::uint32_t>(outputs[i].sampled[c]) !=
                    std::bit_cast<std::uint32_t>(sampled[c]) &&
                sampledMismatches++ < 5) {
                ADD_FAILURE() << "key " << i << " sampled " << c << ": device "
                              << outputs[i].sampled[c] << ", C++ " << sampled[c];
            }
            const bool bitsEqual = outputs[i].bits[c] == bits[c];
            const bool floatsEqual = std::bit_cast<std::uint32_t>(outputs[i].floats[c]) ==
                                     std::bit_cast<std::uint32_t>(floats[c]);
            if (!bitsEqual && bitMismatches++ < 5) {
                ADD_FAILURE() << "key " << i << " word " << c << ": device " << outputs[i].bits[c]
                              << ", C++ " << bits[c];
            }
            if (!floatsEqual && floatMismatches++ < 5) {
                ADD_FAILURE() << "key " << i << " float " << c << ": device "
                              << outputs[i].floats[c] << ", C++ " << floats[c];
            }
        }
    }
    EXPECT_EQ(bitMismatches, 0u);
    EXPECT_EQ(floatMismatches, 0u);
    EXPECT_EQ(sampledMismatches, 0u);
}

} // namespace
} // namespace vkpt::test::rng_kernel_test
