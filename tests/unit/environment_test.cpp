// environment_test.cpp — the environment light: the equirectangular mapping, the sampler
// against its own pdf (chi-square), the pdf's normalisation, estimators with analytic answers,
// the tables' layout and power, and reading maps from .hdr and .pfm files with their errors.
//
// Chi-square tests: three in this file, each at the Šidák-corrected level
// 1 − (1 − 0.01)^(1/3) ≈ 0.00334, so that the file as a whole fails by chance with
// probability 0.01 (Mitsuba's chi2 tests correct the same way).
#include "prepare/environment_map.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <unistd.h>

#include "../support/chi_square.h"
#include "../support/test_directory.h"
#include "common/errors.h"
#include "common/math_constants.h"
#include "image/image_io.h"
#include "shared/environment.h"
#include "shared/rng.h"
#include "shared/sampling.h"

namespace vkpt::environment_test {
namespace {

namespace fs = std::filesystem;

constexpr int kChiSquareTests = 3;
const double kAlpha = 1.0 - std::pow(1.0 - 0.01, 1.0 / kChiSquareTests);

// An environment with its tables and the parameters the shared code reads.
struct TestEnvironment {
    SceneEnvironment scene;
    EnvironmentDistribution distribution;
    gpu::EnvironmentParams params{};

    explicit TestEnvironment(SceneEnvironment environment) : scene(std::move(environment)) {
        distribution = buildEnvironmentDistribution(scene, 1.0);
        params = makeEnvironmentParams(scene, 0);
    }

