// dispersion.h — KHR_materials_dispersion for both executors: the index of refraction at a
// wavelength from the Abbe number, and the wavelength a path carries once it meets dispersive
// glass, with the weight that turns its contribution back into RGB without bias.
//
// The extension gives dispersion = 20/V_d (V_d the Abbe number) and fits a Cauchy law
// n(λ) = A + B/λ² through n_d at the Fraunhofer d line with (n_F − n_C) = (n_d − 1)/V_d between
// the F and C lines (λ_F = 486.1, λ_D = 587.6, λ_C = 656.3 nm):
//   n(λ) = n_d + (n_d − 1)/V_d · (1/λ² − 1/λ_D²) / (1/λ_F² − 1/λ_C²)
// (the extension's 523655/λ² − 1.5168 rounds those constants: 523453.7 and 1.51605).
//
// A path takes its wavelength λ, uniform on [380, 780] nm, from its camera sample's dimension
// (DIM_CAMERA's z at bounce 0: one hero wavelength per path, whichever vertex needs it), and its
// throughput is multiplied once by w(λ) = r(λ) / (N · pdf(λ)) per channel, where r is the sRGB
// response (the CIE 1931 matching functions in Wyman, Sloan and Shirley's fit, "Simple Analytic
// Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2), 2013, times the XYZ →
// linear Rec. 709 matrix, negative lobes clipped) and N = ∫ r dλ over the range. E[w] = 1 in
// every channel, so a path whose throughput does not depend on λ keeps its expectation exactly
// (white stays white: tests/unit/dispersion_test.cpp), and one through a prism sends each
// channel the light of the wavelengths its response covers.
#ifndef VKPT_DISPERSION_H
#define VKPT_DISPERSION_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

#define VKPT_WAVELENGTH_MIN 380.0f
#define VKPT_WAVELENGTH_MAX 780.0f
#define VKPT_FRAUNHOFER_F 486.1f
#define VKPT_FRAUNHOFER_D 587.6f
#define VKPT_FRAUNHOFER_C 656.3f

// The index of refraction at `wavelength` (nm) of glass with index iorD at the d line and
// KHR_materials_dispersion `dispersion`; never below 1 (the extension's clamp).
VKPT_FN float dispersiveIor(float iorD, float dispersion, float wavelength) {
    float inverseF = 1.0f / (VKPT_FRAUNHOFER_F * VKPT_FRAUNHOFER_F);
    float inverseD = 1.0f / (VKPT_FRAUNHOFER_D * VKPT_FRAUNHOFER_D);
    float inverseC = 1.0f / (VKPT_FRAUNHOFER_C * VKPT_FRAUNHOFER_C);
    float b = (iorD - 1.0f) * (dispersion / 20.0f) / (inverseF - inverseC);
    return max(iorD + b * (1.0f / (wavelength * wavelength) - inverseD), 1.0f);
}

// λ from a uniform u in [0, 1); its density is 1/(max − min).
VKPT_FN float sampleWavelength(float u) {
    return VKPT_WAVELENGTH_MIN + u * (VKPT_WAVELENGTH_MAX - VKPT_WAVELENGTH_MIN);
}

// One lobe of Wyman et al.'s fit: a Gaussian with one width below its peak, another above.
VKPT_FN float piecewiseGaussian(float x, float mean, float sigmaBelow, float sigmaAbove) {
    float t = (x - mean) / (x < mean ? sigmaBelow : sigmaAbove);
    return exp(-0.5f * t * t);
}

// The CIE 1931 2° matching functions x̄, ȳ, z̄ at λ nm (Wyman et al. 2013, the multi-lobe fit).
VKPT_FN vec3 cieMatching(float wavelength) {
    float l = wavelength;
    float x = 1.056f * piecewiseGaussian(l, 599.8f, 37.9f, 31.0f) +
              0.362f * piecewiseGaussian(l, 442.0f, 16.0f, 26.7f) -
              0.065f * piecewiseGaussian(l, 501.1f, 20.4f, 26.2f);
    float y = 0.821f * piecewiseGaussian(l, 568.8f, 46.9f, 40.5f) +
              0.286f * piecewiseGaussian(l, 530.9f, 16.3f, 31.1f);
    float z = 1.217f * piecewiseGaussian(l, 437.0f, 11.8f, 36.0f) +
              0.681f * piecewiseGaussian(l, 459.0f, 26.0f, 13.8f);
    return vec3(x, y, z);
}

// The linear Rec. 709 (sRGB) response at λ, negative lobes clipped: XYZ → RGB by the sRGB
// matrix (IEC 61966-2-1, D65).
VKPT_FN vec3 rgbResponse(float wavelength) {
    vec3 c = cieMatching(wavelength);
    float r = 3.2404542f * c.x - 1.5371385f * c.y - 0.4985314f * c.z;
    float g = -0.9692660f * c.x + 1.8760108f * c.y + 0.0415560f * c.z;
    float b = 0.0556434f * c.x - 0.2040259f * c.y + 1.0572252f * c.z;
    return max(vec3(r, g, b), vec3(0.0f));
}

// ∫ rgbResponse dλ over [380, 780] nm per channel (midpoint rule on 400 000 points; the unit test
// recomputes it).
#define VKPT_RGB_RESPONSE_INTEGRAL vec3(176.177322f, 115.385570f, 109.318455f)

// w(λ) = r(λ) / (N · pdf(λ)), the factor by which a path's RGB throughput is multiplied once it
// carries λ: E[w(λ)] = (1, 1, 1) over the uniform λ of sampleWavelength.
VKPT_FN vec3 wavelengthWeight(float wavelength) {
    return rgbResponse(wavelength) * (VKPT_WAVELENGTH_MAX - VKPT_WAVELENGTH_MIN) /
           VKPT_RGB_RESPONSE_INTEGRAL;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_DISPERSION_H
