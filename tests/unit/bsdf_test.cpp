// bsdf_test.cpp — the metallic-roughness BRDF of shared/bsdf.h: its sampler draws from its pdf
// (chi-square), weights and pdfs agree with evaluation, the pdf integrates to one, white-furnace
// albedos, reciprocity, finite values at grazing angles, and the Lambertian material's exact
// arithmetic; the same for KHR_materials_anisotropy's stretched lobe.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/adaptive_simpson.h"
#include "../support/bsdf_chi_square.h"
#include "../support/furnace.h"
#include "common/math_constants.h"
#include "shared/bsdf.h"
#include "shared/rng.h"

namespace vkpt::bsdf_test {
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

using test::AlbedoEstimate;
using test::estimateAlbedo;
using test::viewAt;

struct BsdfCase {
    const char* name;
    float roughness;
    float metallic;
    float specular;
    vec3 baseColor;
    float cosThetaO;
    float clearcoat = 0.0f; // KHR_materials_clearcoat; 0: none
    float clearcoatRoughness = 0.0f;
    vec3 sheenColor = vec3(0.0f); // KHR_materials_sheen; black: none
    float sheenRoughness = 0.0f;
    float coatTilt = 0.0f;        // the clearcoat normal turned about y (clearcoatNormalTexture)
    float transmission = 0.0f;    // KHR_materials_transmission: solid glass of ior 1.5
    float anisotropy = 0.0f;      // KHR_materials_anisotropy strength; 0: isotropic
    float anisotropyAngle = 0.0f; // its direction's angle from the frame's x axis
    float iridescence = 0.0f;     // KHR_materials_iridescence factor (film ior 1.3); 0: none
    float filmThickness = 400.0f; // nm

    gpu::ShadingMaterial material() const {
        gpu::ShadingMaterial m =
            gpu::makeShadingMaterial(baseColor, metallic, roughness, specular, vec3(1.0f), true);
        if (clearcoat > 0.0f) m = gpu::withClearcoat(m, clearcoat, clearcoatRoughness);
        if (gpu::maxComponent(sheenColor) > 0.0f) m = gpu::withSheen(m, sheenColor, sheenRoughness);
        m.clearcoatNormal = vec3(std::sin(coatTilt), 0.0f, std::cos(coatTilt));
        m.transmission = transmission;
        m.eta = 1.5f;
        m.thinWalled = false;
        if (iridescence > 0.0f) m = gpu::withIridescence(m, iridescence, 1.3f, filmThickness);
        if (anisotropy > 0.0f)
            m = gpu::withAnisotropy(m, anisotropy,
                                    vec2(std::cos(anisotropyAngle), std::sin(anisotropyAngle)));
        return m;
    }
    vec3 wo() const { return viewAt(cosThetaO); }
    // The narrowest GGX lobe, which the chi-square grid resolves.
    float narrowestAlpha() const {
        gpu::ShadingMaterial m = material();
        return gpu::hasClearcoat(m) ? std::min(m.alpha, m.clearcoatAlpha) : m.alpha;
    }
};

// Narrow and broad lobes, metals, dielectrics and mixtures, normal to grazing views; clearcoat
// and sheen alone over a black base (each sampler on its own as far as the base lets it), and
// over dielectric and metal bases (the full mixture of four lobes); a clearcoat with its own
// tilted normal; both layers over rough solid glass (five lobes, transmission included); and
// KHR_materials_anisotropy's stretched lobe on metal, dielectric and a mixture under a coat; and
// KHR_materials_iridescence's film over a dielectric and a metal.
const BsdfCase kCases[] = {
    {"metal r0.05", 0.05f, 1.0f, 1.0f, vec3(0.9f, 0.6f, 0.3f), 0.8f},
    {"metal r0.3", 0.3f, 1.0f, 1.0f, vec3(1.0f), 0.5f},
    {"metal r0.7 grazing", 0.7f, 1.0f, 1.0f, vec3(0.8f), 0.01f},
    {"metal r1", 1.0f, 1.0f, 1.0f, vec3(1.0f), 0.9f},
    {"dielectric r0.05", 0.05f, 0.0f, 1.0f, vec3(0.5f, 0.7f, 0.2f), 0.6f},
    {"dielectric r0.3 grazing", 0.3f, 0.0f, 1.0f, vec3(0.8f), 0.02f},
    {"dielectric r0.7", 0.7f, 0.0f, 1.0f, vec3(1.0f), 1.0f},
    {"half metal r1 grazing", 1.0f, 0.5f, 0.5f, vec3(0.6f), 0.05f},
    {"half metal r0.05 grazing", 0.05f, 0.5f, 1.0f, vec3(0.6f), 0.1f},
    {"clearcoat r0.1 over black", 1.0f, 0.0f, 0.0f, vec3(0.0f), 0.7f, 1.0f, 0.1f},
    {"clearcoat r0.5 grazing over black", 1.0f, 0.0f, 0.0f, vec3(0.0f), 0.1f, 1.0f, 0.5f},
    {"sheen r0.3 over black", 1.0f, 0.0f, 0.0f, vec3(0.0f), 0.6f, 0.0f, 0.0f, vec3(1.0f), 0.3f},
    {"sheen r1 grazing over black", 1.0f, 0.0f, 0.0f, vec3(0.0f), 0.05f, 0.0f, 0.0f, vec3(0.8f),
     1.0f},
    {"clearcoat r0.05 over dielectric r0.6", 0.6f, 0.0f, 1.0f, vec3(0.5f, 0.3f, 0.2f), 0.5f, 0.8f,
     0.05f},
    {"clearcoat and sheen over half metal", 0.3f, 0.5f, 1.0f, vec3(0.7f), 0.3f, 0.6f, 0.2f,
     vec3(0.9f, 0.5f, 0.3f), 0.5f},
    {"clearcoat and sheen over dielectric grazing", 0.8f, 0.0f, 1.0f, vec3(0.6f), 0.05f, 1.0f, 0.3f,
     vec3(0.4f), 0.7f},
    {"clearcoat r0.3 tilted 25° over black", 1.0f, 0.0f, 0.0f, vec3(0.0f), 0.7f, 1.0f, 0.3f,
     vec3(0.0f), 0.0f, 0.436f},
    {"clearcoat r1 tilted 30° over black", 1.0f, 0.0f, 0.0f, vec3(0.0f), 1.0f, 1.0f, 1.0f,
     vec3(0.0f), 0.0f, 0.5236f},
    {"clearcoat r0.2 tilted -20° over dielectric r0.5", 0.5f, 0.0f, 1.0f, vec3(0.6f), 0.5f, 1.0f,
     0.2f, vec3(0.0f), 0.0f, -0.349f},
    {"clearcoat and sheen over rough glass", 0.4f, 0.0f, 1.0f, vec3(0.9f), 0.6f, 1.0f, 0.2f,
     vec3(0.5f), 0.6f, 0.0f, 1.0f},
    {"anisotropic metal r0.3 s0.8 at 40°", 0.3f, 1.0f, 1.0f, vec3(0.9f, 0.7f, 0.5f), 0.6f, 0.0f,
     0.0f, vec3(0.0f), 0.0f, 0.0f, 0.0f, 0.8f, 0.7f},
    {"anisotropic dielectric r0.1 s1 grazing at 115°", 0.1f, 0.0f, 1.0f, vec3(0.5f), 0.1f, 0.0f,
     0.0f, vec3(0.0f), 0.0f, 0.0f, 0.0f, 1.0f, 2.0f},
    {"anisotropic half metal r0.5 s0.5 at -57° under clearcoat", 0.5f, 0.5f, 1.0f, vec3(0.7f), 0.9f,
     1.0f, 0.1f, vec3(0.0f), 0.0f, 0.0f, 0.0f, 0.5f, -1.0f},
    {"iridescent dielectric r0.3 300 nm", 0.3f, 0.0f, 1.0f, vec3(0.4f), 0.7f, 0.0f, 0.0f,
     vec3(0.0f), 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 300.0f},
    {"iridescent metal r0.15 grazing 550 nm", 0.15f, 1.0f, 1.0f, vec3(0.9f, 0.6f, 0.3f), 0.15f,
     0.0f, 0.0f, vec3(0.0f), 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.7f, 550.0f},
};
constexpr int kCaseCount = int(sizeof(kCases) / sizeof(kCases[0]));

// Cells over the whole sphere of directions in spherical coordinates (θ', φ') about the mirror
// direction of wo. A GGX lobe of α = 0.0025 is a few milliradians wide: on a (cos θ, φ) grid
// about the normal it would fill one cell, so the θ' cells follow a blend of two distributions,
// half of them uniform in θ' and half packed like a Cauchy lobe of width 2α around the mirror
// direction; φ' is uniform.
class MirrorFrameGrid {
public:
    static constexpr int kThetaBins = 24;
    static constexpr int kPhiBins = 20;