    gpu::EnvironmentSample sampleAt(glm::vec2 u) const {
        return gpu::sampleEnvironment(params, u, view());
    }
    float pdf(glm::vec3 direction) const { return gpu::environmentPdf(params, direction, view()); }
    glm::vec3 radiance(glm::vec3 direction) const {
        return gpu::environmentRadiance(params, direction, view());
    }
    // The shared code reads the map's tables through a SceneView; nothing else in it is read.
    gpu::SceneView view() const {
        gpu::SceneView v{};
        v.environmentTexels = distribution.texels;
        v.environmentCdf = distribution.cdf;
        return v;
    }
};

SceneEnvironment makeMap(std::uint32_t width, std::uint32_t height, glm::vec3 scale,
                         const std::function<glm::vec3(std::uint32_t, std::uint32_t)>& texel) {
    SceneEnvironment environment;
    environment.radiance = scale;
    environment.width = width;
    environment.height = height;
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            environment.texels.push_back(texel(x, y));
    return environment;
}

// 16 × 8 with strong contrast: a sun 600× the sky, a dark band, a black row, black texels at
// the start and inside of a lit row, lit rows at both poles, and a coloured scale.
constexpr std::uint32_t kZeroRow = 2, kDarkRow = 5, kSunX = 11, kSunY = 1, kZeroX = 3, kZeroY = 4;

SceneEnvironment contrastMap() {
    return makeMap(16, 8, glm::vec3(1.0f, 0.8f, 1.2f), [](std::uint32_t x, std::uint32_t y) {
        if (y == kZeroRow || (y == kZeroY && (x == 0 || x == kZeroX))) return glm::vec3(0.0f);
        if (x == kSunX && y == kSunY) return glm::vec3(300.0f, 270.0f, 240.0f);
        if (y == kDarkRow) return glm::vec3(0.002f);
        return glm::vec3(0.4f + 0.05f * float(x), 0.5f, 0.6f - 0.03f * float(y));
    });
}

SceneEnvironment blackMap() {
    return makeMap(12, 6, glm::vec3(1.0f),
                   [](std::uint32_t, std::uint32_t) { return glm::vec3(0.0f); });
}

SceneEnvironment constantColour(glm::vec3 radiance) {
    SceneEnvironment environment;
    environment.radiance = radiance;
    return environment;
}

glm::vec2 uniformPair(std::uint32_t seed, std::uint32_t i) {
    const glm::vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_LIGHT_FIRST);
    return {u.y, u.z};
}

// The (u, v) of a direction, computed here in double rather than by the code under test.
glm::dvec2 referenceEquirect(glm::vec3 d) {
    const double u = 0.5 + std::atan2(double(d.z), double(d.x)) / (2.0 * kPi);
    const double v = std::acos(std::clamp(double(d.y), -1.0, 1.0)) / kPi;
    return {u >= 1.0 ? u - 1.0 : u, v};
}

// -------------------------------------------------------------------------------------------
// The mapping

TEST(EnvironmentMapping, DirectionsMapAsDocumented) {
    auto uvOf = [](glm::vec3 d) { return gpu::directionToEquirect(d); };
    EXPECT_NEAR(uvOf({0, 1, 0}).y, 0.0f, 1e-7f);  // +Y: the top row
    EXPECT_NEAR(uvOf({0, -1, 0}).y, 1.0f, 1e-7f); // −Y: the bottom row
    EXPECT_NEAR(uvOf({-1, 0, 0}).x, 0.0f, 1e-7f); // −X: the left edge
    EXPECT_NEAR(uvOf({0, 0, -1}).x, 0.25f, 1e-7f);
    EXPECT_NEAR(uvOf({1, 0, 0}).x, 0.5f, 1e-7f);
    EXPECT_NEAR(uvOf({0, 0, 1}).x, 0.75f, 1e-7f);
    EXPECT_NEAR(uvOf({1, 0, 0}).y, 0.5f, 1e-7f);
    // Seen from inside, looking along −Z with +Y up, +X is to the right: u grows rightwards.
    EXPECT_LT(uvOf(glm::normalize(glm::vec3(-0.1f, 0, -1))).x, 0.25f);
    EXPECT_GT(uvOf(glm::normalize(glm::vec3(0.1f, 0, -1))).x, 0.25f);
    // Both signs of zero at the seam land inside [0, 1).
    EXPECT_LT(uvOf({-1, 0, -0.0f}).x, 1.0f);
    EXPECT_LT(uvOf({-1, 0, 0.0f}).x, 1.0f);
}

TEST(EnvironmentMapping, EquirectRoundTrips) {
    float worstUv = 0.0f, worstDirection = 0.0f;
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const glm::vec2 uv = uniformPair(1, i);
        const glm::vec2 back = gpu::directionToEquirect(gpu::equirectToDirection(uv));
        const float du = std::abs(back.x - uv.x);
        worstUv = std::max({worstUv, std::min(du, 1.0f - du), std::abs(back.y - uv.y)});

        const glm::vec3 d = gpu::sampleUniformSphere(uniformPair(2, i));
        const glm::vec3 again = gpu::equirectToDirection(gpu::directionToEquirect(d));
        worstDirection = std::max(worstDirection, glm::length(again - d));
        ASSERT_NEAR(glm::length(gpu::equirectToDirection(uv)), 1.0f, 1e-6f);
    }
    EXPECT_LT(worstUv, 2e-6f);
    EXPECT_LT(worstDirection, 2e-6f);
}

TEST(EnvironmentMapping, RadianceIsTheNearestTexelTimesTheScale) {
    const TestEnvironment env(contrastMap());
    for (std::uint32_t y = 0; y < env.scene.height; ++y)
        for (std::uint32_t x = 0; x < env.scene.width; ++x) {
            const glm::vec2 centre((float(x) + 0.5f) / 16.0f, (float(y) + 0.5f) / 8.0f);
            const glm::vec3 expected = env.scene.texels[y * 16 + x] * env.scene.radiance;
            const glm::vec3 got = env.radiance(gpu::equirectToDirection(centre));
            EXPECT_EQ(got, expected) << "texel " << x << ", " << y;
        }
    const TestEnvironment constant(constantColour({0.25f, 0.5f, 2.0f}));
    EXPECT_EQ(constant.radiance({0, 0, 1}), glm::vec3(0.25f, 0.5f, 2.0f));
}

// -------------------------------------------------------------------------------------------
// The sampler against its pdf

