// dispersion_test.cpp — KHR_materials_dispersion in shared/dispersion.h and its use by the path
// rules: the index at a wavelength follows the extension's formula, the wavelength's RGB weight
// has expectation 1 in every channel (a path whose throughput does not depend on λ stays white),
// and a path binds its wavelength once, only at dispersive glass.
#include <cmath>

#include <gtest/gtest.h>

#include "shared/bsdf.h"
#include "shared/dispersion.h"
#include "shared/path_rules.h"
#include "shared/rng.h"

namespace vkpt::dispersion_test {
namespace {

using glm::vec3;

// The extension's own form of the fit, λ in nm: n_d + (n_d − 1)/V · (523655/λ² − 1.5168).
double extensionIor(double iorD, double dispersion, double wavelength) {
    const double abbe = 20.0 / dispersion;
    return std::max(iorD + (iorD - 1.0) / abbe * (523655.0 / (wavelength * wavelength) - 1.5168),
                    1.0);
}

// n at the d line is the material's ior; n_F − n_C = (n_d − 1)/V_d (the Abbe number's
// definition); and everywhere the extension's rounded formula, to its rounding: its constants
// 523655 and 1.5168 stand for 1/(λ_F⁻² − λ_C⁻²) = 523453.7 and λ_D⁻²/(λ_F⁻² − λ_C⁻²) = 1.51605,
// 4e-4 and 5e-4 relative, so the two differ by at most 6e-4 of n − n_d, plus the rounded
// formula's own miss at λ_D, (n_d − 1)/V · 1.6e-4, plus float rounding.
TEST(Dispersion, IorFollowsTheAbbeNumber) {
    for (float iorD : {1.33f, 1.5f, 1.8f})
        for (float dispersion : {0.2f, 1.0f, 4.0f}) {
            EXPECT_NEAR(gpu::dispersiveIor(iorD, dispersion, VKPT_FRAUNHOFER_D), iorD, 1e-5f);
            const float spread = gpu::dispersiveIor(iorD, dispersion, VKPT_FRAUNHOFER_F) -
                                 gpu::dispersiveIor(iorD, dispersion, VKPT_FRAUNHOFER_C);
            EXPECT_NEAR(spread, (iorD - 1.0f) * dispersion / 20.0f, 2e-5f);
            for (float wavelength = 380.0f; wavelength <= 780.0f; wavelength += 20.0f)
                EXPECT_NEAR(gpu::dispersiveIor(iorD, dispersion, wavelength),
                            extensionIor(iorD, dispersion, wavelength),
                            6e-4 * std::abs(extensionIor(iorD, dispersion, wavelength) - iorD) +
                                2e-4 * (iorD - 1.0f) * dispersion / 20.0f + 1e-5)
                    << iorD << " " << dispersion << " " << wavelength;
        }
}

// Dispersion 0 is none; the index never falls below 1 (the extension's clamp).
TEST(Dispersion, ZeroIsNoneAndTheIndexStaysAtLeastOne) {
    for (float wavelength : {380.0f, 587.6f, 780.0f}) {
        EXPECT_EQ(gpu::dispersiveIor(1.5f, 0.0f, wavelength), 1.5f);
        EXPECT_GE(gpu::dispersiveIor(1.01f, 20.0f, wavelength), 1.0f);
    }
}

// The integral of the response the weight divides by is the one dispersion.h states: the
// midpoint rule on 40 000 points agrees to 1e-5 relative.
TEST(Dispersion, ResponseIntegralIsTheStatedConstant) {
    constexpr int kPoints = 40000;
    const double step = double(VKPT_WAVELENGTH_MAX - VKPT_WAVELENGTH_MIN) / kPoints;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < kPoints; ++i)
        sum += glm::dvec3(gpu::rgbResponse(float(VKPT_WAVELENGTH_MIN + (i + 0.5) * step))) * step;
    const vec3 stated = VKPT_RGB_RESPONSE_INTEGRAL;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sum[c], double(stated[c]), 1e-5 * double(stated[c])) << "channel " << c;
}

