// diffuse_transmission_test.cpp — KHR_materials_diffuse_transmission in shared/bsdf.h: the
// sampler draws from the pdf over the whole sphere (chi-square), weights and pdfs agree with
// evaluation, the white furnace returns exactly what it receives split between the two sides,
// no coloured or layered case gains, reflection and transmission are reciprocal, and MIS
// counts a transmitted sample only where light sampling reaches the far side.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "../support/bsdf_chi_square.h"
#include "../support/furnace.h"
#include "shared/bsdf.h"
#include "shared/path_rules.h"
#include "shared/rng.h"

namespace vkpt::diffuse_transmission_test {
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

using test::AlbedoEstimate;
using test::estimateAlbedo;
using test::viewAt;

struct TransmittingCase {
    const char* name;
    float roughness;
    float metallic;
    vec3 baseColor;
    float diffuseTransmission;
    vec3 diffuseTransmissionColor;
    float cosThetaO;
    float glass = 0.0f;     // KHR_materials_transmission, thin-walled, ior 1.5
    float clearcoat = 0.0f; // KHR_materials_clearcoat of roughness 0.3

    gpu::ShadingMaterial material() const {
        gpu::ShadingMaterial m =
            gpu::makeShadingMaterial(baseColor, metallic, roughness, 1.0f, vec3(1.0f), true);
        m = gpu::withDiffuseTransmission(m, diffuseTransmission, diffuseTransmissionColor);
        m.transmission = glass;
        m.thinWalled = true;
        if (clearcoat > 0.0f) m = gpu::withClearcoat(m, clearcoat, 0.3f);
        return m;
    }
    vec3 wo() const { return viewAt(cosThetaO); }
};

// A leaf-like dielectric, all-transmitting bases at a grazing view, a partly metallic one, one
// under a clearcoat, and one that is half rough thin glass (both transmitted lobes together).
const TransmittingCase kCases[] = {
    {"dielectric r0.5 dt0.5", 0.5f, 0.0f, vec3(0.3f, 0.6f, 0.1f), 0.5f, vec3(0.7f, 0.9f, 0.3f),
     0.7f},
    {"dielectric r0.8 dt1 grazing", 0.8f, 0.0f, vec3(0.8f), 1.0f, vec3(0.9f, 0.5f, 0.2f), 0.1f},
    {"dielectric r0.3 dt0.3 normal", 0.3f, 0.0f, vec3(0.5f), 0.3f, vec3(1.0f), 1.0f},
    {"half metal r0.6 dt0.7", 0.6f, 0.5f, vec3(0.7f), 0.7f, vec3(0.6f), 0.5f},
    {"dt0.6 under clearcoat", 0.7f, 0.0f, vec3(0.4f), 0.6f, vec3(0.8f), 0.6f, 0.0f, 1.0f},
    {"dt0.5 with rough thin glass", 0.5f, 0.0f, vec3(0.6f), 0.5f, vec3(0.9f), 0.8f, 0.5f},
};

// Cells over the whole sphere: the lobes here are broad (roughness ≥ 0.3), which 24 × 24 cells
// of 16 × 16 sub-cells each resolve.
using WholeSphereGrid = test::SphereGrid<24, 24, 16>;

// Each case drawn 2·10^5 times (streams 700, 701, ...).
test::SamplingAnalyses analyses = test::samplingAnalysesOf(
    kCases, 700u, [](const TransmittingCase&) { return WholeSphereGrid(); });

// Pearson's chi-square over the sphere's cells (and the invalid samples), family-wise α = 0.01
// over the six cases (Šidák).
TEST(DiffuseTransmission, SampledDirectionsMatchThePdfByChiSquare) {
    test::expectSamplesFollowThePdf(analyses);
}

// ∫ pdf over the sphere + the invalid share = 1; the midpoint rule's error on these broad lobes
// stays below 2e-3 (measured 4e-4 at most).
TEST(DiffuseTransmission, PdfIntegratesToOneLessTheInvalidShare) {
    test::expectPdfIntegratesToOneLessTheInvalidShare(analyses, 2e-3);
}

// Every valid sample's weight is f·|cos θi|/pdf and its pdf bsdfPdf's; and transmitted samples
// do occur.
TEST(DiffuseTransmission, SampleWeightAndPdfAgreeWithEvaluation) {
    for (const TransmittingCase& c : kCases) {
        int below = 0;
        auto countBelow = [&below](const gpu::BsdfSample& s) { below += s.direction.z < 0.0f; };
        ASSERT_NO_FATAL_FAILURE(test::expectSamplesAgreeWithEvaluation(
            c.material(), c.wo(), 20000, 31, 1e-6f, 1e-5f, c.name, countBelow));
        EXPECT_GT(below, 1000) << c.name;
    }
}

// The transmitted share of an albedo estimate: Σ weight over samples below the surface / n.
double transmittedAlbedo(const gpu::ShadingMaterial& m, float cosThetaO, int samples,
                         std::uint32_t seed) {
    const vec3 wo = viewAt(cosThetaO);
    double sum = 0.0;
    for (std::uint32_t i = 0; i < std::uint32_t(samples); ++i) {
        const vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_BSDF);
        const gpu::BsdfSample s = gpu::sampleBsdf(m, wo, vec2(u.x, u.y), u.w);
        if (s.valid && s.direction.z < 0.0f) sum += double(s.weight.x);
    }
    return sum / samples;
}