// Bins of the (u, v) rectangle, 2 × 2 per texel; expected counts are n·∫ pdf dω over each bin
// with dω = 2π² sin θ du dv, by a 4 × 4 midpoint rule (exact up to rounding, since pdf·sin θ
// is constant inside a texel).
test::ChiSquareResult chiSquareOfMap(const TestEnvironment& env, std::uint32_t seed, int n) {
    const int uBins = int(env.scene.width) * 2, vBins = int(env.scene.height) * 2;
    std::vector<double> observed(std::size_t(uBins * vBins), 0.0);
    std::vector<double> expected(observed.size(), 0.0);
    for (int i = 0; i < n; ++i) {
        const gpu::EnvironmentSample s = env.sampleAt(uniformPair(seed, std::uint32_t(i)));
        if (!s.valid) continue;
        const glm::dvec2 uv = referenceEquirect(s.direction);
        const int bu = std::min(uBins - 1, int(uv.x * uBins));
        const int bv = std::min(vBins - 1, int(uv.y * vBins));
        observed[std::size_t(bv * uBins + bu)] += 1.0;
    }
    const int q = 4;
    for (int bv = 0; bv < vBins; ++bv)
        for (int bu = 0; bu < uBins; ++bu) {
            double integral = 0.0;
            for (int j = 0; j < q * q; ++j) {
                const double u = (bu + (j % q + 0.5) / q) / uBins;
                const double v = (bv + (j / q + 0.5) / q) / vBins;
                const glm::vec3 d = gpu::equirectToDirection(glm::vec2(u, v));
                integral += double(env.pdf(d)) * 2.0 * kPi * kPi * std::sin(kPi * v);
            }
            expected[std::size_t(bv * uBins + bu)] = n * integral / (q * q * uBins * vBins);
        }
    return test::chiSquareTest(observed, expected);
}

TEST(EnvironmentSampling, MapSamplesFollowTheirPdfByChiSquare) {
    const TestEnvironment env(contrastMap());
    const test::ChiSquareResult r = chiSquareOfMap(env, 11, 400000);
    EXPECT_GT(r.pValue, kAlpha) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
}

TEST(EnvironmentSampling, BlackMapFallsBackToSolidAngleByChiSquare) {
    const TestEnvironment env(blackMap());
    EXPECT_TRUE(env.distribution.uniformFallback);
    EXPECT_EQ(env.distribution.power, 0.0);
    const test::ChiSquareResult r = chiSquareOfMap(env, 12, 200000);
    EXPECT_GT(r.pValue, kAlpha) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
    // Every direction off the poles can be sampled, so MIS weights of BSDF samples stay finite.
    for (std::uint32_t i = 0; i < 1000; ++i) {
        const float pdf = env.pdf(gpu::sampleUniformSphere(uniformPair(13, i)));
        EXPECT_GT(pdf, 0.0f);
        EXPECT_TRUE(std::isfinite(pdf));
    }
}

// A constant colour: uniform over the sphere, binned by (y, φ) into equal solid angles.
TEST(EnvironmentSampling, ConstantColourIsUniformByChiSquare) {
    const TestEnvironment env(constantColour(glm::vec3(1.0f)));
    const int n = 200000, yBins = 16, phiBins = 32;
    std::vector<double> observed(std::size_t(yBins * phiBins), 0.0);
    for (int i = 0; i < n; ++i) {
        const gpu::EnvironmentSample s = env.sampleAt(uniformPair(14, std::uint32_t(i)));
        ASSERT_TRUE(s.valid);
        ASSERT_FLOAT_EQ(s.pdf, float(1.0 / (4.0 * kPi)));
        ASSERT_FLOAT_EQ(env.pdf(s.direction), s.pdf);
        const double phi = std::atan2(double(s.direction.z), double(s.direction.x)) + kPi;
        const int by = std::min(yBins - 1, int((double(s.direction.y) + 1.0) / 2.0 * yBins));
        const int bp = std::min(phiBins - 1, int(phi / (2.0 * kPi) * phiBins));
        observed[std::size_t(by * phiBins + bp)] += 1.0;
    }
    const std::vector<double> expected(observed.size(), double(n) / double(observed.size()));
    const test::ChiSquareResult r = test::chiSquareTest(observed, expected);
    EXPECT_GT(r.pValue, kAlpha) << "chi2 " << r.statistic << " dof " << r.degreesOfFreedom;
}

