// sampling_kernel_test.cpp — shared/sampling.h on the device agrees with its C++ build within
// float tolerances that follow from what Vulkan allows a device to do differently:
//  * arithmetic and sqrt: the device may fuse multiply-adds (lavapipe compiles through LLVM,
//    GPUs have FMA units) and Vulkan allows sqrt and division a few ULP of error, so outputs of
//    magnitude ~1 may differ by a few 1e-7; we allow 1e-5 · max(1, |x|).
//  * sin and cos: Vulkan only requires an absolute error of 2^-11 (on [-π, π]), and the warps
//    take sin/cos of 2π·u ∈ [0, 2π); outputs that go through them get 2^-11 + 1e-5.
// The largest differences seen are printed, so a tighter device shows how much tighter.
#include "gpu_test_support.h"
#include "kernel_test_io.h"
#include "shared/sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace vkpt::test::sampling_kernel_test {
namespace {

using gpu::test::SamplingInput;
using gpu::test::SamplingOutput;

constexpr double kArithmeticTolerance = 1e-5;
constexpr double kSinCosTolerance = 1.0 / 2048.0 + 1e-5;

gpu::vec3 randomUnitVector(std::mt19937& random) {
    std::normal_distribution<float> normal;
    gpu::vec3 v(normal(random), normal(random), normal(random));
    return glm::normalize(v);
}

// Samples include the ends of [0, 1) and normals include the poles, the equator and the
// neighbourhood of n.z = -1, where Frisvad's basis (but not Duff's) breaks down.
std::vector<SamplingInput> makeSamplingInputs(std::size_t count) {
    std::mt19937 random(7u);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float uEdges[] = {0.0f, 0.5f, 0x1.fffffep-1f};
    const gpu::vec3 normalEdges[] = {
        {0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, glm::normalize(gpu::vec3(1e-4f, 0, -1))};
    std::vector<SamplingInput> inputs;
    for (float ux : uEdges) {
        for (float uy : uEdges) {
            for (const gpu::vec3& n : normalEdges) {
                inputs.push_back({{ux, uy, 0, 0}, {n, ux}, {1, 0, 1, 0}, {ux, uy, 1, 0}});
            }
        }
    }
    while (inputs.size() < count) {
        const gpu::vec4 u(unit(random), unit(random), 0, 0);
        const gpu::vec3 n = randomUnitVector(random);
        const gpu::vec4 mis(1.0f + std::floor(4 * unit(random)), 10 * unit(random),
                            1.0f + std::floor(4 * unit(random)), 10 * unit(random));
        const gpu::vec4 color(10 * unit(random), 10 * unit(random), 10 * unit(random), 0);
        inputs.push_back({u, {n, 2 * unit(random) - 1}, mis, color});
    }
    return inputs;
}

SamplingOutput computeOnCpu(const SamplingInput& s) {
    const gpu::vec3 cosineDirection = gpu::sampleCosineHemisphere(gpu::vec2(s.u));
    const gpu::Basis basis = gpu::makeBasis(gpu::vec3(s.normal));
    SamplingOutput o;
    o.cosineDirection = {cosineDirection, gpu::cosineHemispherePdf(s.normal.w)};
    o.uniformDirection = {gpu::sampleUniformHemisphere(gpu::vec2(s.u)),
                          gpu::uniformHemispherePdf()};
    o.barycentrics = {gpu::sampleTriangleBarycentrics(gpu::vec2(s.u)),
                      gpu::luminance(gpu::vec3(s.color))};
    o.tangent = {basis.tangent, gpu::powerHeuristic(s.mis.x, s.mis.y, s.mis.z, s.mis.w)};
    o.bitangent = {basis.bitangent, 0.0f};
    o.worldDirection = {gpu::basisToWorld(basis, cosineDirection), 0.0f};
    return o;
}

// One output vector: which components go through sin/cos, and the largest error seen.
struct Field {
    const char* name;
    gpu::vec4 SamplingOutput::*member;
    int sinCosComponents; // components [0, n) depend on sin/cos
    double worstError = 0.0;
};

class SamplingKernel : public GpuTest {};

TEST_F(SamplingKernel, WarpsMatchCpuWithinTolerance) {
    constexpr std::uint32_t kCount = 1u << 16;
    const std::vector<SamplingInput> inputs = makeSamplingInputs(kCount);
    const Buffer samplingInputs =
        makeStorageBuffer("samplingInputs", std::span<const SamplingInput>(inputs));
    const Buffer samplingOutputs =
        makeStorageBuffer("samplingOutputs", kCount * sizeof(SamplingOutput));
    const Kernel kernel = makeKernel("run_sampling", 2, sizeof(std::uint32_t));
    runKernel(kernel, {&samplingInputs, &samplingOutputs}, kCount, pushConstantBytes(kCount));
    const auto outputs = download<SamplingOutput>(context(), samplingOutputs, kCount);

    Field fields[] = {{"cosineDirection", &SamplingOutput::cosineDirection, 2},
                      {"uniformDirection", &SamplingOutput::uniformDirection, 2},
                      {"barycentrics", &SamplingOutput::barycentrics, 0},
                      {"tangent", &SamplingOutput::tangent, 0},
                      {"bitangent", &SamplingOutput::bitangent, 0},
                      {"worldDirection", &SamplingOutput::worldDirection, 3}};
    std::size_t failures = 0;
    for (std::uint32_t i = 0; i < kCount; ++i) {
        const SamplingOutput expected = computeOnCpu(inputs[i]);
        for (Field& field : fields) {
            for (int c = 0; c < 4; ++c) {
                const double cpu = (expected.*field.member)[c];
                const double device = (outputs[i].*field.member)[c];
                const double error = std::abs(device - cpu);
                const double tolerance = c < field.sinCosComponents
                                             ? kSinCosTolerance
                                             : kArithmeticTolerance * std::max(1.0, std::abs(cpu));
                field.worstError = std::max(field.worstError, error);
                if (error > tolerance && failures++ < 10) {
                    ADD_FAILURE() << "input " << i << ": " << field.name << "[" << c << "] device "
                                  << device << ", C++ " << cpu;
                }
            }
        }
    }
    for (const Field& field : fields) {
        std::printf("%-16s largest |device - C++| = %.3g\n", field.name, field.worstError);
    }
    EXPECT_EQ(failures, 0u);
}

} // namespace
} // namespace vkpt::test::sampling_kernel_test