// White furnace of the white dielectric (base and transmission colour 1, specular 1): the
// specular layer reflects E_s(μo), the diffuse base receives 1 − E_s(μo) and sends dt of it to
// the other side, so the albedo over both sides is exactly 1 (up to the tables' 0.0012, as
// bsdf_test's white dielectric) and the transmitted part dt·(1 − E_s(μo)). 10^5 samples per
// point, bounds 3σ plus the tables' error.
TEST(DiffuseTransmission, WhiteFurnaceReturnsAllItReceivesSplitBetweenTheSides) {
    constexpr double kTableError = 0.0012;
    constexpr int kSamples = 100000;
    for (float dt : {0.3f, 1.0f})
        for (float roughness : {0.2f, 0.6f, 1.0f})
            for (float cosThetaO : {1.0f, 0.5f, 0.1f}) {
                gpu::ShadingMaterial m = gpu::withDiffuseTransmission(
                    gpu::makeShadingMaterial(vec3(1.0f), 0.0f, roughness, 1.0f, vec3(1.0f), true),
                    dt, vec3(1.0f));
                AlbedoEstimate e = estimateAlbedo(m, cosThetaO, kSamples, 41);
                SCOPED_TRACE(::testing::Message()
                             << "dt " << dt << " roughness " << roughness << " cos " << cosThetaO);
                EXPECT_NEAR(e.mean, 1.0, 3.0 * e.sigma + kTableError);
                const double specular =
                    double(gpu::dielectricSpecularAlbedo(m, viewAt(cosThetaO)).x);
                const double expected = double(dt) * (1.0 - specular);
                // The transmitted part's own noise is below the whole estimate's σ·√2 here.
                EXPECT_NEAR(transmittedAlbedo(m, cosThetaO, kSamples, 41), expected,
                            4.0 * e.sigma + 2.0 * kTableError);
            }
}

// No case returns more than it receives (each channel of each case, at its view and two more).
TEST(DiffuseTransmission, NoCaseGains) {
    for (const TransmittingCase& c : kCases)
        for (float cosThetaO : {c.cosThetaO, 0.9f, 0.2f})
            for (int channel = 0; channel < 3; ++channel) {
                AlbedoEstimate e = estimateAlbedo(c.material(), cosThetaO, 50000, 43, channel);
                EXPECT_LE(e.mean, 1.0 + 4.0 * e.sigma + 0.0012)
                    << c.name << " cos " << cosThetaO << " channel " << channel;
            }
}

