// denoise.h — the statistics-gated denoiser, one definition for vkpt's kernels
// (demodulate_radiance, filter_radiance) and vkpt-ref's loop (host/denoise): per-pixel input,
// albedo demodulation, one à-trous step of a cross-bilateral filter guided by the AOVs and gated
// by a t-test on the pixels' means, and the albedo multiplied back (docs/denoise.md).
//
// The filter is the edge-avoiding à-trous wavelet transform (Dammertz et al., "Edge-Avoiding
// À-Trous Wavelet Transform for fast Global Illumination Filtering", HPG 2010): a 5×5 B3-spline
// kernel whose taps lie `step` pixels apart, step = 1, 2, 4, ..., each tap weighted by how much
// its guides (normal, depth, albedo) resemble the centre's, with the variance carried through
// the iterations as in SVGF (Schied et al., HPG 2017, §4.2: Var(Σ wᵢxᵢ / Σ wᵢ) = Σ wᵢ²Var(xᵢ) /
// (Σ wᵢ)²). What makes it consistent is the gate after Sakai et al., "StatMC: Statistical Monte
// Carlo Denoising" (2024): a tap whose mean differs from the centre's by more than the noise of
// the two means can explain (Welch's t = |Δ| / √(Var p + Var q)) takes no part. As the samples
// grow the variances of the means go to 0, t grows without bound for every neighbour whose
// expectation differs, and the output converges to the pixel's own mean — never to a blur.
#ifndef VKPT_DENOISE_H
#define VKPT_DENOISE_H

#include "host_device.h"
#include "sampling.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// One pixel as the denoiser reads it: the estimate and its noise, the means of its two disjoint
// half sample sets (docs/integrator.md, "Two halves"), and the AOVs that guide the filter.
struct DenoisePixel {
    vec3 radiance;           // mean radiance
    float luminanceVariance; // variance of the mean luminance, M2 / (n − 1) / n
    vec3 albedo;             // mean albedo, 0 where every sample missed
    float depth;             // camera-space z of the nearest hit; +inf where none
    vec3 normal;             // mean shading normal; 0 where every sample missed
    uint sampleCount;        // samples behind the mean
    vec3 halfA;              // mean radiance of the even samples
    float halfCountA;        // their count; 0: no half estimate (the pixel stays raw)
    vec3 halfB;              // mean radiance of the odd samples
    float halfCountB;
};

// One pixel of an iterate: the filtered whole estimate and the two filtered halves, each the
// demodulated radiance (rgb) and the variance of its mean luminance (w); and the blend of the
// candidates so far (rgb, demodulated) with the sum of their weights (w; 0 before the first);
// and this pixel's share of the iterate's error estimate (estimate.x, candidateError; estimate.y
// 1 where the pixel has two halves, else 0), which the next pass averages over a window.
struct DenoiseValue {
    vec4 full;
    vec4 halfA;
    vec4 halfB;
    vec4 chosen;
    vec4 estimate;
};

// The filter's settings (push constants of both kernels).
struct DenoiseParams {
    uint width;
    uint height;
    uint step;     // the à-trous step of this iteration: 1, 2, 4, ...; 0: the last pass
    uint modulate; // 1 on the last pass: choose only, and write radiance (albedo multiplied back)
    // A tap whose t statistic reaches gateT takes no part; below it its weight falls smoothly
    // as (1 − (t/gateT)⁴)², so that the output does not jump where a tap crosses the bound.
    float gateT;
    float normalPower; // normal weight max(0, cos θ)^normalPower
    float depthSigma;  // depth weight exp(−|Δz| / (depthSigma · z · pixel distance))
    float albedoSigma; // albedo weight exp(−|Δa|² / albedoSigma²)
};

// The defaults, measured in docs/trade/denoise.md.
// Three steps (reach 14 pixels) with the 5×5 variance prior below against four with a 3×3 prior
// (docs/trade/denoise.md): less error in the Cornell box and the many-light scene, more at 16 spp
// in the 64² glTF samples (TransmissionTest's glass +17 %), for a quarter less filtering.
#define DENOISE_ITERATIONS 3u
#define DENOISE_GATE_T 3.0f
#define DENOISE_NORMAL_POWER 32.0f
#define DENOISE_DEPTH_SIGMA 0.02f
#define DENOISE_ALBEDO_SIGMA 0.25f
// What the neighbourhood's variance weighs, in samples, against a pixel's own (denoise_filter.h);
// 16 and 256 were measured, 64 kept (docs/trade/denoise.md).
#define DENOISE_PRIOR_SAMPLES 64.0f
// The reach of that neighbourhood: 5×5 (radius 2) gave 10 % less error than 3×3 at Cornell 16 spp,
// where a heavy tail leaves many pixels' own variance several times too low
// (docs/trade/denoise.md).
#define DENOISE_PRIOR_RADIUS 2
// The reach of the window over which a candidate's error estimate is averaged (denoise_filter.h).
#define DENOISE_ERROR_RADIUS 2
// The raw candidate's estimate counts 1 + DENOISE_RAW_PRIOR / n times (denoise_filter.h): its
// estimate, (A − B)² / 4 from two half means, is the noisiest of all, and a pixel that a low draw
// leaves raw keeps all its noise. The factor goes to 1 as the samples grow, so the choice stays
// consistent; 16, 64 and 256 were measured (docs/trade/denoise.md), 64 kept.
#define DENOISE_RAW_PRIOR 64.0f