    MirrorFrameGrid(vec3 wo, float alpha)
        : frame_(gpu::makeBasis(vec3(-wo.x, -wo.y, wo.z))), lobeWidth_(2.0 * alpha) {
        for (int k = 0; k <= kThetaBins; ++k)
            thetaEdges_.push_back(thetaAtWarp(double(k) / kThetaBins));
    }

    int cells() const { return kThetaBins * kPhiBins; }

    int cellOf(vec3 wi) const {
        vec3 local = gpu::worldToBasis(frame_, wi);
        // atan2, not acos(z): near the mirror direction cos θ' rounds to 1 in float.
        double theta = std::atan2(std::hypot(double(local.x), double(local.y)), double(local.z));
        double phi = std::atan2(double(local.y), double(local.x));
        if (phi < 0.0) phi += 2.0 * kPi;
        int ti = std::min(kThetaBins - 1, int(warp(theta) * kThetaBins));
        int pi = std::min(kPhiBins - 1, int(phi / (2.0 * kPi) * kPhiBins));
        return ti * kPhiBins + pi;
    }

    // ∫ over the cell of g(direction) dω, dω = sin θ' dθ' dφ', by nested adaptive Simpson to a
    // relative 1e-5 (with an absolute floor of 1e-12) in each of the nested integrals.
    template <typename G> double integrateCell(int cell, const G& g) const {
        int ti = cell / kPhiBins, pi = cell % kPhiBins;
        double phi0 = 2.0 * kPi * pi / kPhiBins, phi1 = 2.0 * kPi * (pi + 1) / kPhiBins;
        auto overPhi = [&](double theta) {
            double s = std::sin(theta);
            if (s == 0.0) return 0.0;
            auto alongPhi = [&](double phi) { return g(directionAt(theta, phi)); };
            return s * test::adaptiveSimpson(alongPhi, phi0, phi1);
        };
        return test::adaptiveSimpson(overPhi, thetaEdges_[size_t(ti)], thetaEdges_[size_t(ti + 1)]);
    }

private:
    vec3 directionAt(double theta, double phi) const {
        vec3 local(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                   float(std::cos(theta)));
        return gpu::basisToWorld(frame_, local);
    }

