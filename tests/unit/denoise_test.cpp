// denoise_test.cpp — the statistics-gated denoiser's claims on synthetic pixels, where the true
// means are known: it leaves an image alone when no noise can explain a difference (the gate
// rejects everything as the variances vanish), it converges to the raw image as the samples
// grow, it keeps a texture's and a geometric edge's contrast, and it neither spreads a firefly
// into its neighbours nor keeps it at full strength. 48×48 pixels: room for the four à-trous
// steps (a reach of 30 pixels) around the features, in milliseconds.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "denoise/cpu_denoiser.h"

namespace vkpt::test::denoise_test {
namespace {

constexpr std::uint32_t kSide = 48;

// A lit, diffuse image: a surface facing the camera at depth 2, of albedo `albedo(x, y)` under
// irradiance `light(x, y)`; each pixel's mean is the truth plus the noise of `samples` samples of
// per-sample standard deviation `sigma` × truth (a Gaussian stand-in for path-tracing noise).
struct Scene {
    std::function<glm::vec3(std::uint32_t, std::uint32_t)> albedo;
    std::function<float(std::uint32_t, std::uint32_t)> light;
    std::function<glm::vec3(std::uint32_t, std::uint32_t)> normal = [](auto, auto) {
        return glm::vec3(0, 0, 1);
    };
};

std::vector<glm::vec3> truthOf(const Scene& scene) {
    std::vector<glm::vec3> truth;
    for (std::uint32_t y = 0; y < kSide; ++y)
        for (std::uint32_t x = 0; x < kSide; ++x)
            truth.push_back(scene.albedo(x, y) * scene.light(x, y));
    return truth;
}

std::vector<gpu::DenoisePixel> noisyPixels(const Scene& scene, std::uint32_t samples, float sigma,
                                           std::uint32_t seed) {
    std::mt19937 random(seed);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    const std::vector<glm::vec3> truth = truthOf(scene);
    std::vector<gpu::DenoisePixel> pixels(truth.size());
    for (std::uint32_t i = 0; i < truth.size(); ++i) {
        const std::uint32_t x = i % kSide, y = i / kSide;
        const float deviation = sigma / std::sqrt(float(samples)); // of the mean, relative
        // Two halves of samples / 2 each, one factor of grey noise each; the mean is theirs.
        const float noiseA = normal(random) * deviation * std::sqrt(2.0f);
        const float noiseB = normal(random) * deviation * std::sqrt(2.0f);
        gpu::DenoisePixel& p = pixels[i];
        p.halfA = truth[i] * (1.0f + noiseA);
        p.halfB = truth[i] * (1.0f + noiseB);
        p.halfCountA = float(samples / 2);
        p.halfCountB = float(samples - samples / 2);
        p.radiance = 0.5f * (p.halfA + p.halfB);
        const float luminance = gpu::luminance(truth[i]);
        p.luminanceVariance = luminance * luminance * deviation * deviation;
        p.albedo = scene.albedo(x, y);
        p.depth = 2.0f;
        p.normal = scene.normal(x, y);
        p.sampleCount = samples;
    }
    return pixels;
}

std::vector<glm::vec3> denoised(const std::vector<gpu::DenoisePixel>& pixels) {
    return CpuDenoiser(1).denoise(pixels, kSide, kSide, DenoiseSettings{});
}

// Mean squared error relative to the truth's luminance (relMSE with a 1e-2 floor).
double relativeMse(const std::vector<glm::vec3>& image, const std::vector<glm::vec3>& truth) {
    double sum = 0.0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const glm::vec3 d = image[i] - truth[i];
        const double t = gpu::luminance(truth[i]);
        sum += double(glm::dot(d, d)) / 3.0 / (t * t + 1e-2);
    }
    return sum / double(truth.size());
}

std::vector<glm::vec3> radianceOf(const std::vector<gpu::DenoisePixel>& pixels) {
    std::vector<glm::vec3> radiance;
    for (const gpu::DenoisePixel& p : pixels)
        radiance.push_back(p.radiance);
    return radiance;
}

// Light that differs between any two pixels a tap apart (no two taps on one level line).
const Scene kSmooth{
    [](auto, auto) { return glm::vec3(0.5f); },
    [](std::uint32_t x, std::uint32_t y) { return 1.0f + 0.01f * float(x) + 0.0037f * float(y); }};

TEST(DenoiseGate, LeavesAnImageWithoutNoiseAsItIs) {
    // Every variance 0: whatever the neighbours' means, none can be explained by noise. An
    // albedo of 0.5 demodulates and modulates back exactly.
    std::vector<gpu::DenoisePixel> pixels = noisyPixels(kSmooth, 4, 0.5f, 1);
    for (gpu::DenoisePixel& p : pixels)
        p.luminanceVariance = 0.0f;
    const std::vector<glm::vec3> out = denoised(pixels);
    for (std::size_t i = 0; i < pixels.size(); ++i)
        ASSERT_EQ(out[i], pixels[i].radiance) << "pixel " << i;
}

TEST(DenoiseGate, TellsColoursOfOneLuminanceApart) {
    // The smooth scene's light in a red left half and a blue right half of one luminance: the
    // luminance test alone would take both halves in, the channel tests keep the columns beside
    // the edge within 10 % of their colour (noise 3 % of the mean: 256 samples).
    const glm::vec3 red(1.0f, 0.25f, 0.1f);
    const glm::vec3 blue =
        glm::vec3(0.1f, 0.25f, 1.0f) * (gpu::luminance(red) / gpu::luminance({0.1f, 0.25f, 1.0f}));
    const auto truthAt = [&](std::uint32_t x, std::uint32_t y) {
        return (x < kSide / 2 ? red : blue) * 0.5f * kSmooth.light(x, y);
    };
    std::vector<gpu::DenoisePixel> pixels = noisyPixels(kSmooth, 256, 0.5f, 6);
    for (std::uint32_t i = 0; i < pixels.size(); ++i) {
        const std::uint32_t x = i % kSide, y = i / kSide;
        const glm::vec3 truth = truthAt(x, y);
        const float factor = gpu::luminance(pixels[i].radiance) / (0.5f * kSmooth.light(x, y));
        pixels[i].radiance = truth * factor; // the grey scene's noise, now coloured
        pixels[i].halfA = truth * gpu::luminance(pixels[i].halfA) / (0.5f * kSmooth.light(x, y));
        pixels[i].halfB = truth * gpu::luminance(pixels[i].halfB) / (0.5f * kSmooth.light(x, y));
        const float deviation = gpu::luminance(truth) * 0.5f / 16.0f;
        pixels[i].luminanceVariance = deviation * deviation;
    }
    const std::vector<glm::vec3> out = denoised(pixels);
    for (std::uint32_t y = 4; y < kSide - 4; ++y)
        for (std::uint32_t x : {kSide / 2 - 1, kSide / 2}) {
            const glm::vec3 truth = truthAt(x, y), shown = out[std::size_t(y) * kSide + x];
            ASSERT_NEAR(shown.x, truth.x, 0.1f * truth.x) << "x " << x << ", y " << y;
            ASSERT_NEAR(shown.z, truth.z, 0.1f * truth.z) << "x " << x << ", y " << y;
        }
}

TEST(DenoiseConsistency, ConvergesToTheRawImageAsSamplesGrow) {
    // Never worse than the raw image, far better at 4 samples (a third of its error or less: the
    // blend of the candidates is weighted from halves of 2 samples each, itself noisy), and by
    // 2^24 samples (noise 1e-4 of the mean; neighbours differ by 2.6e-3 or more) the raw image
    // itself: the gap between the two is under 5 % of the raw error.
    const std::vector<glm::vec3> truth = truthOf(kSmooth);
    double lastGap = 1.0;
    for (std::uint32_t samples : {4u, 256u, 16384u, 1u << 24}) {
        const std::vector<gpu::DenoisePixel> pixels = noisyPixels(kSmooth, samples, 0.5f, 2);
        const std::vector<glm::vec3> raw = radianceOf(pixels), out = denoised(pixels);
        const double rawError = relativeMse(raw, truth);
        const double gap = relativeMse(out, raw) / rawError;
        EXPECT_LE(relativeMse(out, truth), rawError * 1.001) << samples << " samples";
        if (samples == 4u) {
            EXPECT_LT(relativeMse(out, truth), rawError / 3.0);
        }
        lastGap = gap;
    }
    EXPECT_LT(lastGap, 0.05) << "at 2^24 samples the output is the raw image";
}

TEST(DenoiseBlend, KeepsTheRawImageWhereTheVarianceMisleadsTheGate) {
    // Light in waves 10 % deep and 12 pixels long, and the render's variance 100× the truth
    // (noise it does not have, as a heavy tail's estimate can be off): the gate then takes in
    // neighbours across the waves, and every filtered candidate flattens them. The halves'
    // differences show the true noise, so the blend keeps the pixels (near) raw: at 4096
    // samples (noise 0.8 % of the mean) the output's error is at most 1.1× the raw one, where
    // the whole image after the four steps alone is many times worse.
    const Scene waves{[](auto, auto) { return glm::vec3(0.5f); },
                      [](std::uint32_t x, std::uint32_t y) {
                          return 1.0f + 0.1f * std::sin(0.52f * float(x) + 0.1f * float(y));
                      }};
    std::vector<gpu::DenoisePixel> pixels = noisyPixels(waves, 4096, 0.5f, 7);
    for (gpu::DenoisePixel& p : pixels)
        p.luminanceVariance *= 100.0f;
    const std::vector<glm::vec3> truth = truthOf(waves);
    const double rawError = relativeMse(radianceOf(pixels), truth);
    EXPECT_LE(relativeMse(denoised(pixels), truth), 1.1 * rawError);
}

TEST(DenoiseEdges, KeepsATextureSharp) {
    // A checkerboard of 4-pixel squares of albedo 0.8 and 0.1 under even light: demodulation
    // takes the texture out before the filter and multiplies it back after, so the pixels on
    // the squares' borders keep their values however hard the light is smoothed — a blur would
    // pull the bright ones down and the dark ones up by up to half the contrast. On average
    // over the ~1000 border pixels of each kind, within 3 % (the noise of that average is
    // under 1 %), and the whole image's error a quarter of the raw one or less.
    const Scene checker{[](std::uint32_t x, std::uint32_t y) {
                            return glm::vec3(((x / 4 + y / 4) % 2) ? 0.8f : 0.1f);
                        },
                        [](auto, auto) { return 1.0f; }};
    const std::vector<glm::vec3> truth = truthOf(checker);
    const std::vector<gpu::DenoisePixel> pixels = noisyPixels(checker, 16, 0.5f, 3);
    const std::vector<glm::vec3> out = denoised(pixels);
    double ratioSum[2] = {0.0, 0.0};
    int count[2] = {0, 0};
    for (std::uint32_t i = 0; i < truth.size(); ++i) {
        const std::uint32_t x = i % kSide, y = i / kSide;
        if (x % 4 != 0 && x % 4 != 3 && y % 4 != 0 && y % 4 != 3) continue; // inside a square
        const int bright = truth[i].x > 0.5f ? 1 : 0;
        ratioSum[bright] += double(out[i].x / truth[i].x);
        ++count[bright];
    }
    for (int bright : {0, 1})
        EXPECT_NEAR(ratioSum[bright] / count[bright], 1.0, 0.03) << (bright ? "bright" : "dark");
    EXPECT_LT(relativeMse(out, truth), relativeMse(radianceOf(pixels), truth) / 4.0);
}

TEST(DenoiseEdges, KeepsAShadowEdgeOnOneSurface) {
    // One surface, one albedo, light 1 on the left half and 0.2 on the right (a shadow): no
    // guide tells the halves apart, only the gate. At 64 samples (noise 6 % of the mean) the
    // difference is ~13 standard deviations, so the columns beside the edge keep their values.
    const Scene shadow{[](auto, auto) { return glm::vec3(0.5f); },
                       [](std::uint32_t x, std::uint32_t) { return x < kSide / 2 ? 1.0f : 0.2f; }};
    const std::vector<glm::vec3> truth = truthOf(shadow);
    const std::vector<glm::vec3> out = denoised(noisyPixels(shadow, 64, 0.5f, 4));
    for (std::uint32_t y = 4; y < kSide - 4; ++y)
        for (std::uint32_t x : {kSide / 2 - 1, kSide / 2}) {
            const std::size_t i = std::size_t(y) * kSide + x;
            ASSERT_NEAR(out[i].x, truth[i].x, 0.1 * truth[i].x) << "x " << x << ", y " << y;
        }
}

TEST(DenoiseFireflies, NeitherSpreadNorKept) {
    // One pixel's 16 samples hold one far above the rest (a caustic path found once): its mean
    // is 100× its neighbours' and its variance that of one sample of 1600. Its neighbours cap
    // its variance at their own, so their tests reject it and they stay within their noise; its
    // own test, with its own variance, takes in the neighbours, so the spot fades.
    std::vector<gpu::DenoisePixel> pixels = noisyPixels(kSmooth, 16, 0.5f, 5);
    const std::uint32_t fx = 20, fy = 20;
    gpu::DenoisePixel& firefly = pixels[fy * kSide + fx];
    const float spike = 100.0f * gpu::luminance(firefly.radiance);
    firefly.radiance *= 100.0f;
    firefly.halfA = 2.0f * firefly.radiance - firefly.halfB; // the spike fell in the even half
    firefly.luminanceVariance = spike * spike; // one sample 16·spike of 16: M2 / 15 / 16 ≈ spike²
    const std::vector<glm::vec3> truth = truthOf(kSmooth);
    const std::vector<glm::vec3> out = denoised(pixels);
    for (std::uint32_t y = fy - 3; y <= fy + 3; ++y)
        for (std::uint32_t x = fx - 3; x <= fx + 3; ++x) {
            const std::size_t i = std::size_t(y) * kSide + x;
            if (x == fx && y == fy) continue;
            ASSERT_LT(out[i].x, 1.15f * truth[i].x) << "x " << x << ", y " << y;
        }
    EXPECT_LT(out[fy * kSide + fx].x, 0.1f * firefly.radiance.x);
}

} // namespace
} // namespace vkpt::test::denoise_test