// The sample's pdf is what environmentPdf says for its direction, and its radiance what
// environmentRadiance says. The two only look the texel up differently when a sample rounds
// onto a texel edge, which must be rare.
TEST(EnvironmentSampling, SamplePdfAndRadianceMatchTheLookups) {
    const TestEnvironment env(contrastMap());
    const int n = 100000;
    int edgeCases = 0;
    for (int i = 0; i < n; ++i) {
        const gpu::EnvironmentSample s = env.sampleAt(uniformPair(15, std::uint32_t(i)));
        ASSERT_TRUE(std::isfinite(s.pdf));
        if (!s.valid) continue;
        ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-6f);
        const float pdf = env.pdf(s.direction);
        if (env.radiance(s.direction) != s.radiance) {
            ++edgeCases;
            continue;
        }
        ASSERT_NEAR(pdf, s.pdf, 1e-5f * s.pdf) << "sample " << i;
        ASSERT_GT(gpu::luminance(s.radiance), 0.0f) << "a texel without light was chosen";
    }
    EXPECT_LE(edgeCases, n / 10000);
}

// Every u that lands exactly on a CDF entry, or just below it, picks a texel with light: the
// upper-bound search skips the zero steps of the black row and the black texels (a
// lower-bound search would pick the black first texel of its row for u = 0). Off the north
// pole (u.x = 0 there) every sample is valid.
TEST(EnvironmentSampling, TexelsWithoutLightAreNeverChosen) {
    const TestEnvironment env(contrastMap());
    std::vector<float> us{0.0f, 0.99999994f};
    for (float c : env.distribution.cdf) {
        us.push_back(c);
        us.push_back(std::nextafter(c, 0.0f));
    }
    for (float ux : us)
        for (float uy : us) {
            if (!(ux < 1.0f) || !(uy < 1.0f)) continue;
            const gpu::EnvironmentSample s = env.sampleAt({ux, uy});
            ASSERT_TRUE(std::isfinite(s.pdf));
            ASSERT_TRUE(s.valid || ux == 0.0f) << ux << ", " << uy;
            if (s.valid) {
                ASSERT_GT(gpu::luminance(s.radiance), 0.0f) << ux << ", " << uy;
            }
        }
}

// At the poles sin θ → 0: samples there are invalid with pdf 0, never infinite or NaN.
TEST(EnvironmentSampling, PolesGiveFinitePdfs) {
    const TestEnvironment env(contrastMap());
    for (float ux : {0.0f, 1e-30f, 1e-9f, 0.99999994f}) {
        const gpu::EnvironmentSample s = env.sampleAt({ux, 0.3f});
        EXPECT_TRUE(std::isfinite(s.pdf)) << ux;
        EXPECT_TRUE(s.valid || s.pdf == 0.0f) << ux;
    }
    EXPECT_FALSE(env.sampleAt({0.0f, 0.3f}).valid); // exactly the north pole
    for (glm::vec3 pole : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(-0.0f, 1, 0)}) {
        EXPECT_EQ(env.pdf(pole), 0.0f);
        EXPECT_TRUE(std::isfinite(gpu::luminance(env.radiance(pole))));
    }
}

// Midpoint rule in (θ, φ) with dω = sin θ dθ dφ, on cells that never straddle a texel edge:
// the pdf is tested against the solid-angle measure, not against its own (u, v) tables.
double integratePdf(const TestEnvironment& env) {
    // A multiple of the texel count, and at least 512 for the sin θ factor's accuracy.
    auto steps = [](std::uint32_t texels) {
        const int n = int(std::max(1u, texels));
        return n * ((511 + n) / n);
    };
    const int thetaSteps = steps(env.scene.height), phiSteps = steps(env.scene.width);
    double sum = 0.0;
    for (int i = 0; i < thetaSteps; ++i) {
        const double theta = (i + 0.5) / thetaSteps * kPi;
        double ring = 0.0;
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = (j + 0.5) / phiSteps * 2.0 * kPi;
            const glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            ring += double(env.pdf(d));
        }
        sum += ring * std::sin(theta);
    }
    return sum * (kPi / thetaSteps) * (2.0 * kPi / phiSteps);
}