    double warp(double theta) const {
        double lobe = std::atan(theta / lobeWidth_) / std::atan(kPi / lobeWidth_);
        return 0.5 * lobe + 0.5 * theta / kPi;
    }

    double thetaAtWarp(double a) const {
        double lo = 0.0, hi = kPi;
        for (int i = 0; i < 100; ++i) {
            double mid = 0.5 * (lo + hi);
            (warp(mid) < a ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    }

    gpu::Basis frame_;
    double lobeWidth_;
    std::vector<double> thetaEdges_;
};

// Each case drawn 2·10^5 times (streams 100, 101, ...) into the mirror-frame cells about its
// narrowest lobe.
test::SamplingAnalyses analyses = test::samplingAnalysesOf(
    kCases, 100u, [](const BsdfCase& c) { return MirrorFrameGrid(c.wo(), c.narrowestAlpha()); });

// (a) Chi-square over the mirror-frame cells plus one outcome for invalid samples (GGX normals
// that reflect below the horizon). α = 0.01 for the family of cases, Šidák-corrected: each of
// the 25 cases is tested at 1 − (1 − 0.01)^(1/25) ≈ 0.00040.
TEST(Bsdf, SampledDirectionsMatchThePdfByChiSquare) {
    test::expectSamplesFollowThePdf(analyses);
}

// (b) The pdf integrates to one less the share of GGX samples lost below the horizon, which
// sampling measures: within 4 binomial σ of that share plus 2e-4 for the quadrature (nested
// adaptive Simpson, relative 1e-5 per cell); and never above one.
TEST(Bsdf, PdfIntegratesToOneLessTheReflectionsLostBelowTheHorizon) {
    test::expectPdfIntegratesToOneLessTheInvalidShare(analyses, 2e-4);
    for (int k = 0; k < kCaseCount; ++k)
        EXPECT_LE(analyses[k].integral, 1.0 + 2e-4) << kCases[k].name;
}

// The quadrature itself: the grid integrates the Lambertian pdf cos θ/π to one.
TEST(Bsdf, MirrorFrameQuadratureIntegratesTheCosinePdfToOne) {
    MirrorFrameGrid grid(viewAt(0.3f), 0.01f);
    double integral = 0.0;
    for (int cell = 0; cell < grid.cells(); ++cell)
        integral +=
            grid.integrateCell(cell, [](vec3 wi) { return std::max(0.0, double(wi.z)) / kPi; });
    EXPECT_NEAR(integral, 1.0, 1e-4);
}

// (b) The weight is f·|cos θi|/pdf and the pdf is bsdfPdf's, for every sampled direction; only
// glass leaves below the surface.
TEST(Bsdf, SampleWeightAndPdfAgreeWithEvaluation) {
    for (const BsdfCase& c : kCases) {
        auto staysAboveUnlessGlass = [&c](const gpu::BsdfSample& s) {
            if (c.transmission == 0.0f) {
                ASSERT_GT(s.direction.z, 0.0f) << c.name;
            }
        };
        ASSERT_NO_FATAL_FAILURE(test::expectSamplesAgreeWithEvaluation(
            c.material(), c.wo(), 20000, 12, 1e-6f, 1e-5f, c.name, staysAboveUnlessGlass));
    }
}

// ---------------------------------------------------------------------------------------------
// (c) White furnace: the directional albedo ∫ f cos θi dωi by Monte Carlo with sampleBsdf
// (tests/support/furnace.h).
constexpr float kFurnaceRoughness[] = {0.1f, 0.25f, 0.5f, 0.75f, 1.0f};
constexpr float kFurnaceCosines[] = {1.0f, 0.5f, 0.2f, 0.05f};
constexpr int kFurnaceSamples = 100000;

// White metal (baseColor 1, so F = 1): single-scattering GGX loses the energy of light that
// would scatter again between microfacets (Heitz et al. 2016, "Multiple-Scattering Microfacet
// BSDFs with the Smith Model"; Kulla and Conty 2017). Directional albedo of this BRDF by
// quadrature of evaluateBsdf·cos θi (the Monte Carlo estimates agree within 2σ):
//
//   roughness   cos θo = 1   0.5      0.2      0.05
//   0.10        0.9999       0.9997   0.9986   0.9762
//   0.25        0.9957       0.9883   0.9463   0.8941
//   0.50        0.9158       0.8573   0.8482   0.9331
//   0.75        0.6269       0.6632   0.7720   0.9049
//   1.00        0.3069       0.4507   0.6417   0.8478
//
// At α = 1 and normal incidence D = 1/π and the albedo is ∫₀¹ μ/(1 + μ) dμ = 1 − ln 2 = 0.3069
// exactly: a 69 % loss, more than the 40–60 % often quoted for roughness 1, which use other
// masking functions or α = roughness. With height-correlated masking the loss shrinks again
// towards grazing views, where the visible microfacets are the highest ones and what they
// reflect escapes. The test holds each Monte Carlo albedo (10^5 samples, σ ≤ 0.0013) at or
// below 1 + 4σ and its loss under the table's plus 0.01.
const float kMetalAlbedo[5][4] = {
    {0.9999f, 0.9997f, 0.9986f, 0.9762f}, {0.9957f, 0.9883f, 0.9463f, 0.8941f},
    {0.9158f, 0.8573f, 0.8482f, 0.9331f}, {0.6269f, 0.6632f, 0.7720f, 0.9049f},
    {0.3069f, 0.4507f, 0.6417f, 0.8478f},
};

TEST(Bsdf, WhiteMetalFurnaceNeverGainsAndLosesNoMoreThanMeasured) {
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 4; ++c) {
            gpu::ShadingMaterial m = gpu::makeShadingMaterial(
                vec3(1.0f), 1.0f, kFurnaceRoughness[r], 1.0f, vec3(1.0f), true);
            AlbedoEstimate e = estimateAlbedo(m, kFurnaceCosines[c], kFurnaceSamples, 21);
            EXPECT_LE(e.mean, 1.0 + 4.0 * e.sigma)
                << "roughness " << kFurnaceRoughness[r] << " cos " << kFurnaceCosines[c];
            EXPECT_GE(e.mean, kMetalAlbedo[r][c] - 0.01)
                << "roughness " << kFurnaceRoughness[r] << " cos " << kFurnaceCosines[c];
        }
}

TEST(Bsdf, WhiteMetalAlbedoAtAlphaOneAndNormalIncidenceIsOneMinusLnTwo) {
    gpu::ShadingMaterial m =
        gpu::makeShadingMaterial(vec3(1.0f), 1.0f, 1.0f, 1.0f, vec3(1.0f), true);
    AlbedoEstimate e = estimateAlbedo(m, 1.0f, 400000, 22);
    EXPECT_NEAR(e.mean, 1.0 - std::log(2.0), 4.0 * e.sigma);
}

// The white dielectric (baseColor 1, specular 1, specularColor 1). glTF's sample code weights
// the diffuse term by 1 − F(V·H) of its own half vector, not by what the specular lobe takes
// at wo, and reflected more than it received at grazing views (quadrature of that BRDF):
//
//   roughness   cos θo = 1   0.5      0.2      0.05
//   0.10        0.9999       1.0254   1.2974   1.6800
//   0.25        0.9998       1.0261   1.2373   1.3994
//   0.50        0.9966       1.0110   1.0736   1.1317
//   0.75        0.9850       0.9899   1.0094   1.0353
//   1.00        0.9722       0.9761   0.9844   1.0013
//
// bsdf.h's albedo scaling leaves the diffuse base exactly what the specular layer does not
// reflect, E_s(μo) + (1 − E_s(μo)) · 1 = 1, up to the bilinear interpolation of the tables
// (at most 0.0012 of E for cos θo ≥ 0.05, vkpt-albedo-tables --interpolation-error). The test
// holds every Monte Carlo albedo (10^5 samples) at or below 1 + 3σ + 0.0012 and above 1 − 3σ −
// 0.0012: energy is neither gained nor lost.
TEST(Bsdf, WhiteDielectricFurnaceReflectsExactlyWhatItReceives) {
    constexpr double kTableError = 0.0012;
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 4; ++c) {
            gpu::ShadingMaterial m = gpu::makeShadingMaterial(
                vec3(1.0f), 0.0f, kFurnaceRoughness[r], 1.0f, vec3(1.0f), true);
            AlbedoEstimate e = estimateAlbedo(m, kFurnaceCosines[c], kFurnaceSamples, 23);
            EXPECT_LE(e.mean, 1.0 + 3.0 * e.sigma + kTableError)
                << "roughness " << kFurnaceRoughness[r] << " cos " << kFurnaceCosines[c];
            EXPECT_GE(e.mean, 1.0 - 3.0 * e.sigma - kTableError)
                << "roughness " << kFurnaceRoughness[r] << " cos " << kFurnaceCosines[c];
        }
}

// KHR_materials_anisotropy: the white metal's stretched lobe never gains (it loses what
// single-scattering GGX loses, more along its rougher axis). The white dielectric's diffuse base
// takes what the isotropic tables leave it at the α of bsdf.h's baseAlbedoAlpha (the smaller of
// the projected roughness on the view's azimuth and √(αt·αb)), which measured no gain here
// (largest 1.0019, within its noise and the tables' 0.0012) and a loss of at most 4.2 % for
// cos θo ≥ 0.5 or roughness 0.5, up to 29 % for a smooth lobe (roughness 0.1, αb = 0.01, αt up
// to 1) seen at cos θo = 0.1, where one isotropic α cannot stand for a lobe so stretched. Views
// across the direction (0°), along it (90°) and between; 10^5 samples each.
constexpr double kAnisotropicLossAwayFromGrazing = 0.05;
constexpr double kAnisotropicLossAtGrazing = 0.3;

TEST(Bsdf, AnisotropicFurnaceNeverGains) {
    for (float roughness : {0.1f, 0.5f})
        for (float strength : {0.5f, 1.0f})
            for (float angle : {0.0f, 0.8f, 1.5708f})
                for (float cosThetaO : {1.0f, 0.5f, 0.1f})
                    for (float metallic : {0.0f, 1.0f}) {
                        gpu::ShadingMaterial m = gpu::withAnisotropy(
                            gpu::makeShadingMaterial(vec3(1.0f), metallic, roughness, 1.0f,
                                                     vec3(1.0f), true),
                            strength, vec2(std::cos(angle), std::sin(angle)));
                        AlbedoEstimate e = estimateAlbedo(m, cosThetaO, kFurnaceSamples, 28);
                        const std::string where =
                            "metallic " + std::to_string(metallic) + " roughness " +
                            std::to_string(roughness) + " strength " + std::to_string(strength) +
                            " angle " + std::to_string(angle) + " cos " + std::to_string(cosThetaO);
                        EXPECT_LE(e.mean, 1.0 + 3.0 * e.sigma + 0.0012) << where;
                        const double loss = cosThetaO >= 0.5f || roughness >= 0.5f
                                                ? kAnisotropicLossAwayFromGrazing
                                                : kAnisotropicLossAtGrazing;
                        if (metallic == 0.0f) {
                            EXPECT_GE(e.mean, 1.0 - loss) << where;
                        }
                    }
}

// Strength 0 is the isotropic lobe, and the stretched lobe's D integrates to one over projected
// area (∫ D(h) cos θh dω = 1) like the isotropic one.
TEST(Bsdf, AnisotropicDistributionIsNormalised) {
    for (vec2 alpha : {vec2(0.3f, 0.3f), vec2(0.6f, 0.1f), vec2(1.0f, 0.05f)}) {
        double sum = 0.0;
        constexpr int kSteps = 2000;
        for (int i = 0; i < kSteps; ++i)
            for (int j = 0; j < kSteps; ++j) {
                // cos θ uniform on [0, 1] per unit of cos: dω = d(cos θ) dφ.
                double cosTheta = (i + 0.5) / kSteps;
                double phi = 2.0 * kPi * (j + 0.5) / kSteps;
                double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
                vec3 h(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)),
                       float(cosTheta));
                sum += double(gpu::ggxDistributionAnisotropic(h, alpha)) * cosTheta;
            }
        sum *= (1.0 / kSteps) * (2.0 * kPi / kSteps);
        EXPECT_NEAR(sum, 1.0, 0.01) << alpha.x << " " << alpha.y;
    }
    vec3 h = glm::normalize(vec3(0.2f, -0.3f, 0.9f));
    EXPECT_FLOAT_EQ(gpu::ggxDistributionAnisotropic(h, vec2(0.4f)), gpu::ggxDistribution(h, 0.4f));
}

