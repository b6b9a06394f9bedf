// rng_test.cpp — the counter-based generator: a pure function of its key, uniform, and with
// no visible correlation between neighbouring keys.
#include <gtest/gtest.h>

#include <set>

#include "../support/chi_square.h"
#include "shared/rng.h"

namespace vkpt::rng_test {
namespace {

TEST(Rng, SameKeyGivesSameNumbers) {
    for (uint32_t i = 0; i < 1000; ++i) {
        EXPECT_EQ(gpu::randomBits(7, i, i * 3, i % 17, i % 5),
                  gpu::randomBits(7, i, i * 3, i % 17, i % 5));
    }
}

TEST(Rng, EveryKeyFieldChangesTheOutput) {
    const glm::uvec4 base = gpu::randomBits(1, 2, 3, 4, 5);
    EXPECT_NE(base, gpu::randomBits(2, 2, 3, 4, 5));
    EXPECT_NE(base, gpu::randomBits(1, 3, 3, 4, 5));
    EXPECT_NE(base, gpu::randomBits(1, 2, 4, 4, 5));
    EXPECT_NE(base, gpu::randomBits(1, 2, 3, 5, 5));
    EXPECT_NE(base, gpu::randomBits(1, 2, 3, 4, 6));
}

TEST(Rng, NoCollisionsOverNeighbouringKeys) {
    std::set<uint32_t> seen;
    for (uint32_t pixel = 0; pixel < 256; ++pixel)
        for (uint32_t sample = 0; sample < 256; ++sample)
            seen.insert(gpu::randomBits(0, pixel, sample, 0, 0).x);
    // 65,536 uniform draws from 2^32 values give n²/2^33 = 0.5 collisions on average; more
    // than 3 has a Poisson probability below 0.2 %.
    EXPECT_GE(seen.size(), 65536u - 3u);
}

TEST(Rng, UnitFloatsStayBelowOne) {
    EXPECT_LT(gpu::bitsToUnitFloat(0xffffffffu), 1.0f);
    EXPECT_EQ(gpu::bitsToUnitFloat(0u), 0.0f);
}

// Chi-square over 64 bins for each of the four output words, keys varying in the sample index
// (the way a pixel consumes them). alpha = 0.01 per word, Bonferroni over 4 words.
TEST(Rng, FloatsAreUniformByChiSquare) {
    const int bins = 64, draws = 200000;
    for (int word = 0; word < 4; ++word) {
        std::vector<double> observed(bins, 0.0), expected(bins, double(draws) / bins);
        for (uint32_t i = 0; i < uint32_t(draws); ++i) {
            glm::vec4 u = gpu::randomFloats(42, 1234, i, 2, DIM_BSDF);
            observed[size_t(u[word] * bins)] += 1.0;
        }
        test::ChiSquareResult r = test::chiSquareTest(observed, expected);
        EXPECT_GT(r.pValue, 0.01 / 4) << "word " << word << " chi2 " << r.statistic;
    }
}

// Pairs of consecutive pixels must look independent: Pearson correlation of 10^5 pairs has a
// standard error of 1/sqrt(n) ≈ 0.0032; 5 standard errors bound it.
TEST(Rng, NeighbouringPixelsAreUncorrelated) {
    const int n = 100000;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        double x = gpu::randomFloats(3, i, 0, 0, DIM_CAMERA).x;
        double y = gpu::randomFloats(3, i + 1, 0, 0, DIM_CAMERA).x;
        sx += x;
        sy += y;
        sxx += x * x;
        syy += y * y;
        sxy += x * y;
    }
    double cov = sxy / n - (sx / n) * (sy / n);
    double corr =
        cov / std::sqrt((sxx / n - (sx / n) * (sx / n)) * (syy / n - (sy / n) * (sy / n)));
    EXPECT_LT(std::abs(corr), 5.0 / std::sqrt(double(n)));
}

} // namespace
} // namespace vkpt::rng_test