TEST(EnvironmentSampling, PdfIntegratesToOne) {
    EXPECT_NEAR(integratePdf(TestEnvironment(contrastMap())), 1.0, 1e-5);
    EXPECT_NEAR(integratePdf(TestEnvironment(blackMap())), 1.0, 1e-5);
    EXPECT_NEAR(integratePdf(TestEnvironment(constantColour(glm::vec3(2.0f)))), 1.0, 1e-5);
}

// -------------------------------------------------------------------------------------------
// Estimators with known answers

struct Estimate {
    glm::dvec3 mean{0.0};
    glm::dvec3 standardError{0.0};
};

// Mean and standard error of f(sample) over n environment samples (invalid ones count as 0).
Estimate estimate(const TestEnvironment& env, std::uint32_t seed, int n,
                  const std::function<glm::dvec3(const gpu::EnvironmentSample&)>& f) {
    glm::dvec3 sum(0.0), sumSquares(0.0);
    for (int i = 0; i < n; ++i) {
        const gpu::EnvironmentSample s = env.sampleAt(uniformPair(seed, std::uint32_t(i)));
        const glm::dvec3 value = s.valid ? f(s) : glm::dvec3(0.0);
        sum += value;
        sumSquares += value * value;
    }
    Estimate e;
    e.mean = sum / double(n);
    const glm::dvec3 variance = glm::max(sumSquares / double(n) - e.mean * e.mean, 0.0);
    e.standardError = glm::sqrt(variance / double(n));
    return e;
}

void expectEstimate(const Estimate& e, glm::dvec3 expected, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(e.mean[c], expected[c], 5.0 * e.standardError[c] + 1e-9 * expected[c])
            << what << ", channel " << c;
}

// Irradiance at a surface with normal n: E = ∫ L max(cos, 0) dω, estimated by L·cos/pdf.
Estimate irradiance(const TestEnvironment& env, glm::vec3 normal, std::uint32_t seed) {
    return estimate(env, seed, 100000, [normal](const gpu::EnvironmentSample& s) {
        const double cosine = std::max(0.0, double(glm::dot(s.direction, normal)));
        return glm::dvec3(s.radiance) * cosine / double(s.pdf);
    });
}

TEST(EnvironmentEstimator, IrradianceOfAConstantEnvironmentIsPiL) {
    const glm::vec3 L(0.5f, 1.0f, 2.0f);
    const TestEnvironment colour(constantColour(L));
    const TestEnvironment map(makeMap(20, 10, glm::vec3(2.0f), [](std::uint32_t, std::uint32_t) {
        return glm::vec3(0.25f, 0.5f, 1.0f);
    }));
    const glm::dvec3 expected = kPi * glm::dvec3(L);
    for (glm::vec3 n : {glm::vec3(0, 1, 0), glm::vec3(0, 0, -1), glm::normalize(glm::vec3(1))}) {
        expectEstimate(irradiance(colour, n, 21), expected, "constant colour");
        expectEstimate(irradiance(map, n, 22), expected, "constant map");
    }
}

// Upper half bright, lower half dark: a surface facing +Y sees only the top, one facing −Y
// only the bottom, and one facing +X half of each (π/2 per half).
TEST(EnvironmentEstimator, IrradianceOfAHalfBrightMapIsExact) {
    const glm::vec3 top(3.0f, 2.0f, 1.0f), bottom(0.01f, 0.02f, 0.03f);
    const TestEnvironment env(makeMap(16, 8, glm::vec3(1.0f), [&](std::uint32_t, std::uint32_t y) {
        return y < 4 ? top : bottom;
    }));
    expectEstimate(irradiance(env, {0, 1, 0}, 23), kPi * glm::dvec3(top), "facing +Y");
    expectEstimate(irradiance(env, {0, -1, 0}, 24), kPi * glm::dvec3(bottom), "facing -Y");
    expectEstimate(irradiance(env, {1, 0, 0}, 25), kPi / 2.0 * glm::dvec3(top + bottom),
                   "facing +X");
}

