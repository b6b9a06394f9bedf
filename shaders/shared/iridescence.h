// iridescence.h — KHR_materials_iridescence: the reflectance of a thin dielectric film over the
// base, for bsdf.h's specular and metal Fresnel terms. Belcour and Barla 2017 ("A Practical
// Extension to Microfacet Theory for the Modeling of Varying Iridescence", ACM TOG 36(4)), in
// the form of the extension's reference: the Airy sum of the film's two interfaces (Schlick's
// Fresnel at each, the phase shift of the optical path difference), its first two spectral
// harmonics integrated against the CIE 1931 matching functions in closed form through their
// Gaussian fit (the paper's eq. 15 and its table of constants), then XYZ to linear Rec. 709.
#ifndef VKPT_IRIDESCENCE_H
#define VKPT_IRIDESCENCE_H

#include "host_device.h"
#include "sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Per component (C++'s cos and sqrt here are the scalar std:: ones).
VKPT_FN vec3 cosEach(vec3 v) {
    return vec3(cos(v.x), cos(v.y), cos(v.z));
}

VKPT_FN vec3 sqrtEach(vec3 v) {
    return vec3(sqrt(v.x), sqrt(v.y), sqrt(v.z));
}

// ((a − b)/(a + b))², the normal-incidence reflectance between indices a and b.
VKPT_FN float reflectanceBetween(float a, float b) {
    float r = (a - b) / (a + b);
    return r * r;
}

VKPT_FN vec3 reflectanceBetween3(vec3 a, float b) {
    vec3 r = (a - vec3(b)) / (a + vec3(b));
    return r * r;
}

// The index whose reflectance against air is f0: (1 + √f0)/(1 − √f0).
VKPT_FN vec3 iorOfReflectance(vec3 f0) {
    vec3 s = sqrtEach(clamp(f0, vec3(0.0f), vec3(0.9999f)));
    return (vec3(1.0f) + s) / (vec3(1.0f) - s);
}

VKPT_FN float schlick1(float f0, float cosTheta) {
    float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (1.0f - f0) * (m2 * m2 * m);
}

VKPT_FN vec3 schlick3(vec3 f0, float cosTheta) {
    float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (vec3(1.0f) - f0) * (m2 * m2 * m);
}

