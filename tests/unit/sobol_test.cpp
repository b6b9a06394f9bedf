// sobol_test.cpp — the two-dimensional Sobol sequence of shared/sobol.h: its direction numbers
// are Joe and Kuo's, its aligned runs are (0,m,2)-nets, and Owen scrambling keeps them nets.
#include <gtest/gtest.h>

#include <random>

#include "../support/nets.h"
#include "shared/sobol.h"

namespace vkpt::sobol_test {
namespace {

// Dimension 1 from its direction numbers, as Bratley and Fox's recurrence builds them from Joe
// and Kuo's parameters for it (s = 1, a = 0, m_1 = 1): m_k = 2·m_(k-1) XOR m_(k-1),
// v_k = m_k · 2^(31-k).
std::uint32_t secondDimensionFromDirections(std::uint32_t index) {
    std::uint32_t value = 0, m = 1;
    for (std::uint32_t k = 0; k < 32; ++k) {
        if (k > 0) m = (m << 1u) ^ m;
        if ((index >> k) & 1u) value ^= m << (31u - k);
    }
    return value;
}

TEST(Sobol, DirectionNumbersAreJoeKuos) {
    // The first m_k of the recurrence: the rows of Pascal's triangle mod 2 read in binary.
    const std::uint32_t m[] = {1, 3, 5, 15, 17, 51, 85, 255, 257};
    for (std::uint32_t k = 0; k < 9; ++k)
        EXPECT_EQ(gpu::sobolPoint(1u << k).y, m[k] << (31u - k)) << "direction " << k;
    std::mt19937 random(5u);
    for (int i = 0; i < 100000; ++i) {
        const auto index = static_cast<std::uint32_t>(random());
        ASSERT_EQ(gpu::sobolPoint(index).y, secondDimensionFromDirections(index)) << index;
        ASSERT_EQ(gpu::sobolPoint(index).x, gpu::bitfieldReverse(index)) << index;
    }
}

std::vector<glm::uvec2> sobolRun(std::uint32_t first, std::uint32_t count) {
    std::vector<glm::uvec2> points;
    for (std::uint32_t i = 0; i < count; ++i)
        points.push_back(gpu::sobolPoint(first + i));
    return points;
}

TEST(Sobol, AlignedRunsAreNets) {
    for (std::uint32_t m = 0; m <= 14; ++m) {
        EXPECT_EQ(test::netDefect(sobolRun(0, 1u << m)), "") << "first 2^" << m;
        EXPECT_EQ(test::netDefect(sobolRun(7u << m, 1u << m)), "") << "run 7 of 2^" << m;
        EXPECT_EQ(test::netDefect(sobolRun(0xffffffffu << m, 1u << m)), "")
            << "last run of 2^" << m;
    }
}

TEST(Sobol, OwenScramblingKeepsNets) {
    for (std::uint32_t seed : {0u, 1u, 0x9e3779b9u, 0xffffffffu}) {
        for (std::uint32_t m : {4u, 9u, 12u}) {
            std::vector<glm::uvec2> points = sobolRun(3u << m, 1u << m);
            for (glm::uvec2& p : points)
                p = glm::uvec2(gpu::nestedUniformScramble(p.x, seed),
                               gpu::nestedUniformScramble(p.y, gpu::pcgHash(seed)));
            EXPECT_EQ(test::netDefect(points), "") << "seed " << seed << ", 2^" << m;
        }
    }
}

// The scramble really moves points: two seeds agree on fewer than 1 % of the first points.
TEST(Sobol, OwenScramblingDependsOnTheSeed) {
    int same = 0;
    for (std::uint32_t i = 0; i < 4096; ++i) {
        const std::uint32_t x = gpu::sobolPoint(i).x;
        same += gpu::nestedUniformScramble(x, 1u) == gpu::nestedUniformScramble(x, 2u);
    }
    EXPECT_LT(same, 41);
}

// The nested uniform shuffle of an index maps each aligned run of 2^m indices onto one aligned
// run, bijectively: bit k is flipped by the bits above k only, so the bits above m move
// together (sampler.h keeps only the low bits of the shuffle).
TEST(Sobol, NestedUniformShuffleKeepsAlignedRuns) {
    for (std::uint32_t m : {1u, 5u, 10u}) {
        for (std::uint32_t run : {0u, 1u, 12345u}) {
            std::vector<bool> seen(std::size_t(1) << m, false);
            const std::uint32_t target = gpu::nestedUniformScramble(run << m, 77u) >> m;
            for (std::uint32_t i = 0; i < (1u << m); ++i) {
                const std::uint32_t shuffled = gpu::nestedUniformScramble((run << m) | i, 77u);
                ASSERT_EQ(shuffled >> m, target) << "2^" << m << " run " << run;
                seen[shuffled & ((1u << m) - 1u)] = true;
            }
            for (bool s : seen)
                ASSERT_TRUE(s) << "2^" << m << " run " << run << ": not a permutation";
        }
    }
}

} // namespace
} // namespace vkpt::sobol_test