// ∫ L dω = 4π × the average radiance the tables report, estimated by L/pdf.
TEST(EnvironmentEstimator, RadianceOverPdfIntegratesToTheAverage) {
    const TestEnvironment env(contrastMap());
    const Estimate e = estimate(env, 26, 100000, [](const gpu::EnvironmentSample& s) {
        return glm::dvec3(s.radiance) / double(s.pdf);
    });
    expectEstimate(e, 4.0 * kPi * env.distribution.averageRadiance, "contrast map");
}

// -------------------------------------------------------------------------------------------
// The tables

TEST(EnvironmentDistribution, TablesHaveTheDocumentedLayout) {
    const TestEnvironment env(contrastMap());
    const EnvironmentDistribution& d = env.distribution;
    const std::size_t w = 16, h = 8;
    ASSERT_EQ(d.texels.size(), w * h);
    ASSERT_EQ(d.cdf.size(), w * h + h);
    EXPECT_FALSE(d.uniformFallback);
    EXPECT_EQ(d.texels[kSunY * w + kSunX], glm::vec4(300.0f, 270.0f, 240.0f, 0.0f));
    for (std::size_t row = 0; row <= h; ++row) { // h conditional rows, then the marginal
        const std::size_t n = row < h ? w : h;
        const float* entries = d.cdf.data() + row * w;
        EXPECT_EQ(entries[n - 1], 1.0f) << "row " << row;
        for (std::size_t i = 1; i < n; ++i)
            EXPECT_LE(entries[i - 1], entries[i]) << "row " << row << " entry " << i;
    }
    const float* marginal = d.cdf.data() + w * h;
    EXPECT_EQ(marginal[kZeroRow], marginal[kZeroRow - 1]); // the black row has no weight
    // Neither have the black texels.
    EXPECT_EQ(d.cdf[kZeroY * w], 0.0f);
    EXPECT_EQ(d.cdf[kZeroY * w + kZeroX], d.cdf[kZeroY * w + kZeroX - 1]);
    EXPECT_GT(marginal[kDarkRow], marginal[kDarkRow - 1]); // the dark band has a little
}

// A constant radiance L over the sphere of radius R sends π·L·4πR² into it, whether it is a
// colour or a map; the map's average is computed with each texel's exact solid angle.
TEST(EnvironmentDistribution, PowerOfAConstantEnvironment) {
    const glm::vec3 L(0.5f, 1.0f, 2.0f);
    const double lum = double(gpu::luminance(L)), radius = 3.0;
    const double expected = kPi * lum * 4.0 * kPi * radius * radius;
    EXPECT_NEAR(buildEnvironmentDistribution(constantColour(L), radius).power, expected,
                1e-6 * expected);
    const SceneEnvironment map = makeMap(7, 5, glm::vec3(2.0f), [](std::uint32_t, std::uint32_t) {
        return glm::vec3(0.25f, 0.5f, 1.0f);
    });
    const EnvironmentDistribution d = buildEnvironmentDistribution(map, radius);
    EXPECT_NEAR(d.power, expected, 1e-6 * expected);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(d.averageRadiance[c], double(L[c]), 1e-6);
}

TEST(EnvironmentDistribution, ParamsDescribeTheMapOrTheColour) {
    const gpu::EnvironmentParams map = makeEnvironmentParams(contrastMap(), 4);
    EXPECT_EQ(map.width, 16u);
    EXPECT_EQ(map.height, 8u);
    EXPECT_EQ(map.emitterIndex, 4u);
    EXPECT_EQ(map.radiance, glm::vec3(1.0f, 0.8f, 1.2f));
    const gpu::EnvironmentParams colour = makeEnvironmentParams(constantColour({1, 2, 3}), 0);
    EXPECT_EQ(colour.width, 0u);
    EXPECT_EQ(colour.radiance, glm::vec3(1, 2, 3));
}