// The stretched lobe is reciprocal like the isotropic one (the diffuse base's tables are taken
// at one α for both directions).
TEST(Bsdf, AnisotropicBrdfIsReciprocal) {
    for (float metallic : {0.0f, 1.0f}) {
        gpu::ShadingMaterial m =
            gpu::withAnisotropy(gpu::makeShadingMaterial(vec3(0.8f, 0.5f, 0.3f), metallic, 0.4f,
                                                         1.0f, vec3(1.0f), true),
                                0.7f, glm::normalize(vec2(0.6f, -0.8f)));
        for (uint32_t i = 0; i < 20000; ++i) {
            vec4 u = gpu::randomFloats(29, i, 0, 0, DIM_BSDF);
            vec3 wo = gpu::sampleUniformHemisphere(vec2(u.x, u.y));
            vec3 wi = gpu::sampleUniformHemisphere(vec2(u.z, u.w));
            vec3 forward = gpu::evaluateBsdf(m, wo, wi);
            vec3 backward = gpu::evaluateBsdf(m, wi, wo);
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_NEAR(forward[ch], backward[ch], 1e-5f * forward[ch] + 1e-30f);
        }
    }
}

// KHR_materials_iridescence. The film loses no light (its reflectance plus transmittance is 1),
// so the white dielectric under it is lossless like the bare one: the diffuse base receives
// exactly what the film's highlight does not reflect, because the layering takes the highlight's
// albedo from the same Fresnel term the highlight uses (bsdf.h, dielectricSpecularAlbedos). The
// white metal under the film reflects at most 1: the film's term is a reflectance. Over roughness 0
// to 1, films from none to two fringes (0 to 700 nm, the extension's range and beyond) and views
// from normal to grazing, all three channels from one set of samples.
//
// Bound: |mean − 1| ≤ 4σ + 0.0015 for the dielectric, mean ≤ 1 + 4σ for the metal. 4σ keeps the
// family of 360 comparisons below a 2 % chance of a false alarm (Šidák); 0.0015 is the bilinear
// interpolation of the albedo tables (0.0012 of E for cos θo ≥ 0.05, as the white dielectric's
// furnace says) plus float rounding. Before the layering took the film's own albedo, this test
// failed 95 of its comparisons: a gain of 0.58 % (roughness 0.5, 250 nm, cos θo 0.2, blue), where
// quadrature had found up to 0.85 % at roughness 0.8, and losses of up to 46 % at cos θo 0.2.
constexpr double kIridescentFurnaceSigmas = 4.0;
constexpr double kIridescentFurnaceTolerance = 0.0015;
constexpr int kIridescentFurnaceSamples = 20000;

