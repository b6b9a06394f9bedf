// bsdf_dielectric_test.cpp — the glass lobe of shared/bsdf_dielectric.h through the material
// of shared/bsdf.h: its sampler draws from its pdf over the whole sphere (chi-square, reflection
// and transmission, entering and leaving), weights and pdfs agree with evaluation, the smooth
// lobe splits by the exact Fresnel term, energy is conserved (white furnace), and the Fresnel
// term has its known values.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/bsdf_chi_square.h"
#include "../support/furnace.h"
#include "shared/bsdf.h"
#include "shared/rng.h"

namespace vkpt::bsdf_dielectric_test {
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

using test::viewAt;

// A glass material: metallic 0, the given transmission, roughness and η (the ratio the path
// crosses: ior entering, 1/ior leaving), white, specular 1.
gpu::ShadingMaterial glass(float roughness, float eta, bool thinWalled = false,
                           float transmission = 1.0f, vec3 tint = vec3(1.0f)) {
    gpu::ShadingMaterial m =
        gpu::makeShadingMaterial(tint, 0.0f, roughness, 1.0f, vec3(1.0f), true);
    m.transmission = transmission;
    m.eta = eta;
    m.thinWalled = thinWalled;
    const float ior = eta < 1.0f ? 1.0f / eta : eta;
    const float r = (ior - 1.0f) / (ior + 1.0f);
    m.iorF0 = r * r;
    return m;
}

struct GlassCase {
    const char* name;
    float roughness;
    float eta;
    bool thinWalled;
    float transmission;
    float cosThetaO;
    gpu::ShadingMaterial material() const {
        return glass(roughness, eta, thinWalled, transmission, vec3(0.9f, 0.8f, 0.7f));
    }
    vec3 wo() const { return viewAt(cosThetaO); }
};

// α = roughness² from 0.09 to 0.64; entering (η > 1) and leaving (η < 1, total internal
// reflection past the critical angle) glass and water; a thin wall; glass over the opaque
// lobes (transmission 0.5).
const GlassCase kCases[] = {
    {"enter r0.3 eta1.5", 0.3f, 1.5f, false, 1.0f, 0.8f},
    {"enter r0.5 eta1.5 grazing", 0.5f, 1.5f, false, 1.0f, 0.15f},
    {"enter r0.8 eta1.33", 0.8f, 1.33f, false, 1.0f, 0.6f},
    {"leave r0.3 eta1/1.5", 0.3f, 1.0f / 1.5f, false, 1.0f, 0.9f},
    {"leave r0.5 eta1/1.5 past critical", 0.5f, 1.0f / 1.5f, false, 1.0f, 0.5f},
    {"leave r0.8 eta1/1.33", 0.8f, 1.0f / 1.33f, false, 1.0f, 0.7f},
    {"thin r0.5", 0.5f, 1.5f, true, 1.0f, 0.7f},
    {"half glass r0.5", 0.5f, 1.5f, false, 0.5f, 0.6f},
};
constexpr int kCaseCount = int(sizeof(kCases) / sizeof(kCases[0]));

// Cells over the whole sphere, 40 in cos θ by 32 in φ, each integrated on 24 × 24 sub-cells. The
// integral of the pdf over all cells, plus the share of invalid samples, is 1 within 1e-3
// (PdfIntegratesToOneLessTheInvalidSamples), which bounds the quadrature.
using SphereGrid = test::SphereGrid<40, 32, 24>;

// Each case drawn 2·10^5 times (streams 300, 301, ...) into the sphere's cells.
test::SamplingAnalyses analyses =
    test::samplingAnalysesOf(kCases, 300u, [](const GlassCase&) { return SphereGrid(); });

// Chi-square over the sphere's cells plus one outcome for invalid samples (visible normals
// that reflect below or refract above the surface). α = 0.01 for the family, Šidák-corrected
// per case.
TEST(Dielectric, SampledDirectionsMatchThePdfOverTheSphereByChiSquare) {
    test::expectSamplesFollowThePdf(analyses);
}

// Both hemispheres are sampled: each case transmits and reflects a real share.
TEST(Dielectric, SamplesReachBothSidesOfTheSurface) {
    for (int k = 0; k < kCaseCount; ++k) {
        const test::SamplingAnalysis& a = analyses[k];
        double below = 0.0; // the lower half of the cos θ bins
        for (int cell = 0; cell < SphereGrid().cells() / 2; ++cell)
            below += a.observed[size_t(cell)];
        EXPECT_GT(below, 0.02 * a.samples) << kCases[k].name;
        EXPECT_LT(below, 0.98 * a.samples) << kCases[k].name;
    }
}

// ∫ pdf + invalid share = 1: within 4 binomial σ of the invalid share plus 1e-3 for the
// midpoint quadrature.
TEST(Dielectric, PdfIntegratesToOneLessTheInvalidSamples) {
    test::expectPdfIntegratesToOneLessTheInvalidShare(analyses, 1e-3);
}

// The weight is f·|cos θi|/pdf and the pdf is bsdfPdf's, for every sampled direction of a rough
// lobe, on both sides.
TEST(Dielectric, SampleWeightIsFTimesCosineOverPdf) {
    for (const GlassCase& c : kCases) {
        auto rough = [&c](const gpu::BsdfSample& s) { ASSERT_FALSE(s.delta) << c.name; };
        ASSERT_NO_FATAL_FAILURE(test::expectSamplesAgreeWithEvaluation(
            c.material(), c.wo(), 20000, 13, 1e-5f, 1e-4f, c.name, rough));
    }
}

// ---------------------------------------------------------------------------------------------
// The exact Fresnel term: 0.04 at normal incidence for η = 1.5, total internal reflection past
// the critical angle, and reciprocity across the interface (the same reflectance from both
// sides for a refracted pair of angles).
TEST(Dielectric, FresnelHasItsKnownValues) {
    EXPECT_NEAR(gpu::dielectricFresnel(1.0f, 1.5f), 0.04f, 1e-7f);
    EXPECT_NEAR(gpu::dielectricFresnel(1.0f, 1.0f / 1.5f), 0.04f, 1e-7f);
    EXPECT_EQ(gpu::dielectricFresnel(0.0f, 1.5f), 1.0f);
    const float critical = std::sqrt(1.0f - 1.0f / (1.5f * 1.5f)); // cos of the critical angle
    EXPECT_EQ(gpu::dielectricFresnel(critical * 0.99f, 1.0f / 1.5f), 1.0f);
    EXPECT_LT(gpu::dielectricFresnel(critical * 1.01f, 1.0f / 1.5f), 1.0f);
    for (float cosI : {0.9f, 0.5f, 0.2f}) {
        float sin2T = (1.0f - cosI * cosI) / (1.5f * 1.5f);
        float cosT = std::sqrt(1.0f - sin2T);
        EXPECT_NEAR(gpu::dielectricFresnel(cosI, 1.5f), gpu::dielectricFresnel(cosT, 1.0f / 1.5f),
                    1e-6f);
    }
    // Brewster's angle, tan θ = η: the parallel polarisation vanishes, leaving half of the
    // perpendicular one, ((η² − 1)/(η² + 1))² / 2.
    float cosB = 1.0f / std::sqrt(1.0f + 1.5f * 1.5f);
    float perpendicular = (1.5f * 1.5f - 1.0f) / (1.5f * 1.5f + 1.0f);
    EXPECT_NEAR(gpu::dielectricFresnel(cosB, 1.5f), 0.5f * perpendicular * perpendicular, 1e-6f);
}

// The smooth lobe: a sample reflects (mirror direction, weight 1) with probability F and
// refracts by Snell's law (weight tint/η²) otherwise; the reflected share of N samples is F
// within 4 binomial σ.
TEST(Dielectric, SmoothLobeSplitsByTheFresnelTerm) {
    const vec3 tint(0.9f, 0.5f, 0.25f);
    for (float eta : {1.5f, 1.0f / 1.5f}) {
        for (float cosTheta : {1.0f, 0.7f, 0.3f}) {
            gpu::ShadingMaterial m = glass(0.0f, eta, false, 1.0f, tint);
            vec3 wo = viewAt(cosTheta);
            const double f = gpu::dielectricFresnel(cosTheta, eta);
            const int n = 100000;
            int reflected = 0;
            for (uint32_t i = 0; i < uint32_t(n); ++i) {
                vec4 u = gpu::randomFloats(14, i, 0, 0, DIM_BSDF);
                gpu::BsdfSample s = gpu::sampleBsdf(m, wo, vec2(u.x, u.y), u.w);
                ASSERT_TRUE(s.valid && s.delta);
                if (s.direction.z > 0.0f) {
                    ++reflected;
                    ASSERT_EQ(s.direction, vec3(-wo.x, -wo.y, wo.z));
                    ASSERT_EQ(s.weight, vec3(1.0f));
                    ASSERT_FLOAT_EQ(s.pdf, float(f));
                } else {
                    // Snell: η sin θt = sin θo, in the plane of incidence on the far side.
                    float sinT = std::sqrt(1.0f - s.direction.z * s.direction.z);
                    ASSERT_NEAR(eta * sinT, wo.x, 1e-6f);
                    ASSERT_LT(s.direction.x, 0.0f + 1e-7f);
                    ASSERT_EQ(s.weight, tint / (eta * eta));
                    ASSERT_FLOAT_EQ(s.pdf, float(1.0 - f));
                }
            }
            const double sigma = std::sqrt(std::max(f * (1.0 - f), 1e-12) / n);
            EXPECT_NEAR(double(reflected) / n, f, 4.0 * sigma + 1e-6)
                << "eta " << eta << " cos " << cosTheta;
        }
    }
}

// The delta lobe is invisible to evaluation: f and pdf are 0 in every direction, so light
// sampling cannot count it (its samples carry the delta flag instead).
TEST(Dielectric, SmoothLobeHasNoDensity) {
    gpu::ShadingMaterial m = glass(0.0f, 1.5f);
    vec3 wo = viewAt(0.6f);
    for (vec3 wi : {vec3(-wo.x, -wo.y, wo.z), -wo, vec3(0.0f, 0.0f, -1.0f)}) {
        EXPECT_EQ(gpu::evaluateBsdf(m, wo, wi), vec3(0.0f));
        EXPECT_EQ(gpu::bsdfPdf(m, wo, wi), 0.0f);
    }
}

// ---------------------------------------------------------------------------------------------
// White furnace. The sample weights are radiance weights, which a refraction scales by 1/η²;
// energy (flux) is conserved when reflection's weight plus η² × transmission's is at most 1.
// Smooth glass loses nothing: every sample's energy weight is 1 to float rounding. Rough glass
// loses what single-scattering microfacets lose (bsdf_test's metal table) and must never
// gain: the mean of 10^5 samples at most 1 + 3σ.
struct EnergyEstimate {
    double mean = 0.0;
    double sigma = 0.0;
    double largest = 0.0;
};

EnergyEstimate estimateEnergy(const gpu::ShadingMaterial& m, float cosTheta, int samples,
                              uint32_t seed) {
    vec3 wo = viewAt(cosTheta);
    double sum = 0.0, sumSquares = 0.0, largest = 0.0;
    for (uint32_t i = 0; i < uint32_t(samples); ++i) {
        vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_BSDF);
        gpu::BsdfSample s = gpu::sampleBsdf(m, wo, vec2(u.x, u.y), u.w);
        double w = 0.0;
        if (s.valid) {
            bool refracted = s.direction.z < 0.0f && !m.thinWalled;
            w = double(s.weight.x) * (refracted ? double(m.eta) * double(m.eta) : 1.0);
        }
        sum += w;
        sumSquares += w * w;
        largest = std::max(largest, w);
    }
    EnergyEstimate e;
    e.mean = sum / samples;
    e.sigma = std::sqrt(std::max(0.0, sumSquares / samples - e.mean * e.mean) / samples);
    e.largest = largest;
    return e;
}

