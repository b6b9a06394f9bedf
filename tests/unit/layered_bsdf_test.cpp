// layered_bsdf_test.cpp — the layering of shared/bsdf.h: the albedo tables it reads
// (shared/albedo_tables.h) against quadrature by another method, and the white furnace of every
// lobe and of their mixtures (clearcoat and sheen over dielectric and metal bases), none of
// which may reflect more than it receives.
//
//   build/ci/tests/unit/layered_bsdf_test --gtest_filter='*Furnace*'
//
// prints the furnace table that docs/scene-model.md quotes.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/adaptive_simpson.h"
#include "../support/furnace.h"
#include "common/math_constants.h"
#include "shared/albedo_lookup.h"
#include "shared/bsdf.h"

namespace vkpt::layered_bsdf_test {
namespace {

using glm::vec3;

constexpr int kSize = VKPT_ALBEDO_TABLE_SIZE;

// Adaptive Simpson (tests/support/adaptive_simpson.h) over 16 first panels, to an absolute
// tolerance.
template <typename F> auto integrate(const F& f, double a, double b, double eps) {
    return test::adaptiveSimpson(f, a, b, {16, 0.0, eps, 14});
}

// ---------------------------------------------------------------------------------------------
// The tables against quadrature by another method. The generator (host/tables) integrates
// over visible normals with a midpoint rule; here ∫ f cos θi dωi is integrated over wi itself
// by nested adaptive Simpson, in spherical coordinates (θ', φ') about the mirror direction of
// wo with θ' = w tan t (w = 2α + 1e-3, the lobe's width), which spreads a narrow lobe over
// the whole t range; the sheen is integrated over (cos θi, φi). Two methods with different
// errors, so agreement checks the tables, not one method against itself.

// The plain albedo (x) and the Fresnel-weighted one (y), integrated together: one pass over the
// same points, refined until both meet the tolerance.
glm::dvec2 ggxAlbediosBySimpson(double cosThetaO, double alpha) {
    const vec3 wo = test::viewAt(float(cosThetaO));
    const gpu::Basis mirror = gpu::makeBasis(vec3(-wo.x, -wo.y, wo.z));
    const float a = float(alpha);
    const double width = 2.0 * alpha + 1e-3;
    auto overT = [&](double t) {
        const double theta = width * std::tan(t);
        const double jacobian = width / (std::cos(t) * std::cos(t)); // dθ'/dt
        auto overPhi = [&](double phi) {
            const vec3 local(float(std::sin(theta) * std::cos(phi)),
                             float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
            const vec3 wi = gpu::basisToWorld(mirror, local);
            if (!(wi.z > 0.0f)) return glm::dvec2(0.0);
            const vec3 h = glm::normalize(wo + wi);
            const double value = double(gpu::ggxReflection(wo, wi, h, a)) * double(wi.z);
            return glm::dvec2(value, value * double(gpu::halfVectorFresnelWeight(wo, wi, h)));
        };
        return std::sin(theta) * jacobian * integrate(overPhi, 0.0, 2.0 * kPi, 1e-6);
    };
    return integrate(overT, 0.0, std::atan(kPi / width), 1e-5);
}

double sheenAlbedoBySimpson(double cosThetaO, double alpha) {
    const vec3 wo = test::viewAt(float(cosThetaO));
    auto overCosine = [&](double cosThetaI) {
        const double sinThetaI = std::sqrt(std::max(0.0, 1.0 - cosThetaI * cosThetaI));
        auto overPhi = [&](double phi) {
            const vec3 wi(float(sinThetaI * std::cos(phi)), float(sinThetaI * std::sin(phi)),
                          float(cosThetaI));
            return double(gpu::sheenReflection(wo, wi, float(alpha))) * cosThetaI;
        };
        return 2.0 * integrate(overPhi, 0.0, kPi, 1e-6); // symmetric about wo's plane
    };
    return integrate(overCosine, 0.0, 1.0, 1e-5);
}

// Node (i, j): √cos θo = i/(N − 1); √α = j/(N − 1) for GGX (α at least VKPT_MIN_GGX_ALPHA),
// sheen roughness 0.1 + 0.9 j/(N − 1) for the sheen. Column 0 is evaluated at cos θo = 1e-4.
double nodeCosine(int i) {
    const double x = double(i) / (kSize - 1);
    return std::max(x * x, 1e-4);
}

// Four nodes along each axis, from the smallest α and grazing views to α = 1 and normal
// incidence (16 nodes, both tables integrated together at each, about a second a node). Over all
// 64 nodes i, j ∈ {0, 9, ..., 63} and 5 × 5 nodes {0, 13, 26, 45, 63}, the two quadratures
// differed by at most 0.0011 (α = 0.043 at normal incidence, where the lobe is narrowest
// for the Simpson rule); the bound is 2e-3. The generator's
// visible-normal quadrature converges fast (at α = 1, cos θo = 0.025: 0.90673, 0.90666, 0.90662 at
// 256², 512², 1024²); a table written for another model or another axis misses by 1e-2 or more
// across the range, and the two quadratures agree to 1e-3.
TEST(AlbedoTables, GgxEntriesMatchAdaptiveSimpson) {
    const int nodes[] = {0, 18, 36, kSize - 1};
    for (int j : nodes)
        for (int i : nodes) {
            const double alpha = gpu::ggxAlphaOf(float(j) / (kSize - 1));
            const double mu = nodeCosine(i);
            const std::size_t k = std::size_t(j * kSize + i);
            const glm::dvec2 albedos = ggxAlbediosBySimpson(mu, alpha);
            EXPECT_NEAR(gpu::ggxAlbedoTable[k], albedos.x, 2e-3)
                << "cos " << mu << " alpha " << alpha;
            EXPECT_NEAR(gpu::ggxFresnelAlbedoTable[k], albedos.y, 2e-3)
                << "cos " << mu << " alpha " << alpha;
        }
}

// The sheen entries against nested adaptive Simpson, to 2e-3 of max(1, E): the lobe reaches
// E = 4 at grazing views, where the generator's midpoint rule (256²) is 0.1 % high (4.0040,
// 4.0013, 4.0004 at 256², 1024², 2048² for cos θo = 1e-4, roughness 0.1; Simpson 3.9994).
TEST(AlbedoTables, SheenEntriesMatchAdaptiveSimpson) {
    for (int j = 0; j < kSize; j += 9)
        for (int i = 0; i < kSize; i += 9) {
            const double roughness = 0.1 + 0.9 * double(j) / (kSize - 1);
            const double alpha = gpu::sheenAlphaOf(float(roughness));
            const double mu = nodeCosine(i);
            const double expected = sheenAlbedoBySimpson(mu, alpha);
            EXPECT_NEAR(gpu::sheenAlbedoTable[std::size_t(j * kSize + i)], expected,
                        2e-3 * std::max(1.0, expected))
                << "cos " << mu << " roughness " << roughness;
        }
}

// The averages are 2 ∫ E(μ) μ dμ of what the lookup returns, so that the diffuse base's
// reciprocal scaling integrates to exactly 1 − E(μo) (bsdf.h).
TEST(AlbedoTables, AveragesAreTheCosineWeightedMeansOfTheLookup) {
    for (int j = 0; j < kSize; j += 3) {
        const float alpha = gpu::ggxAlphaOf(float(j) / (kSize - 1));
        // The lookup is linear in √μ between nodes: integrate over x = √μ, μ dμ = 2x³ dx.
        auto plain = [&](double x) {
            return double(gpu::ggxAlbedo(float(x * x), alpha)) * 2.0 * x * x * x;
        };
        auto fresnel = [&](double x) {
            return double(gpu::ggxFresnelAlbedo(float(x * x), alpha)) * 2.0 * x * x * x;
        };
        EXPECT_NEAR(gpu::ggxAverageAlbedo(alpha), 2.0 * integrate(plain, 0.0, 1.0, 1e-8), 1e-5)
            << "alpha " << alpha;
        EXPECT_NEAR(gpu::ggxFresnelAverageAlbedo(alpha), 2.0 * integrate(fresnel, 0.0, 1.0, 1e-8),
                    1e-5)
            << "alpha " << alpha;
    }
}

// The lookup returns the table's nodes at the nodes.
TEST(AlbedoTables, LookupReturnsTheNodes) {
    for (int j : {0, 17, kSize - 1})
        for (int i : {3, 40, kSize - 1}) {
            const float mu = float(i) / (kSize - 1);
            const float root = float(j) / (kSize - 1);
            const std::size_t k = std::size_t(j * kSize + i);
            const float alpha = std::max(root * root, VKPT_MIN_GGX_ALPHA);
            if (root * root >= VKPT_MIN_GGX_ALPHA) {
                EXPECT_NEAR(gpu::ggxAlbedo(mu * mu, alpha), gpu::ggxAlbedoTable[k], 1e-5f);
            }
            const float sheenRoughness = 0.1f + 0.9f * root;
            EXPECT_NEAR(gpu::sheenAlbedo(mu * mu, sheenRoughness * sheenRoughness),
                        gpu::sheenAlbedoTable[k], 1e-4f * std::max(1.0f, gpu::sheenAlbedoTable[k]));
        }
}

// ---------------------------------------------------------------------------------------------
// White furnace of every lobe and mixture. All colours white (base, specular, sheen), every
// roughness the row's; clearcoat 1. "Black base" is baseColor 0 with specular 0, so only the
// named layer reflects. The glass is thin-walled (ior 1.5), whose transmission carries no 1/η²,
// so that its furnace is the energy it keeps; a tilted coat's normal is turned by `coatTilt`
// radians about y (a clearcoatNormalTexture's bump).
struct FurnaceMaterial {
    const char* name;
    float metallic;
    float specular;
    float base;
    float clearcoat;
    float sheen;
    float transmission = 0.0f;
    float coatTilt = 0.0f;
};

const FurnaceMaterial kFurnaceMaterials[] = {
    {"diffuse (specular 0)", 0.0f, 0.0f, 1.0f, 0.0f, 0.0f},
    {"specular layer, black base", 0.0f, 1.0f, 0.0f, 0.0f, 0.0f},
    {"dielectric", 0.0f, 1.0f, 1.0f, 0.0f, 0.0f},
    {"metal", 1.0f, 1.0f, 1.0f, 0.0f, 0.0f},
    {"clearcoat, black base", 0.0f, 0.0f, 0.0f, 1.0f, 0.0f},
    {"sheen, black base", 0.0f, 0.0f, 0.0f, 0.0f, 1.0f},
    {"clearcoat over dielectric", 0.0f, 1.0f, 1.0f, 1.0f, 0.0f},
    {"sheen over dielectric", 0.0f, 1.0f, 1.0f, 0.0f, 1.0f},
    {"clearcoat + sheen over dielectric", 0.0f, 1.0f, 1.0f, 1.0f, 1.0f},
    {"clearcoat over metal", 1.0f, 1.0f, 1.0f, 1.0f, 0.0f},
    {"clearcoat + sheen over metal", 1.0f, 1.0f, 1.0f, 1.0f, 1.0f},
    {"thin glass", 0.0f, 1.0f, 1.0f, 0.0f, 0.0f, 1.0f},
    {"half glass, half dielectric", 0.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.5f},
    {"clearcoat + sheen over thin glass", 0.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f},
    {"clearcoat tilted 30° over dielectric", 0.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.5236f},
    {"clearcoat tilted 30°, black base", 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.5236f},
};

gpu::ShadingMaterial furnaceMaterial(const FurnaceMaterial& f, float roughness) {
    gpu::ShadingMaterial m =
        gpu::makeShadingMaterial(vec3(f.base), f.metallic, roughness, f.specular, vec3(1.0f), true);
    if (f.clearcoat > 0.0f) m = gpu::withClearcoat(m, f.clearcoat, roughness);
    if (f.sheen > 0.0f) m = gpu::withSheen(m, vec3(f.sheen), roughness);
    m.transmission = f.transmission;
    m.iorF0 = 0.04f;
    m.eta = 1.5f;
    m.thinWalled = true;
    m.clearcoatNormal = vec3(std::sin(f.coatTilt), 0.0f, std::cos(f.coatTilt));
    return m;
}

// Each albedo from 2·10^5 samples must be at most 1 + 3σ (a 0.13 % one-sided false alarm per
// entry if the truth were exactly 1) plus 0.0012, the tables' bilinear interpolation error for
// cos θo ≥ 0.05 (vkpt-albedo-tables --interpolation-error): the layers leave the base
// 1 − E_table while reflecting E_true, so a gain of that size is the lookup's, not the model's.
TEST(LayeredFurnace, NoLobeOrMixtureReflectsMoreThanItReceives) {
    const float roughnesses[] = {0.1f, 0.5f, 1.0f};
    const float cosines[] = {1.0f, 0.5f, 0.2f, 0.05f};
    constexpr double kTableError = 0.0012;
    std::printf("%-36s %9s %16s %16s %16s %16s\n", "material (white)", "roughness", "cos θo = 1",
                "0.5", "0.2", "0.05");
    int stream = 0;
    for (const FurnaceMaterial& f : kFurnaceMaterials)
        for (float roughness : roughnesses) {
            std::string row;
            char cell[64];
            for (float cosThetaO : cosines) {
                const test::AlbedoEstimate e = test::estimateAlbedo(
                    furnaceMaterial(f, roughness), cosThetaO, 200000, 300u + uint32_t(stream++));
                std::snprintf(cell, sizeof(cell), " %9.4f ± %.4f", e.mean, e.sigma);
                row += cell;
                EXPECT_LE(e.mean, 1.0 + 3.0 * e.sigma + kTableError)
                    << f.name << " roughness " << roughness << " cos " << cosThetaO;
            }
            std::printf("%-36s %9.2f%s\n", f.name, roughness, row.c_str());
        }
}

// Energy preservation, not only conservation: each layer leaves what lies below exactly what it
// does not reflect itself (its E includes its own single-scattering loss), so over a white
// Lambertian base nothing is lost: a white dielectric, and a clearcoat over it, reflect 1
// within 3σ plus the tables' interpolation error.
TEST(LayeredFurnace, WhiteDielectricWithClearcoatKeepsItsEnergy) {
    for (float cosThetaO : {1.0f, 0.5f, 0.2f}) {
        const gpu::ShadingMaterial dielectric = furnaceMaterial(kFurnaceMaterials[2], 0.5f);
        const test::AlbedoEstimate plain = test::estimateAlbedo(dielectric, cosThetaO, 100000, 400);
        EXPECT_NEAR(plain.mean, 1.0, 3.0 * plain.sigma + 0.0012) << cosThetaO;
        const gpu::ShadingMaterial coated = furnaceMaterial(kFurnaceMaterials[6], 0.5f);
        const test::AlbedoEstimate c = test::estimateAlbedo(coated, cosThetaO, 100000, 401);
        EXPECT_NEAR(c.mean, 1.0, 3.0 * c.sigma + 0.0024) << cosThetaO; // two layers' lookups
    }
}

} // namespace
} // namespace vkpt::layered_bsdf_test
