// sampling_test.cpp — the shared warps: each pdf integrates to 1 and each sampler draws from
// its pdf by a chi-square test (alpha = 0.01 per test), plus the basis and MIS helpers.
#include <gtest/gtest.h>

#include "../support/chi_square.h"
#include "common/math_constants.h"
#include "shared/rng.h"
#include "shared/sampling.h"

namespace vkpt::sampling_test {
namespace {

constexpr double kAlpha = 0.01;

// Bins over (z = cos θ, φ) of the hemisphere, with dω = dz dφ.
struct HemisphereHistogram {
    int zBins = 16, phiBins = 32;
    std::vector<double> counts = std::vector<double>(size_t(zBins * phiBins), 0.0);

    void add(const glm::vec3& d) {
        double phi = std::atan2(double(d.y), double(d.x));
        if (phi < 0) phi += 2 * kPi;
        int zi = std::min(zBins - 1, int(double(d.z) * zBins));
        int pi = std::min(phiBins - 1, int(phi / (2 * kPi) * phiBins));
        counts[size_t(zi * phiBins + pi)] += 1.0;
    }

    // expected[i] = n ∫_bin pdf dω for a pdf of z alone, integrated over z by its antiderivative.
    template <typename ZIntegral>
    std::vector<double> expected(double n, ZIntegral integralOverZ) const {
        std::vector<double> e(counts.size());
        for (int zi = 0; zi < zBins; ++zi)
            for (int pi = 0; pi < phiBins; ++pi)
                e[size_t(zi * phiBins + pi)] =
                    n * integralOverZ(double(zi) / zBins, double(zi + 1) / zBins) *
                    (2 * kPi / phiBins);
        return e;
    }
};

TEST(Sampling, CosineHemisphereMatchesItsPdfByChiSquare) {
    const int n = 200000;
    HemisphereHistogram h;
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        glm::vec4 u = gpu::randomFloats(1, i, 0, 0, DIM_BSDF);
        h.add(gpu::sampleCosineHemisphere(glm::vec2(u.x, u.y)));
    }
    // ∫ z/π dz = (z1² − z0²) / (2π)
    auto e = h.expected(n, [](double z0, double z1) { return (z1 * z1 - z0 * z0) / (2 * kPi); });
    test::ChiSquareResult r = test::chiSquareTest(h.counts, e);
    EXPECT_GT(r.pValue, kAlpha) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
}

TEST(Sampling, UniformHemisphereMatchesItsPdfByChiSquare) {
    const int n = 200000;
    HemisphereHistogram h;
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        glm::vec4 u = gpu::randomFloats(2, i, 0, 0, DIM_BSDF);
        h.add(gpu::sampleUniformHemisphere(glm::vec2(u.x, u.y)));
    }
    auto e = h.expected(n, [](double z0, double z1) { return (z1 - z0) / (2 * kPi); });
    test::ChiSquareResult r = test::chiSquareTest(h.counts, e);
    EXPECT_GT(r.pValue, kAlpha) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
}

// Midpoint rule over (θ, φ) with dω = sin θ dθ dφ; 512² cells give ~1e-5 accuracy.
template <typename Pdf> double integrateOverHemisphere(Pdf pdf) {
    const int steps = 512;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        double theta = (i + 0.5) / steps * kPi / 2;
        sum += double(pdf(float(std::cos(theta)))) * std::sin(theta) * (kPi / 2 / steps) * 2 * kPi;
    }
    return sum;
}

TEST(Sampling, HemispherePdfsIntegrateToOne) {
    EXPECT_NEAR(integrateOverHemisphere([](float c) { return gpu::cosineHemispherePdf(c); }), 1.0,
                1e-4);
    EXPECT_NEAR(integrateOverHemisphere([](float) { return gpu::uniformHemispherePdf(); }), 1.0,
                1e-4);
}

TEST(Sampling, SampledDirectionsAreUnitAndInTheUpperHemisphere) {
    for (uint32_t i = 0; i < 10000; ++i) {
        glm::vec4 u = gpu::randomFloats(3, i, 0, 0, DIM_BSDF);
        glm::vec3 c = gpu::sampleCosineHemisphere(glm::vec2(u.x, u.y));
        glm::vec3 h = gpu::sampleUniformHemisphere(glm::vec2(u.x, u.y));
        EXPECT_NEAR(glm::length(c), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(h), 1.0f, 1e-5f);
        EXPECT_GE(c.z, 0.0f);
        EXPECT_GE(h.z, 0.0f);
    }
}

// The unit right triangle x + y <= 1 on an n × n grid: cells below the diagonal are inside,
// cells the diagonal cuts through their corners are half inside, so expected counts are exact.
TEST(Sampling, TriangleBarycentricsAreUniformByChiSquare) {
    const int n = 200000, grid = 24;
    std::vector<double> observed(size_t(grid * grid), 0.0), expected(observed.size(), 0.0);
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        glm::vec4 u = gpu::randomFloats(4, i, 0, 0, DIM_LIGHT_FIRST);
        glm::vec3 b = gpu::sampleTriangleBarycentrics(glm::vec2(u.y, u.z));
        ASSERT_NEAR(b.x + b.y + b.z, 1.0f, 1e-6f);
        int xi = std::min(grid - 1, int(b.y * grid)), yi = std::min(grid - 1, int(b.z * grid));
        observed[size_t(yi * grid + xi)] += 1.0;
    }
    const double cellShare = 2.0 / (grid * grid); // cell area / triangle area 1/2
    for (int y = 0; y < grid; ++y)
        for (int x = 0; x < grid; ++x)
            expected[size_t(y * grid + x)] = x + y < grid - 1    ? n * cellShare
                                             : x + y == grid - 1 ? n * cellShare / 2
                                                                 : 0.0;
    test::ChiSquareResult r = test::chiSquareTest(observed, expected);
    EXPECT_GT(r.pValue, kAlpha) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
}

TEST(Sampling, BasisIsOrthonormalAndRightHanded) {
    for (uint32_t i = 0; i < 10000; ++i) {
        glm::vec4 u = gpu::randomFloats(5, i, 0, 0, DIM_BSDF);
        float z = 2.0f * u.x - 1.0f, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        float phi = 2.0f * float(kPi) * u.y;
        glm::vec3 n(r * std::cos(phi), r * std::sin(phi), z);
        if (i == 0) n = glm::vec3(0, 0, -1); // Frisvad's singularity, which Duff et al. remove
        gpu::Basis b = gpu::makeBasis(n);
        EXPECT_NEAR(glm::dot(b.tangent, b.bitangent), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(b.tangent, n), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::length(b.tangent), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(b.bitangent), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(glm::cross(b.tangent, b.bitangent), n), 0.999f);
    }
}

TEST(Sampling, PowerHeuristicWeightsSumToOne) {
    EXPECT_FLOAT_EQ(gpu::powerHeuristic(1, 0.3f, 4, 0.7f) + gpu::powerHeuristic(4, 0.7f, 1, 0.3f),
                    1.0f);
    EXPECT_EQ(gpu::powerHeuristic(1, 0.5f, 0, 0.9f), 1.0f); // no competing samples
    EXPECT_EQ(gpu::powerHeuristic(1, 0.0f, 1, 0.0f), 0.0f);
}

} // namespace
} // namespace vkpt::sampling_test