TEST(Dielectric, SmoothGlassFurnaceIsExactlyOne) {
    for (bool thin : {false, true})
        for (float eta : {1.5f, 1.0f / 1.5f, 1.33f})
            for (float cosTheta : {1.0f, 0.5f, 0.1f}) {
                EnergyEstimate e = estimateEnergy(glass(0.0f, eta, thin), cosTheta, 20000, 15);
                EXPECT_NEAR(e.mean, 1.0, 1e-6) << "eta " << eta << " cos " << cosTheta;
                EXPECT_LE(e.largest, 1.0 + 1e-6);
            }
}

TEST(Dielectric, RoughGlassFurnaceNeverGains) {
    for (bool thin : {false, true})
        for (float roughness : {0.1f, 0.3f, 0.6f, 1.0f})
            for (float eta : {1.5f, 1.0f / 1.5f})
                for (float cosTheta : {1.0f, 0.5f, 0.1f}) {
                    EnergyEstimate e =
                        estimateEnergy(glass(roughness, eta, thin), cosTheta, 100000, 16);
                    EXPECT_LE(e.mean, 1.0 + 3.0 * e.sigma)
                        << "thin " << thin << " roughness " << roughness << " eta " << eta
                        << " cos " << cosTheta;
                    // Nor does it lose more than single scattering can: at least 0.3, the
                    // metal's worst albedo (1 − ln 2 at α = 1) less the noise.
                    EXPECT_GE(e.mean, 0.3 - 3.0 * e.sigma);
                }
}

// ---------------------------------------------------------------------------------------------
// The opaque material keeps its exact arithmetic: without transmission, a material reads as
// before (F0 0.04 at ior 1.5), and with KHR_materials_ior F0 is ((ior − 1)/(ior + 1))².
TEST(Dielectric, IorSetsTheOpaqueDielectricsF0) {
    gpu::ShadingMaterial m =
        gpu::makeShadingMaterial(vec3(0.5f), 0.0f, 0.5f, 1.0f, vec3(1.0f), true);
    EXPECT_EQ(gpu::dielectricF0(m), vec3(0.04f));
    m.iorF0 = (0.33f / 2.33f) * (0.33f / 2.33f);
    EXPECT_NEAR(gpu::dielectricF0(m).x, 0.0200593f, 1e-6f);
}

} // namespace
} // namespace vkpt::bsdf_dielectric_test
