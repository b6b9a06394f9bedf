// sampler_test.cpp — the default sampler (shared/sampler.h): each half of a pixel's samples
// (even and odd indices) is stratified in every 2-D pair the renderers use, 2×2 quads of pixels
// together form a larger net (the blue-noise layout), samples past a pixel's block stay
// stratified and uniform, and distinct pixels, seeds, dimensions and halves are uncorrelated.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../support/nets.h"
#include "shared/sampler.h"

namespace vkpt::sampler_test {
namespace {

constexpr std::uint32_t kWidth = 128, kHeight = 96;

std::uint32_t sobolSetup(std::uint32_t spp) {
    return gpu::makeSamplerSetup(SAMPLER_SOBOL, kWidth, kHeight, spp);
}

// Pair 0 (.xy) or pair 1 (.zw) of samples first + stride·i, i < count, of pixel (x, y). A stride
// of 2 from first = h walks half h of the samples.
std::vector<glm::uvec2> pairPoints(std::uint32_t setup, std::uint32_t seed, std::uint32_t x,
                                   std::uint32_t y, std::uint32_t first, std::uint32_t count,
                                   std::uint32_t bounce, std::uint32_t dimension,
                                   std::uint32_t pair, std::uint32_t stride = 2) {
    std::vector<glm::uvec2> points;
    for (std::uint32_t i = 0; i < count; ++i) { // the last index may wrap to 0
        const std::uint32_t s = first + stride * i;
        glm::vec4 u = gpu::sampleFloats(setup, kWidth, seed, y * kWidth + x, s, bounce, dimension);
        points.emplace_back(test::unitFloatBits(u[int(2 * pair)]),
                            test::unitFloatBits(u[int(2 * pair + 1)]));
    }
    return points;
}

// The (bounce, dimension) pairs the integrators read (docs/integrator.md), and a few far ones.
struct Dimension {
    std::uint32_t bounce, dimension;
};
const Dimension kDimensions[] = {
    {0, DIM_CAMERA},          {0, DIM_BSDF}, {0, DIM_LIGHT_FIRST}, {3, DIM_BSDF},
    {3, DIM_LIGHT_FIRST + 5}, {1000, 200},   {1u << 22, 7}};

TEST(Sampler, SetupFollowsImageAndSampleCount) {
    const std::uint32_t setup = sobolSetup(64);
    EXPECT_EQ(gpu::samplerKind(setup), SAMPLER_SOBOL);
    EXPECT_EQ(gpu::samplerMortonBits(setup), 7u); // 128 wide
    EXPECT_EQ(gpu::samplerBlockBits(setup), 5u);  // 32 samples per half
    EXPECT_EQ(gpu::samplerBlockBits(sobolSetup(65)), 6u);
    EXPECT_EQ(gpu::samplerBlockBits(sobolSetup(1u << 20)), 18u); // 32 - 2·7 bits left
    const std::uint32_t huge = gpu::makeSamplerSetup(SAMPLER_SOBOL, 200000, 3, 0xffffffffu);
    EXPECT_EQ(gpu::samplerMortonBits(huge), 16u);
    EXPECT_EQ(gpu::samplerBlockBits(huge), 0u);
    EXPECT_EQ(gpu::samplerBlockBits(gpu::makeSamplerSetup(SAMPLER_SOBOL, 1, 1, 0xffffffffu)), 31u);
}

TEST(Sampler, IndependentKindIsRngFloats) {
    const std::uint32_t setup = gpu::makeSamplerSetup(SAMPLER_INDEPENDENT, kWidth, kHeight, 64);
    for (std::uint32_t i = 0; i < 1000; ++i)
        EXPECT_EQ(gpu::sampleFloats(setup, kWidth, 9, i * 7, i, i % 5, i % 3),
                  gpu::randomFloats(9, i * 7, i, i % 5, i % 3));
}

// The first 2^k samples of each half of a pixel (every k up to the block) are a net in each
// pair, for any seed.
TEST(Sampler, EachPixelsSamplesAreStratifiedInEveryPair) {
    const std::uint32_t setup = sobolSetup(256);
    for (const Dimension& d : kDimensions)
        for (std::uint32_t pair = 0; pair < 2; ++pair)
            for (std::uint32_t k = 0; k <= 7; ++k)
                for (std::uint32_t seed : {0u, 12345u})
                    for (std::uint32_t half = 0; half < 2; ++half) {
                        EXPECT_EQ(test::netDefect(pairPoints(setup, seed, 37, 61, half, 1u << k,
                                                             d.bounce, d.dimension, pair)),
                                  "")
                            << "bounce " << d.bounce << " dimension " << d.dimension << " pair "
                            << pair << " first 2^" << k << " seed " << seed << " half " << half;
                    }
}

// At spp = 2^(b+1) the pixels of an aligned 2×2 (4×4) quad hold together, in each half, an
// aligned run of the half's sequence: a (0, b+2, 2)-net (a (0, b+4, 2)-net), which is what
// spreads the error as blue noise.
TEST(Sampler, AlignedPixelQuadsTogetherFormNets) {
    const std::uint32_t spp = 16, setup = sobolSetup(spp);
    for (const Dimension& d : kDimensions)
        for (std::uint32_t pair = 0; pair < 2; ++pair)
            for (std::uint32_t side : {2u, 4u})
                for (std::uint32_t corner : {0u, 8u, 44u})
                    for (std::uint32_t half = 0; half < 2; ++half) {
                        std::vector<glm::uvec2> points;
                        for (std::uint32_t y = corner; y < corner + side; ++y)
                            for (std::uint32_t x = corner; x < corner + side; ++x) {
                                auto own = pairPoints(setup, 3, x, y, half, spp / 2, d.bounce,
                                                      d.dimension, pair);
                                points.insert(points.end(), own.begin(), own.end());
                            }
                        EXPECT_EQ(test::netDefect(points), "")
                            << "bounce " << d.bounce << " dimension " << d.dimension << " pair "
                            << pair << " quad " << side << " at " << corner << " half " << half;
                    }
}

// Samples past the pixel's block (--resume to a larger --spp, 2^20 spp and more): each further
// block is again a net, up to the last block before the sample index wraps.
TEST(Sampler, BlocksPastTheFirstAreNetsToo) {
    const std::uint32_t setup = sobolSetup(64); // blocks of 32 samples of each half
    for (std::uint32_t block : {1u, 2u, 1000u, (1u << 26) - 1u})
        for (std::uint32_t pair = 0; pair < 2; ++pair)
            for (std::uint32_t half = 0; half < 2; ++half)
                EXPECT_EQ(test::netDefect(pairPoints(setup, 5, 100, 90, half + block * 64, 32, 2,
                                                     DIM_BSDF, pair)),
                          "")
                    << "block " << block << " pair " << pair << " half " << half;
}

// Far past the block the numbers stay uniform: the mean of 2^18 draws from sample indices
// near 2^31 is within 5 standard errors of 1/2 (independent draws' standard error
// sqrt(1/12 / n); stratified blocks only lower it).
TEST(Sampler, FarPastTheBlockNumbersStayUniform) {
    const std::uint32_t setup = sobolSetup(64), n = 1u << 18;
    double sum[4] = {0, 0, 0, 0};
    for (std::uint32_t s = 0; s < n; ++s) {
        glm::vec4 u = gpu::sampleFloats(setup, kWidth, 1, 4321, 0x80000000u + s * 4099u, 1, 2);
        for (int c = 0; c < 4; ++c)
            sum[c] += u[c];
    }
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(sum[c] / n, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n)) << "component " << c;
}

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    const double n = double(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        sa += a[i];
        sb += b[i];
        saa += a[i] * a[i];
        sbb += b[i] * b[i];
        sab += a[i] * b[i];
    }
    const double cov = sab / n - sa / n * sb / n;
    return cov / std::sqrt((saa / n - sa / n * sa / n) * (sbb / n - sb / n * sb / n));
}