struct RgbAlbedoEstimate {
    vec3 mean;
    vec3 sigma;
};

// The albedo per channel at cos θo from `samples` draws of sampleBsdf (stream `seed`).
RgbAlbedoEstimate estimateRgbAlbedo(const gpu::ShadingMaterial& m, float cosThetaO, int samples,
                                    uint32_t seed) {
    const vec3 wo = viewAt(cosThetaO);
    glm::dvec3 sum(0.0), sumSquares(0.0);
    for (uint32_t i = 0; i < uint32_t(samples); ++i) {
        const vec4 u = gpu::randomFloats(seed, i, 0, 0, DIM_BSDF);
        const gpu::BsdfSample s = gpu::sampleBsdf(m, wo, vec2(u.x, u.y), u.w);
        const glm::dvec3 w = s.valid ? glm::dvec3(s.weight) : glm::dvec3(0.0);
        sum += w;
        sumSquares += w * w;
    }
    const glm::dvec3 mean = sum / double(samples);
    const glm::dvec3 variance = glm::max(sumSquares / double(samples) - mean * mean, 0.0);
    return {vec3(mean), vec3(glm::sqrt(variance / double(samples)))};
}

TEST(Bsdf, IridescentFurnace) {
    for (float roughness : {0.0f, 0.3f, 0.5f, 0.8f, 1.0f})
        for (float thickness : {0.0f, 250.0f, 400.0f, 700.0f})
            for (float cosThetaO : {1.0f, 0.6f, 0.2f})
                for (float metallic : {0.0f, 1.0f}) {
                    gpu::ShadingMaterial m = gpu::withIridescence(
                        gpu::makeShadingMaterial(vec3(1.0f), metallic, roughness, 1.0f, vec3(1.0f),
                                                 true),
                        1.0f, 1.3f, thickness);
                    const std::string where = "metallic " + std::to_string(metallic) +
                                              " roughness " + std::to_string(roughness) +
                                              " thickness " + std::to_string(thickness) + " cos " +
                                              std::to_string(cosThetaO);
                    const RgbAlbedoEstimate e =
                        estimateRgbAlbedo(m, cosThetaO, kIridescentFurnaceSamples, 30);
                    for (int channel = 0; channel < 3; ++channel) {
                        const double bound = kIridescentFurnaceSigmas * e.sigma[channel];
                        if (metallic == 1.0f) {
                            EXPECT_LE(e.mean[channel], 1.0 + bound) << where << " ch " << channel;
                        } else {
                            EXPECT_NEAR(e.mean[channel], 1.0, bound + kIridescentFurnaceTolerance)
                                << where << " ch " << channel;
                        }
                    }
                }
}

