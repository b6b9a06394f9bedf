// render_checks.h — checks of whole renders that hold for either executor, so that vkpt-ref
// (tests/render) and vkpt (tests/image) are held to the same analytic values and promises.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "image/image_compare.h"
#include "image/render_output.h"
#include "scene/scene.h"
#include "shared/adaptive.h"
#include "shared/sampling.h"

namespace vkpt::test {

// Two renders of one scene by independent estimators (or seeds) agree in distribution: the
// per-pixel Welch test at family-wise α = 0.01 over all pixels (Šidák), variances from the
// renders themselves.
inline void expectSameImage(const RenderOutput& a, const RenderOutput& b, const std::string& what) {
    ZTestResult z = zTestPerPixel(a, b, 0.01);
    EXPECT_TRUE(z.passed) << what << ": " << z.summary;
}

// The white furnace: inside a closed surface of albedo a emitting E, the radiance with at most
// D scattering events is exactly E·(1 − a^(D+1)) / (1 − a) everywhere.
struct FurnaceParameters {
    float emission;
    float albedo;
};

inline FurnaceParameters furnaceParameters(const Scene& scene) {
    const SceneMaterial& m = scene.materials.at(0);
    return {gpu::luminance(m.emission), gpu::luminance(glm::vec3(m.baseColor))};
}

inline double furnaceRadiance(const FurnaceParameters& p, std::uint32_t maxDepth) {
    double a = p.albedo;
    return p.emission * (1.0 - std::pow(a, double(maxDepth) + 1.0)) / (1.0 - a);
}

// The image mean must lie within 4.42 standard errors (two-sided p = 1e-5) of the analytic
// value, the standard error coming from the render's own per-pixel variances, plus a float
// rounding allowance of 1e-5 relative.
inline void expectFurnaceMean(const RenderOutput& output, double expected,
                              const std::string& what) {
    MeanEstimate mean = meanLuminance(output);
    double bound = 4.42 * mean.standardError + 1e-5 * expected;
    EXPECT_NEAR(mean.mean, expected, bound) << what << ": standard error " << mean.standardError;
}

inline float maxEmittedLuminance(const Scene& scene) {
    float m = 0.0f;
    for (const SceneMaterial& material : scene.materials)
        m = std::max(m, gpu::luminance(material.emission));
    return m;
}

// The Cornell box (scenes/cornell-box.gltf, camera 0, a square image): every pixel finite and
// non-negative; the mean below Le·ρ/(1 − ρ) with ρ the largest albedo (each bounce keeps at
// most ρ of the energy); the red wall on the left, the green wall on the right.
inline void expectCornellBoxPlausible(const RenderOutput& output, const Scene& scene) {
    const Image& image = output.image;
    float albedo = 0.0f;
    for (const SceneMaterial& m : scene.materials)
        albedo = std::max(albedo, gpu::luminance(glm::vec3(m.baseColor)));
    const std::uint32_t edge = image.width / 8;
    double mean = 0.0;
    glm::dvec3 left(0.0), right(0.0);
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const glm::vec3& p = image.at(x, y);
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
                << x << "," << y;
            ASSERT_TRUE(p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f) << x << "," << y;
            mean += gpu::luminance(p);
            if (x < edge) left += glm::dvec3(p);
            if (x >= image.width - edge) right += glm::dvec3(p);
        }
    mean /= double(image.pixels.size());
    EXPECT_LT(mean, maxEmittedLuminance(scene) * albedo / (1.0f - albedo));
    EXPECT_GT(mean, 0.0);
    EXPECT_GT(left.r, left.g) << "red wall on the left";
    EXPECT_GT(right.g, right.r) << "green wall on the right";
}

// Pixels that stopped early promised a 95 % interval of half-width tol·max(μ, floor); against a
// far more converged render, at least 90 % of them must lie within it (the 95 % promise less
// slack for the estimated σ and the reference's own noise).
inline void expectAdaptivePromiseKept(const RenderOutput& adaptive, const RenderOutput& reference,
                                      std::uint32_t budget, float tolerance) {
    int stopped = 0, within = 0;
    for (std::size_t i = 0; i < adaptive.sampleCounts.size(); ++i) {
        if (adaptive.sampleCounts[i] >= budget) continue;
        float truth = gpu::luminance(reference.image.pixels[i]);
        float estimate = gpu::luminance(adaptive.image.pixels[i]);
        ++stopped;
        within += std::abs(estimate - truth) <= tolerance * std::max(truth, ADAPTIVE_DARK_FLOOR);
    }
    ASSERT_GT(stopped, 50);
    EXPECT_GE(double(within) / stopped, 0.90) << within << " of " << stopped;
}

} // namespace vkpt::test
