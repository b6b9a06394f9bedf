// image_compare_test.cpp — the per-pixel z-test on synthetic renders of known mean and
// variance: noise passes at about the promised rate, a biased pixel is found, edge cases are
// rejected with a reason; and the normal quantile behind the critical value.
#include "image/image_compare.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "common/errors.h"

namespace vkpt::image_compare_test {
namespace {

// Standard normal numbers by Box–Muller from mt19937_64, whose output sequence the C++ standard
// fixes (std::normal_distribution's is implementation-defined), so every seed gives the same
// render on every platform.
class Gaussian {
public:
    explicit Gaussian(std::uint64_t seed) : engine_(seed) {}
    double next() {
        const double u1 = uniformOpen(), u2 = uniformOpen();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }

private:
    double uniformOpen() { return (double(engine_() >> 11) + 0.5) * 0x1p-53; } // in (0, 1)
    std::mt19937_64 engine_;
};

using PixelFunction = std::function<double(std::uint32_t x, std::uint32_t y)>;

// A render whose pixel (x, y) averages n samples of N(mean(x, y), sigma(x, y)²), with the
// Welford statistics an accumulator keeps.
RenderOutput syntheticRender(std::uint32_t width, std::uint32_t height, std::uint32_t n,
                             std::uint64_t seed, const PixelFunction& mean,
                             const PixelFunction& sigma) {
    RenderOutput output;
    output.image = Image(width, height);
    Gaussian gaussian(seed);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            double runningMean = 0.0, m2 = 0.0;
            for (std::uint32_t k = 1; k <= n; ++k) {
                const double sample = mean(x, y) + sigma(x, y) * gaussian.next();
                const double delta = sample - runningMean;
                runningMean += delta / k;
                m2 += delta * (sample - runningMean);
            }
            output.image.at(x, y) = glm::vec3(float(runningMean));
            output.sampleCounts.push_back(n);
            output.luminanceMean.push_back(float(runningMean));
            output.luminanceM2.push_back(float(m2));
        }
    return output;
}

double gradientMean(std::uint32_t x, std::uint32_t y) {
    return 0.5 + 0.1 * x + 0.05 * y;
}
double varyingSigma(std::uint32_t x, std::uint32_t y) {
    return 0.2 + 0.03 * ((x + 3 * y) % 7);
}

// Two renders of the same image as two executors would make them: same mean and per-sample
// noise, different seeds and sample counts.
std::pair<RenderOutput, RenderOutput> independentRenders(std::uint64_t seed, std::uint32_t size) {
    return {syntheticRender(size, size, 128, 2 * seed, gradientMean, varyingSigma),
            syntheticRender(size, size, 64, 2 * seed + 1, gradientMean, varyingSigma)};
}

// Pixel statistics set directly, for the rules that do not depend on noise.
RenderOutput constantRender(std::uint32_t width, std::uint32_t height, std::uint32_t n, float mean,
                            float m2) {
    RenderOutput output;
    output.image = Image(width, height);
    const std::size_t pixels = std::size_t(width) * height;
    output.sampleCounts.assign(pixels, n);
    output.luminanceMean.assign(pixels, mean);
    output.luminanceM2.assign(pixels, m2);
    return output;
}

TEST(ZTest, IdenticalImagesPass) {
    const RenderOutput render = independentRenders(7, 16).first;
    const ZTestResult result = zTestPerPixel(render, render);
    EXPECT_TRUE(result.passed) << result.summary;
    EXPECT_EQ(result.rejectedPixels, 0u);
    EXPECT_EQ(result.worstZ, 0.0);
    EXPECT_EQ(result.summary.rfind("z-test passed: 256 pixels, per-pixel p >= ", 0), 0u)
        << result.summary;
}

TEST(ZTest, IndependentRendersOfTheSameImagePass) {
    const auto [a, b] = independentRenders(1, 16);
    const ZTestResult result = zTestPerPixel(a, b, 0.01);
    EXPECT_TRUE(result.passed) << result.summary;
    EXPECT_LE(std::abs(result.worstZ), result.criticalZ);
}

// Under the null hypothesis the test should fail on about alpha of the seeds. Expected failures
// in 200 seeds: 2 at alpha 0.01, 20 at alpha 0.1; the bounds are far in the binomial tails
// (about 1e-4 each), yet would catch a test that never fails or fails too often. (The z
// statistic uses estimated variances, so its tails are a little heavier than the normal's;
// with 64 and 128 samples per pixel that adds well under a quarter to the rate.)
TEST(ZTest, FalseAlarmRateMatchesFamilyAlpha) {
    constexpr int kSeeds = 200;
    int failuresAt001 = 0, failuresAt01 = 0;
    for (int seed = 1000; seed < 1000 + kSeeds; ++seed) {
        const auto [a, b] = independentRenders(std::uint64_t(seed), 8);
        failuresAt001 += zTestPerPixel(a, b, 0.01).passed ? 0 : 1;
        failuresAt01 += zTestPerPixel(a, b, 0.1).passed ? 0 : 1;
    }
    EXPECT_LE(failuresAt001, 9);
    EXPECT_GE(failuresAt01, 8);
    EXPECT_LE(failuresAt01, 37);
    EXPECT_LE(failuresAt001, failuresAt01); // a smaller alpha can only reject less
}

TEST(ZTest, MeanShiftedBySixSigmaInOnePixelIsCaughtAndLocated) {
    constexpr std::uint32_t kX = 5, kY = 11, kSize = 16;
    // Standard deviation of the difference of the two means at (kX, kY).
    const double sigma = varyingSigma(kX, kY);
    const double shift = 6.0 * std::sqrt(sigma * sigma / 128.0 + sigma * sigma / 64.0);
    const auto shiftedMean = [&](std::uint32_t x, std::uint32_t y) {
        return gradientMean(x, y) + (x == kX && y == kY ? shift : 0.0);
    };
    const RenderOutput a = syntheticRender(kSize, kSize, 128, 42, shiftedMean, varyingSigma);
    const RenderOutput b = syntheticRender(kSize, kSize, 64, 43, gradientMean, varyingSigma);
    const ZTestResult result = zTestPerPixel(a, b, 0.01);
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.rejectedPixels, 1u);
    EXPECT_EQ(result.worstX, kX);
    EXPECT_EQ(result.worstY, kY);
    EXPECT_GT(result.worstZ, result.criticalZ);
    EXPECT_NE(result.summary.find("z-test: 1 of 256 pixels differs at per-pixel p < "),
              std::string::npos)
        << result.summary;
    EXPECT_NE(result.summary.find("family alpha 0.01); worst z = "), std::string::npos);
    EXPECT_NE(result.summary.find(" at (5, 11)"), std::string::npos) << result.summary;
}