// The film's Fresnel term: in [0, 1]; a film of no thickness leaves the base's reflectance at
// normal incidence, up to the residue of the reference formula's clamp of R12·R23 at 1e-5 (its
// first harmonic, 2·√1e-5·(1 − f0) times the white sensitivity, about 0.007); thicknesses a
// fringe apart colour it differently.
TEST(Bsdf, IridescenceFresnelIsAReflectance) {
    const vec3 f0(0.04f, 0.5f, 0.9f);
    const vec3 bare = gpu::iridescenceFresnel(1.3f, 0.0f, 1.0f, f0);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(bare[c], f0[c], 0.009f) << "channel " << c;
    for (float thickness : {100.0f, 300.0f, 500.0f, 1200.0f})
        for (float cosTheta : {1.0f, 0.7f, 0.3f, 0.01f}) {
            const vec3 f = gpu::iridescenceFresnel(1.5f, thickness, cosTheta, vec3(0.04f));
            for (int c = 0; c < 3; ++c) {
                EXPECT_GE(f[c], 0.0f);
                EXPECT_LE(f[c], 1.0f);
            }
        }
    const vec3 thin = gpu::iridescenceFresnel(1.33f, 250.0f, 1.0f, vec3(0.04f));
    const vec3 thick = gpu::iridescenceFresnel(1.33f, 400.0f, 1.0f, vec3(0.04f));
    EXPECT_GT(glm::length(thin - thick), 0.02f) << "a fringe apart, the colours differ";
}

// The film's term as the BSDF takes it, interpolated between VKPT_FILM_NODES cosines
// (iridescence.h): equal to the formula at the nodes, and within 0.04 of it between them for films
// up to 400 nm, 0.065 up to 1200 nm (measured on a finer grid: 0.0385 and 0.0641), for film
// indices 1.2 to 2.2 over bases of F0 0.04 to 0.9. 1000 cosines per film.
TEST(Bsdf, InterpolatedFilmFollowsTheFormula) {
    for (float ior : {1.2f, 1.5f, 2.2f})
        for (float f0 : {0.04f, 0.5f, 0.9f})
            for (float thickness = 0.0f; thickness <= 1200.0f; thickness += 50.0f) {
                const float bound = thickness <= 400.0f ? 0.04f : 0.065f;
                for (int k = 0; k < VKPT_FILM_NODES; ++k) {
                    const float c = gpu::filmNodeCosine(k);
                    const vec3 exact = gpu::iridescenceFresnel(ior, thickness, c, vec3(f0));
                    const vec3 node =
                        gpu::interpolatedIridescenceFresnel(ior, thickness, c, vec3(f0));
                    ASSERT_LE(glm::length(node - exact), 1e-6f) << "node " << k;
                }
                for (int i = 0; i <= 1000; ++i) {
                    const float c = float(i) / 1000.0f;
                    const vec3 d =
                        gpu::interpolatedIridescenceFresnel(ior, thickness, c, vec3(f0)) -
                        gpu::iridescenceFresnel(ior, thickness, c, vec3(f0));
                    ASSERT_LE(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}), bound)
                        << "ior " << ior << " f0 " << f0 << " thickness " << thickness << " cos "
                        << c;
                }
            }
}

// The film keeps the BRDF reciprocal: its term is taken at V·H, the same both ways.
TEST(Bsdf, IridescentBrdfIsReciprocal) {
    for (float metallic : {0.0f, 1.0f}) {
        gpu::ShadingMaterial m =
            gpu::withIridescence(gpu::makeShadingMaterial(vec3(0.8f, 0.5f, 0.3f), metallic, 0.4f,
                                                          1.0f, vec3(1.0f), true),
                                 0.8f, 1.4f, 350.0f);
        for (uint32_t i = 0; i < 20000; ++i) {
            vec4 u = gpu::randomFloats(31, i, 0, 0, DIM_BSDF);
            vec3 wo = gpu::sampleUniformHemisphere(vec2(u.x, u.y));
            vec3 wi = gpu::sampleUniformHemisphere(vec2(u.z, u.w));
            vec3 forward = gpu::evaluateBsdf(m, wo, wi);
            vec3 backward = gpu::evaluateBsdf(m, wi, wo);
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_NEAR(forward[ch], backward[ch], 1e-4f * forward[ch] + 1e-30f);
        }
    }
}