// White stays white: the mean of w(λ) over λ drawn as paths draw it (sampleWavelength of
// independent uniforms, 10^6 of them) is 1 in every channel within 4 standard errors; and no
// weight is negative.
TEST(Dispersion, WavelengthWeightOfAWhitePathSumsToWhite) {
    constexpr int kSamples = 1000000;
    glm::dvec3 sum(0.0), sumSquares(0.0);
    for (std::uint32_t i = 0; i < kSamples; ++i) {
        const float u = gpu::randomFloats(61, i, 0, 0, DIM_CAMERA).z;
        const vec3 w = gpu::wavelengthWeight(gpu::sampleWavelength(u));
        ASSERT_GE(glm::min(w.x, glm::min(w.y, w.z)), 0.0f);
        sum += glm::dvec3(w);
        sumSquares += glm::dvec3(w) * glm::dvec3(w);
    }
    for (int c = 0; c < 3; ++c) {
        const double mean = sum[c] / kSamples;
        const double sigma = std::sqrt((sumSquares[c] / kSamples - mean * mean) / kSamples);
        EXPECT_NEAR(mean, 1.0, 4.0 * sigma) << "channel " << c;
    }
}

// Each channel's weight peaks where its colour does: red at long wavelengths, green in the
// middle, blue at short ones.
TEST(Dispersion, ChannelsPeakInTheirOwnPartOfTheSpectrum) {
    const vec3 blue = gpu::wavelengthWeight(450.0f);
    const vec3 green = gpu::wavelengthWeight(540.0f);
    const vec3 red = gpu::wavelengthWeight(620.0f);
    EXPECT_GT(blue.z, blue.x);
    EXPECT_GT(blue.z, blue.y);
    EXPECT_GT(green.y, green.x);
    EXPECT_GT(green.y, green.z);
    EXPECT_GT(red.x, red.y);
    EXPECT_GT(red.x, red.z);
}

gpu::ShadingMaterial dispersiveGlass(float eta) {
    gpu::ShadingMaterial m =
        gpu::makeShadingMaterial(vec3(1.0f), 0.0f, 0.0f, 1.0f, vec3(1.0f), true);
    m.transmission = 1.0f;
    m.thinWalled = false;
    m.eta = eta;
    m.dispersion = 2.0f;
    return m;
}

// A path binds its wavelength at the first dispersive glass: the throughput takes w(λ) once,
// later glass keeps λ and the throughput; entering glass sees n(λ), leaving it 1/n(λ).
TEST(Dispersion, PathBindsItsWavelengthOnceAtDispersiveGlass) {
    vec3 throughput(0.5f);
    gpu::ShadingMaterial entering = dispersiveGlass(1.5f);
    float wavelength = gpu::bindWavelength(entering, throughput, VKPT_NO_WAVELENGTH, 0.25f);
    EXPECT_EQ(wavelength, gpu::sampleWavelength(0.25f));
    EXPECT_EQ(throughput, vec3(0.5f) * gpu::wavelengthWeight(wavelength));
    EXPECT_EQ(entering.eta, gpu::dispersiveIor(1.5f, 2.0f, wavelength));
    const vec3 bound = throughput;
    gpu::ShadingMaterial leaving = dispersiveGlass(1.0f / 1.5f);
    EXPECT_EQ(gpu::bindWavelength(leaving, throughput, wavelength, 0.9f), wavelength);
    EXPECT_EQ(throughput, bound);
    EXPECT_NEAR(leaving.eta, 1.0f / gpu::dispersiveIor(1.5f, 2.0f, wavelength), 1e-6f);
}

// Thin walls, opaque materials and glass without dispersion leave the path as it was.
TEST(Dispersion, OnlyDispersiveGlassThatBoundsAVolumeBindsAWavelength) {
    gpu::ShadingMaterial thin = dispersiveGlass(1.5f);
    thin.thinWalled = true;
    gpu::ShadingMaterial opaque = dispersiveGlass(1.5f);
    opaque.transmission = 0.0f;
    gpu::ShadingMaterial plain = dispersiveGlass(1.5f);
    plain.dispersion = 0.0f;
    for (gpu::ShadingMaterial m : {thin, opaque, plain}) {
        vec3 throughput(1.0f);
        const float eta = m.eta;
        EXPECT_EQ(gpu::bindWavelength(m, throughput, VKPT_NO_WAVELENGTH, 0.5f), VKPT_NO_WAVELENGTH);
        EXPECT_EQ(throughput, vec3(1.0f));
        EXPECT_EQ(m.eta, eta);
    }
}

} // namespace
} // namespace vkpt::dispersion_test