// Pearson correlation between the first sample of every pixel and (a) the same pixel at
// another seed, (b) the pixel half an image to the right, (c) the same sample's other pair and
// a later bounce's pair, (d) the first sample of the other half. 12,288 pixels give a standard
// error of 1/sqrt(n) ≈ 0.009 for independent values; 5 standard errors bound each.
TEST(Sampler, SeedsPixelsAndDimensionsAreUncorrelated) {
    const std::uint32_t setup = sobolSetup(16);
    std::vector<double> base, otherSeed, farPixel, otherPair, laterBounce, otherHalf;
    for (std::uint32_t y = 0; y < kHeight; ++y)
        for (std::uint32_t x = 0; x < kWidth; ++x) {
            const std::uint32_t pixel = y * kWidth + x;
            const std::uint32_t far = y * kWidth + (x + kWidth / 2) % kWidth;
            glm::vec4 u = gpu::sampleFloats(setup, kWidth, 3, pixel, 0, 0, DIM_BSDF);
            base.push_back(u.x);
            otherSeed.push_back(gpu::sampleFloats(setup, kWidth, 4, pixel, 0, 0, DIM_BSDF).x);
            farPixel.push_back(gpu::sampleFloats(setup, kWidth, 3, far, 0, 0, DIM_BSDF).x);
            otherPair.push_back(u.z);
            laterBounce.push_back(gpu::sampleFloats(setup, kWidth, 3, pixel, 0, 1, DIM_BSDF).x);
            // Sample 1, the odd half's first: in one sequence it would be sample 0's partner
            // in the other half of [0, 1) (a correlation near −1/2).
            otherHalf.push_back(gpu::sampleFloats(setup, kWidth, 3, pixel, 1, 0, DIM_BSDF).x);
        }
    const double bound = 5.0 / std::sqrt(double(base.size()));
    EXPECT_LT(std::abs(pearson(base, otherSeed)), bound);
    EXPECT_LT(std::abs(pearson(base, farPixel)), bound);
    EXPECT_LT(std::abs(pearson(base, otherPair)), bound);
    EXPECT_LT(std::abs(pearson(base, laterBounce)), bound);
    EXPECT_LT(std::abs(pearson(base, otherHalf)), bound);
}