// The Monte Carlo albedo equals the quadrature of evaluateBsdf·cos θi over the mirror-frame
// cells: sampling covers all of f, and the furnace figures above are the BRDF's own.
TEST(Bsdf, AlbedoBySamplingMatchesQuadrature) {
    const BsdfCase cases[] = {
        {"white dielectric r0.1 grazing", 0.1f, 0.0f, 1.0f, vec3(1.0f), 0.05f},
        {"white metal r0.5", 0.5f, 1.0f, 1.0f, vec3(1.0f), 0.5f},
        {"half metal r0.25", 0.25f, 0.5f, 1.0f, vec3(0.7f), 0.2f},
    };
    for (const BsdfCase& c : cases) {
        gpu::ShadingMaterial m = c.material();
        vec3 wo = c.wo();
        MirrorFrameGrid grid(wo, m.alpha);
        auto integrand = [&](vec3 wi) {
            return double(gpu::evaluateBsdf(m, wo, wi).x) * std::max(0.0, double(wi.z));
        };
        double quadrature = 0.0;
        for (int cell = 0; cell < grid.cells(); ++cell)
            quadrature += grid.integrateCell(cell, integrand);
        AlbedoEstimate e = estimateAlbedo(m, c.cosThetaO, 100000, 24);
        EXPECT_NEAR(e.mean, quadrature, 4.0 * e.sigma + 1e-3) << c.name;
    }
}

// The Lambertian material's albedo is its base colour exactly: every weight is baseColor.
TEST(Bsdf, DiffuseOnlyFurnaceGivesExactlyTheBaseColour) {
    const vec3 base(0.8f, 0.5f, 0.25f);
    gpu::ShadingMaterial m = gpu::makeShadingMaterial(base, 0.0f, 0.5f, 0.0f, vec3(1.0f), false);
    for (float cosThetaO : kFurnaceCosines) {
        for (uint32_t i = 0; i < 10000; ++i) {
            vec4 u = gpu::randomFloats(25, i, 0, 0, DIM_BSDF);
            gpu::BsdfSample s = gpu::sampleBsdf(m, viewAt(cosThetaO), vec2(u.x, u.y), u.w);
            ASSERT_TRUE(s.valid);
            ASSERT_EQ(s.weight, base);
        }
    }
}

// The Lambertian material keeps the arithmetic of the Lambertian path bit for bit.
TEST(Bsdf, DiffuseOnlyMaterialIsTheLambertianPathBitForBit) {
    const vec3 base(0.7f, 0.3f, 0.1f);
    gpu::ShadingMaterial m = gpu::makeShadingMaterial(base, 0.0f, 1.0f, 0.0f, vec3(1.0f), false);
    for (uint32_t i = 0; i < 10000; ++i) {
        vec4 u = gpu::randomFloats(26, i, 0, 0, DIM_BSDF);
        vec3 wo = viewAt(u.z);
        gpu::BsdfSample s = gpu::sampleBsdf(m, wo, vec2(u.x, u.y), u.w);
        vec3 lambert = gpu::sampleCosineHemisphere(vec2(u.x, u.y));
        ASSERT_EQ(s.direction, lambert);
        ASSERT_EQ(s.pdf, gpu::cosineHemispherePdf(lambert.z));
        ASSERT_EQ(s.weight, base);
        ASSERT_EQ(gpu::bsdfPdf(m, wo, lambert), gpu::cosineHemispherePdf(lambert.z));
        ASSERT_EQ(gpu::evaluateBsdf(m, wo, lambert), base * VKPT_INV_PI);
    }
    EXPECT_EQ(gpu::evaluateBsdf(m, viewAt(0.5f), vec3(0.0f, 0.6f, -0.8f)), vec3(0.0f));
}

// (d) V·H = L·H and the diffuse base's albedo scaling (1 − E(μo))(1 − E(μi)) / (1 − E_avg) is
// symmetric, so the base BRDF is reciprocal; only the rounding of the two dot products differs.
// (Clearcoat and sheen scale what lies below by 1 − E(μo) alone, which is not reciprocal by
// design: bsdf.h says why.)
TEST(Bsdf, BrdfIsReciprocal) {
    const gpu::ShadingMaterial materials[] = {
        gpu::makeShadingMaterial(vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.3f, 1.0f, vec3(1.0f), true),
        gpu::makeShadingMaterial(vec3(0.5f, 0.7f, 0.2f), 0.0f, 0.2f, 1.0f, vec3(1.0f, 0.5f, 2.0f),
                                 true),
        gpu::makeShadingMaterial(vec3(0.6f), 0.4f, 0.8f, 0.7f, vec3(1.0f), true),
        gpu::makeShadingMaterial(vec3(0.6f), 0.4f, 0.0f, 0.7f, vec3(1.0f), true),
    };
    for (const gpu::ShadingMaterial& m : materials)
        for (uint32_t i = 0; i < 20000; ++i) {
            vec4 u = gpu::randomFloats(27, i, 0, 0, DIM_BSDF);
            vec3 wo = gpu::sampleUniformHemisphere(vec2(u.x, u.y));
            vec3 wi = gpu::sampleUniformHemisphere(vec2(u.z, u.w));
            vec3 forward = gpu::evaluateBsdf(m, wo, wi);
            vec3 backward = gpu::evaluateBsdf(m, wi, wo);
            for (int ch = 0; ch < 3; ++ch)
                ASSERT_NEAR(forward[ch], backward[ch], 1e-5f * forward[ch] + 1e-30f);
        }
}