// Dividing by a dark albedo channel would lift its noise beyond what the filter can take; a
// pixel without a surface (albedo 0: sky, emitters seen directly) is filtered as it is.
#define DENOISE_ALBEDO_FLOOR 0.02f
#define DENOISE_NO_ALBEDO 1e-3f
// A candidate's error where nothing estimates it (no halves): never taken, the raw stays.
#define DENOISE_NO_ESTIMATE 3.0e38f
// The candidates are blended with weights 1 / error² (denoise_filter.h); an estimate below
// DENOISE_ERROR_FLOOR / n (it may come out 0 or negative, a difference of noisy squares) counts
// as that floor, so that no single candidate's chance estimate takes all the weight. Relative
// squared error, as candidateError; a raw estimate's error is about 0.2 / n in the Cornell box,
// so the floor stays a small fraction of it at every n and the raw candidate's weight still
// grows as n² (consistency). 1e-4, 1e-3 and 1e-2 measured alike.
#define DENOISE_ERROR_FLOOR 1e-3f

VKPT_FN vec3 demodulationAlbedo(vec3 albedo) {
    if (max(albedo.x, max(albedo.y, albedo.z)) < DENOISE_NO_ALBEDO) return vec3(1.0f);
    return max(albedo, vec3(DENOISE_ALBEDO_FLOOR));
}

VKPT_FN bool hasHalves(DenoisePixel pixel) {
    return pixel.halfCountA > 0.0f && pixel.halfCountB > 0.0f;
}

// The albedo-demodulated radiance (rgb) and the variance of its mean luminance (w): the
// luminance's variance scaled by the square of the factor demodulation scaled the luminance by.
VKPT_FN vec4 demodulatedEstimate(vec3 radiance, float variance, vec3 albedo) {
    vec3 demodulated = radiance / albedo;
    float before = luminance(radiance);
    float scale = before > 0.0f ? luminance(demodulated) / before : 1.0f / luminance(albedo);
    return vec4(demodulated, variance * scale * scale);
}

// The blend of the candidates with the albedo multiplied back.
VKPT_FN vec3 modulatedRadiance(DenoisePixel pixel, DenoiseValue value) {
    return vec3(value.chosen.x, value.chosen.y, value.chosen.z) * demodulationAlbedo(pixel.albedo);
}

// One pixel's share of a candidate's error estimate, from its filtered halves FA, FB and raw
// halves A, B (demodulated; `albedo` modulates them back). FA depends on half A's samples only, so
// E[(FA − B)²] = MSE(FA) + Var B; Var B ≈ (A − B)² / 2; and the filtered whole, of twice the
// samples, has about half FA's variance, Var FA ≈ (FA − FB)² / 2 (Rousselle, Knaus and Zwicker,
// "Adaptive Rendering with Non-Local Means Filtering", SIGGRAPH Asia 2012, §4–5, estimate a
// filter's error from half buffers this way). Symmetrised over the halves:
//   MSE(F whole) ≈ ((FA − B)² + (FB − A)²) / 2 − (A − B)² / 2 − (FA − FB)² / 4,
// which for the raw candidate (FA = A, FB = B) is (A − B)² / 4, the variance of the whole mean.
// Relative to the pixel's squared luminance (+ 0.01), as relMSE weighs errors.
VKPT_FN float candidateError(vec3 filteredA, vec3 filteredB, vec3 rawA, vec3 rawB, vec3 albedo) {
    vec3 crossA = (filteredA - rawB) * albedo;
    vec3 crossB = (filteredB - rawA) * albedo;
    vec3 halves = (rawA - rawB) * albedo;
    vec3 filtered = (filteredA - filteredB) * albedo;
    float error = 0.5f * (dot(crossA, crossA) + dot(crossB, crossB)) - 0.5f * dot(halves, halves) -
                  0.25f * dot(filtered, filtered);
    float scale = luminance(0.5f * (rawA + rawB) * albedo);
    return error / (scale * scale + 0.01f);
}