// Within one pixel, two pairs of a sample are not the same net in another order: over the
// pixel's 1024 samples the pairs' x coordinates are uncorrelated (5 standard errors, 0.16).
TEST(Sampler, PairsOfOnePixelAreUncorrelated) {
    const std::uint32_t setup = sobolSetup(1024);
    std::vector<double> a, b, c;
    for (std::uint32_t s = 0; s < 1024; ++s) {
        glm::vec4 u = gpu::sampleFloats(setup, kWidth, 8, 777, s, 2, DIM_BSDF);
        a.push_back(u.x);
        b.push_back(u.z);
        c.push_back(gpu::sampleFloats(setup, kWidth, 8, 777, s, 2, DIM_LIGHT_FIRST).x);
    }
    EXPECT_LT(std::abs(pearson(a, b)), 5.0 / 32.0);
    EXPECT_LT(std::abs(pearson(a, c)), 5.0 / 32.0);
}

// The light sample's numbers: the stratified pair goes to the point (u.yz), the emitter gets
// the other pair's first number.
TEST(Sampler, LightSampleOrderPutsThePairOnThePoint) {
    const glm::vec4 u(0.1f, 0.2f, 0.3f, 0.4f);
    EXPECT_EQ(gpu::lightSampleOrder(u), glm::vec4(0.3f, 0.1f, 0.2f, 0.4f));
}

// The Fisher–Yates shuffle the table holds: swaps drawn from choice mod 4, then mod 3 and mod 2
// of what is left, on four 2-bit fields that start as the identity.
std::uint32_t shuffledDigit(std::uint32_t digit, std::uint32_t choice) {
    std::uint32_t fields = 0xe4u;
    for (std::uint32_t i = 3; i > 0; --i) {
        const std::uint32_t j = choice % (i + 1);
        choice /= i + 1;
        const std::uint32_t differ = ((fields >> (2 * i)) ^ (fields >> (2 * j))) & 3u;
        fields ^= (differ << (2 * i)) | (differ << (2 * j));
    }
    return (fields >> (2 * digit)) & 3u;
}

TEST(Sampler, TheDigitPermutationTableIsTheFisherYatesShuffle) {
    std::mt19937 random(24);
    for (std::uint32_t n = 0; n < 100000; ++n) {
        const std::uint32_t choice = n < 48 ? n : std::uint32_t(random());
        std::uint32_t seen = 0;
        for (std::uint32_t digit = 0; digit < 4; ++digit) {
            ASSERT_EQ(gpu::permuteBase4Digit(digit, choice), shuffledDigit(digit, choice))
                << "choice " << choice << ", digit " << digit;
            seen |= 1u << gpu::permuteBase4Digit(digit, choice);
        }
        ASSERT_EQ(seen, 15u) << "choice " << choice << " is not a permutation";
    }
}

} // namespace
} // namespace vkpt::sampler_test