// Grazing views (down to cos θo = 1e-30 and 0), the α floor (roughness 0) and directions on the
// horizon give finite values; invalid samples carry zero weight.
TEST(Bsdf, FiniteAtGrazingAnglesAndTheAlphaFloor) {
    const float roughnesses[] = {0.0f, 1e-3f, 0.05f, 1.0f};
    const float cosines[] = {1.0f, 0.5f, 1e-3f, 1e-7f, 1e-30f, 0.0f, -0.2f};
    for (float roughness : roughnesses)
        for (float metallic : {0.0f, 0.5f, 1.0f})
            for (float cosThetaO : cosines) {
                gpu::ShadingMaterial m = gpu::makeShadingMaterial(vec3(0.8f), metallic, roughness,
                                                                  1.0f, vec3(1.0f), true);
                vec3 wo = viewAt(std::abs(cosThetaO));
                wo.z = cosThetaO;
                for (uint32_t i = 0; i < 2000; ++i) {
                    vec4 u = gpu::randomFloats(28, i, 0, 0, DIM_BSDF);
                    gpu::BsdfSample s = gpu::sampleBsdf(m, wo, vec2(u.x, u.y), u.w);
                    ASSERT_TRUE(std::isfinite(s.pdf) && std::isfinite(s.weight.x) &&
                                std::isfinite(s.weight.y) && std::isfinite(s.weight.z))
                        << roughness << " " << metallic << " " << cosThetaO;
                    if (!s.valid) {
                        ASSERT_EQ(s.weight, vec3(0.0f));
                    }
                    vec3 wi = gpu::sampleUniformHemisphere(vec2(u.x, u.y));
                    if (i % 7 == 0) wi = vec3(1.0f, 0.0f, 1e-30f); // on the horizon
                    vec3 f = gpu::evaluateBsdf(m, wo, wi);
                    float pdf = gpu::bsdfPdf(m, wo, wi);
                    ASSERT_TRUE(std::isfinite(f.x) && std::isfinite(f.y) && std::isfinite(f.z) &&
                                std::isfinite(pdf) && f.x >= 0.0f && pdf >= 0.0f)
                        << roughness << " " << metallic << " " << cosThetaO;
                }
            }
}

// The shading frame: worldToBasis undoes basisToWorld (sampling.h).
TEST(Bsdf, WorldToBasisUndoesBasisToWorld) {
    for (uint32_t i = 0; i < 1000; ++i) {
        vec4 u = gpu::randomFloats(29, i, 0, 0, DIM_BSDF);
        gpu::Basis frame = gpu::makeBasis(gpu::sampleUniformSphere(vec2(u.x, u.y)));
        vec3 local = gpu::sampleUniformSphere(vec2(u.z, u.w));
        vec3 back = gpu::worldToBasis(frame, gpu::basisToWorld(frame, local));
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(back[c], local[c], 1e-6f);
    }
}

TEST(Bsdf, AlphaIsRoughnessSquaredWithAFloor) {
    EXPECT_EQ(gpu::makeShadingMaterial(vec3(1.0f), 0.0f, 0.5f, 1.0f, vec3(1.0f), true).alpha,
              0.25f);
    EXPECT_EQ(gpu::makeShadingMaterial(vec3(1.0f), 0.0f, 0.0f, 1.0f, vec3(1.0f), true).alpha,
              VKPT_MIN_GGX_ALPHA);
    EXPECT_EQ(gpu::makeShadingMaterial(vec3(1.0f), 0.0f, 2.0f, 1.0f, vec3(1.0f), true).alpha, 1.0f);
}

// Both lobes are sampled when both contribute; a lobe that cannot contribute never is.
TEST(Bsdf, LobeProbabilityStaysInsideWhenBothLobesContribute) {
    for (float cosThetaO : {1.0f, 0.5f, 0.01f}) {
        const vec3 wo(std::sqrt(1.0f - cosThetaO * cosThetaO), 0.0f, cosThetaO);
        float dielectric =
            gpu::lobeProbabilities(
                gpu::makeShadingMaterial(vec3(1.0f), 0.0f, 0.5f, 1.0f, vec3(1.0f), true), wo)
                .specular;
        EXPECT_GE(dielectric, VKPT_MIN_LOBE_PROBABILITY);
        EXPECT_LE(dielectric, 1.0f - VKPT_MIN_LOBE_PROBABILITY);
        float halfMetal =
            gpu::lobeProbabilities(
                gpu::makeShadingMaterial(vec3(0.3f), 0.5f, 0.5f, 1.0f, vec3(1.0f), true), wo)
                .specular;
        EXPECT_GT(halfMetal, 0.0f);
        EXPECT_LT(halfMetal, 1.0f);
        EXPECT_EQ(gpu::lobeProbabilities(
                      gpu::makeShadingMaterial(vec3(0.0f), 1.0f, 0.5f, 1.0f, vec3(1.0f), true), wo)
                      .specular,
                  1.0f); // a black metal still reflects at grazing half-angles
        EXPECT_EQ(gpu::lobeProbabilities(
                      gpu::makeShadingMaterial(vec3(0.5f), 0.0f, 0.5f, 0.0f, vec3(1.0f), true), wo)
                      .specular,
                  0.0f); // specular 0: only the diffuse lobe
    }
}

} // namespace
} // namespace vkpt::bsdf_test