// The spectral sensitivity of the XYZ matching functions to a path difference opd (nm) with
// phase shift `shift`, as linear Rec. 709 RGB: each function a Gaussian (value, position,
// variance; X with a second lobe), whose Fourier transform is taken at the phase 2π·opd.
VKPT_FN vec3 iridescenceSensitivity(float opd, vec3 shift) {
    float phase = 2.0f * VKPT_PI * opd * 1e-9f;
    vec3 value = vec3(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
    vec3 position = vec3(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
    vec3 variance = vec3(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    vec3 xyz = value * sqrtEach(2.0f * VKPT_PI * variance) * cosEach(position * phase + shift) *
               exp(-(phase * phase) * variance);
    xyz.x += 9.7470e-14f * sqrt(2.0f * VKPT_PI * 4.5282e+09f) * cos(2.2399e+06f * phase + shift.x) *
             exp(-4.5282e+09f * phase * phase);
    xyz /= 1.0685e-7f;
    // CIE XYZ to linear Rec. 709 (sRGB primaries, D65).
    return vec3(3.2404542f * xyz.x - 1.5371385f * xyz.y - 0.4985314f * xyz.z,
                -0.9692660f * xyz.x + 1.8760108f * xyz.y + 0.0415560f * xyz.z,
                0.0556434f * xyz.x - 0.2040259f * xyz.y + 1.0572252f * xyz.z);
}

// The film's reflectance at cos θ (to the microfacet normal) from outside (index 1): a film of
// index filmIor and thickness `thickness` nm over a base of normal-incidence reflectance baseF0.
// A film of zero thickness is no film (its index then blends to the outside's). Total internal
// reflection inside the film reflects everything.
VKPT_FN vec3 iridescenceFresnel(float filmIor, float thickness, float cosTheta, vec3 baseF0) {
    float outside = 1.0f;
    float film = mix(outside, filmIor, smoothstep(0.0f, 0.03f, thickness));
    float sinFilmSquared = (outside / film) * (outside / film) * (1.0f - cosTheta * cosTheta);
    float cosFilmSquared = 1.0f - sinFilmSquared;
    if (cosFilmSquared < 0.0f) return vec3(1.0f);
    float cosFilm = sqrt(cosFilmSquared);
    // The outer interface: reflectance, transmittance, and the phase of the reflection inside.
    float r12 = schlick1(reflectanceBetween(film, outside), cosTheta);
    float t121 = 1.0f - r12;
    float phase21 = film < outside ? 0.0f : VKPT_PI;
    // The inner interface, against the base's index (from its F0).
    vec3 baseIor = iorOfReflectance(baseF0);
    vec3 r23 = schlick3(reflectanceBetween3(baseIor, film), cosFilm);
    vec3 phase23 = vec3(baseIor.x < film ? VKPT_PI : 0.0f, baseIor.y < film ? VKPT_PI : 0.0f,
                        baseIor.z < film ? VKPT_PI : 0.0f);
    float pathDifference = 2.0f * film * thickness * cosFilm;
    vec3 phase = vec3(phase21) + phase23;
    // The Airy sum: the direct term, then the first two harmonics of the multiple reflections.
    vec3 r123 = clamp(r12 * r23, vec3(1e-5f), vec3(0.9999f));
    vec3 amplitude = sqrtEach(r123);
    vec3 multiple = (t121 * t121) * r23 / (vec3(1.0f) - r123);
    vec3 reflectance = vec3(r12) + multiple;
    vec3 harmonic = multiple - vec3(t121);
    for (int m = 1; m <= 2; ++m) {
        harmonic *= amplitude;
        reflectance +=
            harmonic * (2.0f * iridescenceSensitivity(float(m) * pathDifference, float(m) * phase));
    }
    return clamp(reflectance, vec3(0.0f), vec3(1.0f));
}

// The film term the BSDF uses is the one above at VKPT_FILM_NODES values of cos θ, linear in
// cos θ between them: its albedo is then exactly a sum over the nodes of the film's value times
// a table (albedo_tables.h, ggxFilmNodeAlbedoTable), so that the layering under the film takes
// what the film's highlight really reflects. Node k lies at cos θ = (k/(N − 1))², denser towards
// grazing angles, where the outer interface's reflectance rises fastest. With 16 nodes the
// interpolant stays within 0.04 of the formula for films up to 400 nm (the extension's default
// maximum) and 0.065 up to 1200 nm, for film indices 1.2 to 2.2 over bases of F0 0.04 to 0.9
// (tests/unit/bsdf_test.cpp, InterpolatedFilmFollowsTheFormula).
#define VKPT_FILM_NODES 16

VKPT_FN float filmNodeCosine(int k) {
    float x = float(k) / float(VKPT_FILM_NODES - 1);
    return x * x;
}

// The node at or below cos θ and the weight of the next one.
struct FilmInterval {
    int node;
    float t;
};

VKPT_FN FilmInterval filmIntervalOf(float cosTheta) {
    float c = clamp(cosTheta, 0.0f, 1.0f);
    FilmInterval at;
    at.node = min(int(sqrt(c) * float(VKPT_FILM_NODES - 1)), VKPT_FILM_NODES - 2);
    float below = filmNodeCosine(at.node);
    at.t = clamp((c - below) / (filmNodeCosine(at.node + 1) - below), 0.0f, 1.0f);
    return at;
}

// The film term between the nodes around cos θ.
VKPT_FN vec3 interpolatedIridescenceFresnel(float filmIor, float thickness, float cosTheta,
                                            vec3 baseF0) {
    FilmInterval at = filmIntervalOf(cosTheta);
    vec3 below = iridescenceFresnel(filmIor, thickness, filmNodeCosine(at.node), baseF0);
    vec3 above = iridescenceFresnel(filmIor, thickness, filmNodeCosine(at.node + 1), baseF0);
    return mix(below, above, at.t);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_IRIDESCENCE_H