// The gate: 1 for equal means, falling to 0 at t = gateT. The quartic keeps the weight of a
// neighbour of the same mean near 1 over the usual range of its t (0.98 at t = 1, 0.64 at 2 for
// gateT = 3), so that a pixel whose own noise put it 2σ out still takes in its neighbours; the
// cut-off is then sharp. With no noise at all (every variance 0) only an equal mean passes: the
// filter leaves the image as it is.
//
// The render keeps the variance of the luminance only; a neighbour of the same luminance and
// another colour would pass a test of the luminance alone, and its bias would never shrink. Each
// channel is tested too, its noise taken as the luminance's relative noise (σ_c / μ_c =
// σ_L / μ_L, as for noise that scales the whole colour), μ_c the larger of the two values.
VKPT_FN float gateWeight(vec3 centre, vec3 neighbour, float variance, float gateT) {
    float centreLuminance = luminance(centre);
    float neighbourLuminance = luminance(neighbour);
    float difference = centreLuminance - neighbourLuminance;
    float squared = difference * difference; // t² · variance, the largest over the tests
    float scale = max(centreLuminance, neighbourLuminance);
    for (int c = 0; c < 3; ++c) {
        float largest = max(centre[c], neighbour[c]);
        if (!(largest > 0.0f)) continue;
        float channel = (centre[c] - neighbour[c]) * scale / largest;
        squared = max(squared, channel * channel);
    }
    if (!(variance > 0.0f)) return squared == 0.0f ? 1.0f : 0.0f;
    float ratio = squared / (variance * gateT * gateT);
    float falloff = max(1.0f - ratio * ratio, 0.0f);
    return falloff * falloff;
}

// The iterate `value`'s candidateError at `pixel` (DenoiseValue.estimate).
VKPT_FN vec4 pixelEstimate(DenoisePixel pixel, DenoiseValue value) {
    if (!hasHalves(pixel)) return vec4(0.0f);
    vec3 albedo = demodulationAlbedo(pixel.albedo);
    float error = candidateError(vec3(value.halfA.x, value.halfA.y, value.halfA.z),
                                 vec3(value.halfB.x, value.halfB.y, value.halfB.z),
                                 pixel.halfA / albedo, pixel.halfB / albedo, albedo);
    return vec4(error, 1.0f, 0.0f, 0.0f);
}

// The first iterate: the whole estimate and the halves demodulated, nothing chosen yet. A half's
// mean has the variance of the whole's times n / n_half (one variance per sample, fewer samples):
// the render keeps one variance for the pixel, so this is the one statistic the two halves'
// filters share (their means, and so their gates' differences, are their own).
VKPT_FN DenoiseValue demodulatedPixel(DenoisePixel pixel) {
    vec3 albedo = demodulationAlbedo(pixel.albedo);
    DenoiseValue value;
    value.full = demodulatedEstimate(pixel.radiance, pixel.luminanceVariance, albedo);
    float samples = float(pixel.sampleCount);
    float varianceA =
        hasHalves(pixel) ? pixel.luminanceVariance * samples / pixel.halfCountA : 0.0f;
    float varianceB =
        hasHalves(pixel) ? pixel.luminanceVariance * samples / pixel.halfCountB : 0.0f;
    value.halfA = demodulatedEstimate(pixel.halfA, varianceA, albedo);
    value.halfB = demodulatedEstimate(pixel.halfB, varianceB, albedo);
    value.chosen = vec4(value.full.x, value.full.y, value.full.z, 0.0f);
    value.estimate = pixelEstimate(pixel, value);
    return value;
}

VKPT_FN bool hasSurface(DenoisePixel pixel) {
    return !isinf(pixel.depth);
}

// How much q's surface resembles p's: normals, depth (relative, per pixel of distance) and
// albedo. A surface and no surface never mix; two misses do.
VKPT_FN float guideWeight(DenoisePixel p, DenoisePixel q, float distance, DenoiseParams params) {
    if (hasSurface(p) != hasSurface(q)) return 0.0f;
    if (!hasSurface(p)) return 1.0f;
    float lengths = length(p.normal) * length(q.normal);
    float cosine = lengths > 0.0f ? dot(p.normal, q.normal) / lengths : 1.0f;
    float normalWeight = pow(max(cosine, 0.0f), params.normalPower);
    float depthScale = params.depthSigma * max(abs(p.depth), 1e-6f) * distance;
    float depthWeight = exp(-abs(p.depth - q.depth) / depthScale);
    vec3 albedoDifference = p.albedo - q.albedo;
    float albedoWeight =
        exp(-dot(albedoDifference, albedoDifference) / (params.albedoSigma * params.albedoSigma));
    return normalWeight * depthWeight * albedoWeight;
}

// The B3-spline's taps 1/16, 1/4, 3/8, 1/4, 1/16 at offsets −2..2.
VKPT_FN float atrousTap(int offset) {
    int distance = abs(offset);
    return distance == 0 ? 0.375f : (distance == 1 ? 0.25f : 0.0625f);
}

#ifdef __cplusplus
static_assert(sizeof(DenoisePixel) == 80 && offsetof(DenoisePixel, halfB) == 64);
static_assert(sizeof(DenoiseValue) == 80);
static_assert(sizeof(DenoiseParams) == 32);
} // namespace vkpt::gpu
#endif

#endif // VKPT_DENOISE_H