TEST(ZTest, ZeroVarianceOnBothSidesRequiresEqualMeans) {
    const RenderOutput one = constantRender(4, 4, 16, 1.0f, 0.0f);
    EXPECT_TRUE(zTestPerPixel(one, one).passed);
    EXPECT_TRUE(zTestPerPixel(one, constantRender(4, 4, 9, 1.000005f, 0.0f)).passed);
    const RenderOutput black = constantRender(4, 4, 16, 0.0f, 0.0f);
    EXPECT_TRUE(zTestPerPixel(black, constantRender(4, 4, 16, 5e-8f, 0.0f)).passed);

    const ZTestResult result = zTestPerPixel(one, constantRender(4, 4, 16, 1.001f, 0.0f));
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.rejectedPixels, 16u);
    EXPECT_EQ(result.summary, "z-test: 16 of 16 pixels have zero variance in both images but "
                              "different means (first at (0, 0))");
}

TEST(ZTest, ZeroVarianceOnOneSideUsesTheOthersVariance) {
    // b: variance of the mean 0.04 / 4 = 0.01, so a difference of 0.2 is z = 2.
    const RenderOutput a = constantRender(2, 2, 16, 1.0f, 0.0f);
    const RenderOutput b = constantRender(2, 2, 4, 1.2f, 0.12f);
    const ZTestResult result = zTestPerPixel(a, b);
    EXPECT_TRUE(result.passed) << result.summary;
    EXPECT_NEAR(result.worstZ, -2.0, 1e-5);
}

TEST(ZTest, PixelsWithFewerThanTwoSamplesAreRejected) {
    RenderOutput a = constantRender(8, 4, 16, 1.0f, 1.0f);
    const RenderOutput b = a;
    a.sampleCounts[std::size_t(2 * 8 + 3)] = 1;
    a.sampleCounts[std::size_t(3 * 8 + 0)] = 0;
    const ZTestResult result = zTestPerPixel(a, b);
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.rejectedPixels, 2u);
    EXPECT_EQ(result.summary, "z-test: 2 of 32 pixels have fewer than 2 samples in an image, so no "
                              "variance to test with (first at (3, 2))");
}

TEST(ZTest, NonFiniteStatisticsAreRejected) {
    RenderOutput a = constantRender(4, 4, 16, 1.0f, 1.0f);
    const RenderOutput b = a;
    a.luminanceMean[5] = std::numeric_limits<float>::quiet_NaN();
    a.luminanceM2[6] = std::numeric_limits<float>::infinity();
    const ZTestResult result = zTestPerPixel(a, b);
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.rejectedPixels, 2u);
    EXPECT_NE(result.summary.find("2 of 16 pixels have a non-finite mean or variance (first at "
                                  "(1, 1))"),
              std::string::npos)
        << result.summary;
}

