// error_metrics_test.cpp — RMSE, relative MSE and the variance estimates on images whose
// answers are known by hand (from σ²/n and from the two halves), and the estimates against the
// true relMSE on synthetic noise.
#include "image/error_metrics.h"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "common/errors.h"

namespace vkpt::error_metrics_test {
namespace {

Image filled(std::uint32_t w, std::uint32_t h, glm::vec3 value) {
    Image image(w, h);
    for (glm::vec3& p : image.pixels)
        p = value;
    return image;
}

// A render of one sample count, mean and M2 for every pixel.
RenderOutput statistics(std::size_t pixels, std::uint32_t n, float mean, float m2) {
    RenderOutput output;
    output.image = Image(std::uint32_t(pixels), 1);
    output.sampleCounts.assign(pixels, n);
    output.luminanceMean.assign(pixels, mean);
    output.luminanceM2.assign(pixels, m2);
    return output;
}

TEST(ErrorMetrics, AnImageEqualToItsReferenceHasNoError) {
    const Image image = filled(4, 3, {0.2f, 0.5f, 3.0f});
    const ReferenceError error = compareWithReference(image, image);
    EXPECT_EQ(error.rmse, 0.0);
    EXPECT_EQ(error.relMse, 0.0);
}

TEST(ErrorMetrics, AConstantOffsetGivesItsRmseAndRelMse) {
    // Every channel off by 0.5 from a reference of 1: (0.5)² / (1 + 0.01).
    const ReferenceError error =
        compareWithReference(filled(8, 8, glm::vec3(1.5f)), filled(8, 8, glm::vec3(1.0f)));
    EXPECT_NEAR(error.rmse, 0.5, 1e-12);
    EXPECT_NEAR(error.relMse, 0.25 / 1.01, 1e-12);
}

TEST(ErrorMetrics, RelMseAveragesPixelsAndChannelsWithEpsilonForBlack) {
    Image image(2, 1), reference(2, 1);
    reference.pixels = {glm::vec3(0.0f, 1.0f, 2.0f), glm::vec3(0.5f)};
    image.pixels = {glm::vec3(0.1f, 1.0f, 2.0f), glm::vec3(0.5f, 0.5f, 1.5f)};
    // Squared errors: 0.01 (over ε = 0.01), 0, 0 | 0, 0, 1 (over 0.25 + 0.01).
    const double relMse = (0.01 / 0.01 + 1.0 / 0.26) / 6.0;
    const double rmse = std::sqrt((0.01 + 1.0) / 6.0);
    const ReferenceError error = compareWithReference(image, reference);
    EXPECT_NEAR(error.relMse, relMse, 1e-6);
    EXPECT_NEAR(error.rmse, rmse, 1e-6);
}

TEST(ErrorMetrics, ImagesOfDifferentSizesAreAProgrammerError) {
    EXPECT_THROW(compareWithReference(Image(2, 2), Image(2, 3)), InternalError);
}

TEST(ErrorMetrics, VarianceEstimateFromWelfordStatistics) {
    // n = 5, M2 = 8: sample variance 2, variance of the mean 0.4.
    const VarianceEstimate estimate = estimateFromVariance(statistics(10, 5, 2.0f, 8.0f));
    EXPECT_NEAR(estimate.meanHalfWidth, 1.96 * std::sqrt(0.4), 1e-6);
    EXPECT_NEAR(estimate.estimatedRelMse, 0.4 / (4.0 + kRelMseEpsilon), 1e-6);
    EXPECT_EQ(estimate.minSamples, 5u);
}

TEST(ErrorMetrics, VarianceEstimateIsUnknownUntilEveryPixelHasTwoSamples) {
    RenderOutput output = statistics(10, 5, 1.0f, 1.0f);
    output.sampleCounts[7] = 1;
    const VarianceEstimate estimate = estimateFromVariance(output);
    EXPECT_TRUE(std::isnan(estimate.meanHalfWidth));
    EXPECT_TRUE(std::isnan(estimate.estimatedRelMse));
    EXPECT_EQ(estimate.minSamples, 1u);
}

// Grey pixels of n Gaussian samples: the estimate's expectation is the true relMSE's (the
// same s², three equal channels), so over 4096 pixels the two agree to a few per cent.
TEST(ErrorMetrics, EstimatedRelMseMatchesTheTrueOneForUnbiasedGreyNoise) {
    constexpr std::uint32_t kSize = 64, kSamples = 16;
    std::mt19937_64 engine(12345);
    std::normal_distribution<double> normal(0.0, 1.0);
    RenderOutput output;
    output.image = Image(kSize, kSize);
    Image reference(kSize, kSize);
    for (std::size_t i = 0; i < output.image.pixels.size(); ++i) {
        const double mu = 0.05 + 0.9 * double(i % kSize) / kSize, sigma = 0.5 * mu + 0.02;
        double mean = 0.0, m2 = 0.0;
        for (std::uint32_t k = 1; k <= kSamples; ++k) {
            const double x = mu + sigma * normal(engine), delta = x - mean;
            mean += delta / k;
            m2 += delta * (x - mean);
        }
        reference.pixels[i] = glm::vec3(float(mu));
        output.image.pixels[i] = glm::vec3(float(mean));
        output.sampleCounts.push_back(kSamples);
        output.luminanceMean.push_back(float(mean));
        output.luminanceM2.push_back(float(m2));
    }
    const double truth = compareWithReference(output.image, reference).relMse;
    const double estimate = estimateFromVariance(output).estimatedRelMse;
    EXPECT_NEAR(estimate / truth, 1.0, 0.1) << "true " << truth << ", estimated " << estimate;
}

// Halves A and B of 4 samples each: w = 1/4, so the variance of the mean is (A − B)²/4.
TEST(ErrorMetrics, HalvesGiveTheRelMseEstimateAndTheVarianceScale) {
    RenderOutput output = statistics(10, 8, 2.0f, 8.0f * 7.0f); // σ²/n = 8/8 = 1
    output.image = filled(10, 1, glm::vec3(2.0f));
    output.halves[0] = filled(10, 1, glm::vec3(2.5f));
    output.halves[1] = filled(10, 1, glm::vec3(1.5f));
    output.halfCounts[0].assign(10, 4);
    output.halfCounts[1].assign(10, 4);
    const VarianceEstimate estimate = estimateFromVariance(output);
    // (A − B)²/4 = 0.25 in every channel, over x² + ε = 4.01; σ²/n = 1 in luminance, so c = 0.25.
    EXPECT_NEAR(estimate.estimatedRelMse, 0.25 / 4.01, 1e-6);
    EXPECT_NEAR(estimate.varianceScale, 0.25, 1e-6);
    EXPECT_NEAR(varianceScaleFromHalves(output), 0.25, 1e-6);
    EXPECT_NEAR(estimate.meanHalfWidth, 1.96 * std::sqrt(0.25), 1e-6);
    // Unequal halves (2 and 6 of 8): w = 12/64 in place of 1/4.
    output.halfCounts[0].assign(10, 2);
    output.halfCounts[1].assign(10, 6);
    EXPECT_NEAR(estimateFromVariance(output).estimatedRelMse, 12.0 / 64.0 / 4.01, 1e-6);
    // A pixel with an empty half: σ²/n alone.
    output.halfCounts[0][3] = 0;
    EXPECT_NEAR(estimateFromVariance(output).estimatedRelMse, 1.0 / 4.01, 1e-6);
    EXPECT_EQ(varianceScaleFromHalves(output), 1.0);
}

// A scale outside [1/4, 4] is clamped: halves that disagree wildly say more about the image
// than about the sampler.
TEST(ErrorMetrics, TheVarianceScaleIsClamped) {
    RenderOutput output = statistics(4, 8, 2.0f, 7.0f * 1e-6f);
    output.image = filled(4, 1, glm::vec3(2.0f));
    output.halves[0] = filled(4, 1, glm::vec3(3.0f));
    output.halves[1] = filled(4, 1, glm::vec3(1.0f));
    output.halfCounts[0].assign(4, 4);
    output.halfCounts[1].assign(4, 4);
    EXPECT_EQ(varianceScaleFromHalves(output), kMaxVarianceScale);
}

} // namespace
} // namespace vkpt::error_metrics_test