// Reflection is reciprocal, f(wo, wi) = f(wi, wo), and so is transmission seen from either side:
// light from wi below leaving towards wo is, looked at from below (the frame turned over),
// light from mirror(wo) leaving towards mirror(wi). Materials without the one-sided layers
// (clearcoat and sheen take the one-sided form, bsdf.h).
TEST(DiffuseTransmission, ReflectionAndTransmissionAreReciprocal) {
    for (const TransmittingCase& c : kCases) {
        if (c.clearcoat > 0.0f || c.glass > 0.0f) continue;
        const gpu::ShadingMaterial m = c.material();
        for (std::uint32_t i = 0; i < 20000; ++i) {
            vec4 u = gpu::randomFloats(47, i, 0, 0, DIM_BSDF);
            vec3 wo = gpu::sampleUniformHemisphere(vec2(u.x, u.y));
            vec3 wi = gpu::sampleUniformHemisphere(vec2(u.z, u.w));
            vec3 reflected = gpu::evaluateBsdf(m, wo, wi);
            vec3 reflectedBack = gpu::evaluateBsdf(m, wi, wo);
            vec3 below = gpu::mirroredThroughSurface(wi);
            vec3 transmitted = gpu::evaluateBsdf(m, wo, below);
            vec3 transmittedBack = gpu::evaluateBsdf(m, gpu::mirroredThroughSurface(below),
                                                     gpu::mirroredThroughSurface(wo));
            ASSERT_GT(transmitted.x, 0.0f) << c.name;
            for (int ch = 0; ch < 3; ++ch) {
                ASSERT_NEAR(reflected[ch], reflectedBack[ch], 1e-5f * reflected[ch] + 1e-30f)
                    << c.name;
                ASSERT_NEAR(transmitted[ch], transmittedBack[ch], 1e-5f * transmitted[ch])
                    << c.name;
            }
        }
    }
}

// With dt = 0 the material is the one it was without the extension, bit for bit.
TEST(DiffuseTransmission, ZeroFactorLeavesTheBsdfUnchanged) {
    const gpu::ShadingMaterial plain =
        gpu::makeShadingMaterial(vec3(0.4f, 0.5f, 0.6f), 0.2f, 0.5f, 1.0f, vec3(1.0f), true);
    const gpu::ShadingMaterial zero = gpu::withDiffuseTransmission(plain, 0.0f, vec3(0.5f));
    for (std::uint32_t i = 0; i < 2000; ++i) {
        vec4 u = gpu::randomFloats(53, i, 0, 0, DIM_BSDF);
        vec3 wo = gpu::sampleUniformHemisphere(vec2(u.x, u.y));
        gpu::BsdfSample a = gpu::sampleBsdf(plain, wo, vec2(u.z, u.w), u.x);
        gpu::BsdfSample b = gpu::sampleBsdf(zero, wo, vec2(u.z, u.w), u.x);
        ASSERT_EQ(a.valid, b.valid);
        ASSERT_EQ(a.direction, b.direction);
        ASSERT_EQ(a.weight, b.weight);
        ASSERT_EQ(a.pdf, b.pdf);
    }
}

// MIS: a transmitted sample of a thin wall that transmits diffusely keeps its pdf (light sampling
// reaches the far side), one of a volume or of glass alone is not light sampled; reflections
// keep theirs.
TEST(DiffuseTransmission, TransmittedSamplesAreLightSampledOnlyThroughThinWalls) {
    gpu::ShadingMaterial thin = kCases[0].material();
    gpu::ShadingMaterial solid = thin;
    solid.thinWalled = false;
    gpu::BsdfSample transmitted = gpu::invalidBsdfSample();
    transmitted.direction = vec3(0.0f, 0.6f, -0.8f);
    transmitted.pdf = 0.25f;
    transmitted.valid = true;
    gpu::BsdfSample reflected = transmitted;
    reflected.direction.z = 0.8f;
    EXPECT_EQ(gpu::misPdfOfBsdfSample(transmitted, thin), 0.25f);
    EXPECT_EQ(gpu::misPdfOfBsdfSample(transmitted, solid), PDF_NOT_LIGHT_SAMPLED);
    EXPECT_EQ(gpu::misPdfOfBsdfSample(reflected, solid), 0.25f);
    gpu::ShadingMaterial glass =
        gpu::makeShadingMaterial(vec3(1.0f), 0.0f, 0.5f, 1.0f, vec3(1.0f), true);
    glass.transmission = 1.0f;
    EXPECT_EQ(gpu::misPdfOfBsdfSample(transmitted, glass), PDF_NOT_LIGHT_SAMPLED);
}

} // namespace
} // namespace vkpt::diffuse_transmission_test