TEST(ZTest, ImagesOfDifferentSizesAreAProgrammerError) {
    EXPECT_THROW(zTestPerPixel(constantRender(4, 4, 8, 1, 1), constantRender(4, 5, 8, 1, 1)),
                 InternalError);
    RenderOutput incomplete = constantRender(4, 4, 8, 1, 1);
    incomplete.luminanceM2.pop_back();
    EXPECT_THROW(zTestPerPixel(incomplete, constantRender(4, 4, 8, 1, 1)), InternalError);
}

TEST(ZTest, SidakAlphaAndCriticalValueAreComputedStably) {
    // 4096 pixels at family alpha 1e-9: (1 − α)^(1/N) computed directly would lose about four
    // digits; Šidák's α₁ = α/N · (1 + α(N − 1)/(2N) + O(α²)).
    const RenderOutput render = constantRender(64, 64, 4, 1.0f, 1.0f);
    const ZTestResult result = zTestPerPixel(render, render, 1e-9);
    const double expected = 1e-9 / 4096.0 * (1.0 + 1e-9 * 4095.0 / 8192.0);
    EXPECT_NEAR(result.alphaPerPixel / expected, 1.0, 1e-13);
    EXPECT_EQ(result.criticalZ, normalUpperQuantile(result.alphaPerPixel / 2.0));

    const ZTestResult usual = zTestPerPixel(render, render, 0.01);
    EXPECT_NEAR(usual.alphaPerPixel, 1.0 - std::pow(0.99, 1.0 / 4096.0), 1e-15);
    const double tail = 0.5 * std::erfc(usual.criticalZ / std::numbers::sqrt2); // two-sided
    EXPECT_NEAR(tail / (usual.alphaPerPixel / 2.0), 1.0, 1e-12);
}

TEST(MeanLuminance, AveragesPixelMeansWithTheirStandardError) {
    RenderOutput output = constantRender(2, 1, 5, 1.0f, 2.0f);
    output.luminanceMean[1] = 3.0f;
    output.luminanceM2[1] = 8.0f;
    const MeanEstimate estimate = meanLuminance(output);
    EXPECT_DOUBLE_EQ(estimate.mean, 2.0);
    // s² = M2 / (n − 1) / n: 2/4/5 = 0.1 and 8/4/5 = 0.4; SE = sqrt(0.5) / 2.
    EXPECT_NEAR(estimate.standardError, std::sqrt(0.5) / 2.0, 1e-12);
}

TEST(MeanLuminance, StandardErrorIsUnknownWithASingleSample) {
    RenderOutput output = constantRender(2, 2, 5, 1.0f, 2.0f);
    output.sampleCounts[3] = 1;
    EXPECT_TRUE(std::isnan(meanLuminance(output).standardError));
}

TEST(NormalUpperQuantile, MatchesKnownValues) {
    EXPECT_NEAR(normalUpperQuantile(0.025), 1.959963985, 1e-9);
    EXPECT_NEAR(normalUpperQuantile(1e-10), 6.361340902, 1e-9);
    EXPECT_NEAR(normalUpperQuantile(0.025), 1.959963984540054, 1e-14);
    EXPECT_NEAR(normalUpperQuantile(0.15865525393145707), 1.0, 1e-14); // Q(1)
    EXPECT_EQ(normalUpperQuantile(0.5), 0.0);
    EXPECT_NEAR(normalUpperQuantile(0.975), -1.959963984540054, 1e-12);
}

TEST(NormalUpperQuantile, InvertsTheTailFromHalfDownToTenToTheMinus300) {
    for (int exponent = 0; exponent <= 300; ++exponent)
        for (double mantissa : {1.0, 2.5, 5.0}) {
            const double p = mantissa * std::pow(10.0, -exponent) / 10.0;
            const double z = normalUpperQuantile(p);
            const double tail = 0.5 * std::erfc(z / std::numbers::sqrt2);
            EXPECT_NEAR(tail / p, 1.0, 1e-12) << "p = " << p << ", z = " << z;
        }
}

TEST(NormalUpperQuantile, HandlesTheEndsOfItsDomain) {
    EXPECT_EQ(normalUpperQuantile(0.0), std::numeric_limits<double>::infinity());
    EXPECT_EQ(normalUpperQuantile(1.0), -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isnan(normalUpperQuantile(std::numeric_limits<double>::quiet_NaN())));
    EXPECT_GT(normalUpperQuantile(1e-300), 37.0);
}

} // namespace
} // namespace vkpt::image_compare_test