// -------------------------------------------------------------------------------------------
// Files

class EnvironmentFile : public test::TestDirectory {
protected:
    EnvironmentFile() : TestDirectory("vkpt_environment") {}

    void writeText(const std::string& name, const std::string& text) const {
        std::ofstream(path(name), std::ios::binary) << text;
    }
};

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no InputError)";
}

// 16 wide, so that stb writes run-length encoded scanlines, as real maps have.
TEST_F(EnvironmentFile, ReadsTheTexelsOfAnHdrFile) {
    const int w = 16, h = 3;
    std::vector<float> rgb;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            rgb.push_back(0.25f * float(x + 1));
            rgb.push_back(float(y + 1));
            rgb.push_back(x == 5 && y == 0 ? 5000.0f : 0.125f);
        }
    ASSERT_NE(stbi_write_hdr(path("sky.hdr").c_str(), w, h, 3, rgb.data()), 0);
    const SceneEnvironment env = readEnvironmentMap(path("sky.hdr"), glm::vec3(2.0f));
    ASSERT_EQ(env.width, std::uint32_t(w));
    ASSERT_EQ(env.height, std::uint32_t(h));
    EXPECT_EQ(env.radiance, glm::vec3(2.0f));
    EXPECT_EQ(env.sourcePath, path("sky.hdr"));
    EXPECT_TRUE(env.hasMap());
    for (int i = 0; i < w * h; ++i) {
        const glm::vec3 written(rgb[3 * std::size_t(i)], rgb[3 * std::size_t(i) + 1],
                                rgb[3 * std::size_t(i) + 2]);
        // RGBE keeps 8 bits of mantissa relative to the largest component (stb truncates).
        const float tolerance = std::max({written.r, written.g, written.b}) / 128.0f;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(env.texels[std::size_t(i)][c], written[c], tolerance) << "texel " << i;
    }
}

TEST_F(EnvironmentFile, ReadsThePixelsOfAPfmFile) {
    Image image(4, 2);
    for (std::uint32_t y = 0; y < 2; ++y)
        for (std::uint32_t x = 0; x < 4; ++x)
            image.at(x, y) = glm::vec3(float(x) + 0.1f, float(y) * 1e6f, 1e-7f);
    writePfm(image, path("sky.pfm"));
    const SceneEnvironment env = readEnvironmentMap(path("sky.pfm"), glm::vec3(1.0f));
    ASSERT_EQ(env.width, 4u);
    ASSERT_EQ(env.height, 2u);
    EXPECT_EQ(env.texels, image.pixels); // row 0 at the top on both sides
}

TEST_F(EnvironmentFile, MissingFileIsNamed) {
    const std::string error =
        errorOf([&] { readEnvironmentMap(path("nowhere.hdr"), glm::vec3(1.0f)); });
    EXPECT_NE(error.find(path("nowhere.hdr") + ": cannot read: "), std::string::npos) << error;
}

TEST_F(EnvironmentFile, FileWithoutTheRadianceSignatureIsRejected) {
    writeText("junk.hdr", "P6\n2 2\n255\nxxxxxxxxxxxx");
    const std::string error = errorOf([&] { readEnvironmentMap(path("junk.hdr"), glm::vec3(1)); });
    EXPECT_NE(error.find(path("junk.hdr") + ": not a Radiance HDR file"), std::string::npos)
        << error;
    writeText("empty.hdr", "");
    const std::string empty = errorOf([&] { readEnvironmentMap(path("empty.hdr"), glm::vec3(1)); });
    EXPECT_NE(empty.find(path("empty.hdr") + ": empty file"), std::string::npos) << empty;
}

TEST_F(EnvironmentFile, CorruptHeaderIsRejected) {
    const std::string pixels(16, '\x80'); // 2 × 2 flat RGBE pixels
    writeText("bad-format.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 2\n" + pixels);
    std::string error = errorOf([&] { readEnvironmentMap(path("bad-format.hdr"), glm::vec3(1)); });
    EXPECT_NE(error.find(path("bad-format.hdr") + ": cannot decode Radiance HDR: "),
              std::string::npos)
        << error;
    writeText("bad-size.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+X 2 -Y 2\n" + pixels);
    error = errorOf([&] { readEnvironmentMap(path("bad-size.hdr"), glm::vec3(1)); });
    EXPECT_NE(error.find(path("bad-size.hdr") + ": cannot decode Radiance HDR: "),
              std::string::npos)
        << error;
}

// Every cut after the header, in flat (4 wide) and run-length encoded (16 wide) files, is
// reported: stb_image alone would read the missing bytes as zeros, or never finish.
TEST_F(EnvironmentFile, TruncatedHdrIsRejected) {
    for (int w : {4, 16}) {
        const int h = 3;
        std::vector<float> rgb(std::size_t(w * h * 3));
        for (std::size_t i = 0; i < rgb.size(); ++i)
            rgb[i] = 0.5f + float(i % 7);
        const std::string whole = path("whole.hdr");
        ASSERT_NE(stbi_write_hdr(whole.c_str(), w, h, 3, rgb.data()), 0);
        EXPECT_EQ(readEnvironmentMap(whole, glm::vec3(1)).width, std::uint32_t(w));
        std::ifstream in(whole, std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), {}};
        const std::size_t resolution = bytes.find("\n-Y ");
        ASSERT_NE(resolution, std::string::npos);
        const std::size_t dataStart = bytes.find('\n', resolution + 1) + 1;
        for (std::size_t cut = dataStart; cut < bytes.size(); ++cut) {
            writeText("cut.hdr", bytes.substr(0, cut));
            const std::string error =
                errorOf([&] { readEnvironmentMap(path("cut.hdr"), glm::vec3(1)); });
            ASSERT_NE(error.find(path("cut.hdr") + ": truncated Radiance HDR: the file ("),
                      std::string::npos)
                << "width " << w << ", cut at " << cut << " of " << bytes.size() << ": " << error;
        }
    }
}

TEST_F(EnvironmentFile, NegativeOrNonFiniteTexelsAreRejected) {
    Image image(3, 2);
    std::fill(image.pixels.begin(), image.pixels.end(), glm::vec3(1.0f));
    image.at(2, 1) = glm::vec3(1.0f, -0.5f, 1.0f);
    writePfm(image, path("negative.pfm"));
    std::string error = errorOf([&] { readEnvironmentMap(path("negative.pfm"), glm::vec3(1)); });
    EXPECT_NE(error.find(path("negative.pfm") + ": texel (2, 1) is (1, -0.5, 1)"),
              std::string::npos)
        << error;
    image.at(2, 1) = glm::vec3(1.0f);
    image.at(0, 1) = glm::vec3(std::nanf(""), 1.0f, 1.0f);
    writePfm(image, path("nan.pfm"));
    error = errorOf([&] { readEnvironmentMap(path("nan.pfm"), glm::vec3(1)); });
    EXPECT_NE(error.find(path("nan.pfm") + ": texel (0, 1) is"), std::string::npos) << error;
}

TEST_F(EnvironmentFile, UnsupportedFormatAndBadScaleAreRejected) {
    writeText("sky.png", "not read");
    const std::string format = errorOf([&] { readEnvironmentMap(path("sky.png"), glm::vec3(1)); });
    EXPECT_NE(format.find(path("sky.png") + ": unsupported image format '.png'"), std::string::npos)
        << format;
    const glm::vec3 negative(1, -1, 1);
    const std::string scale = errorOf([&] { readEnvironmentMap(path("sky.png"), negative); });
    EXPECT_NE(scale.find(path("sky.png") + ": environment scale (1, -1, 1) must be finite"),
              std::string::npos)
        << scale;
}

} // namespace
} // namespace vkpt::environment_test
