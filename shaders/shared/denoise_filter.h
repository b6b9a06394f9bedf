// denoise_filter.h — the denoiser's pass (shared/denoise.h): the blend of the candidates by
// their estimated error, and one à-trous iteration. Both read the pixels around the one they
// write: in a kernel from the buffers denoisePixels and denoiseValuesIn, which the kernel
// declares before it includes this file; in C++ from the arrays of a DenoiseSource.
#ifndef VKPT_DENOISE_FILTER_H
#define VKPT_DENOISE_FILTER_H

#include "denoise.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Where a kernel and the C++ loop read the pixels and the current iterate: buffers on the
// device (declared by the kernel before it includes this file), arrays on the host.
#ifdef __cplusplus
struct DenoiseSource {
    const DenoisePixel* pixels;
    const DenoiseValue* values;
};
#define DENOISE_SOURCE_PARAM const DenoiseSource &source,
#define DENOISE_PIXEL(i) source.pixels[i]
#define DENOISE_VALUE(i) source.values[i]
#else
#define DENOISE_SOURCE_PARAM
#define DENOISE_PIXEL(i) denoisePixels[i]
#define DENOISE_VALUE(i) denoiseValuesIn[i]
#endif

// The variances the centre's tests use, for the whole estimate and each half (x, y, z): its own,
// or, where larger, its own blended with the mean over its 5×5 neighbourhood (DENOISE_PRIOR_RADIUS)
// leaving out the largest, the neighbourhood counting as DENOISE_PRIOR_SAMPLES samples against the
// pixel's n. A pixel whose few samples happened to agree (variance 0 at 4 spp, or a heavy tail's
// rare bright path missed) thus still sees its surroundings' noise, while 64 samples of exactly 0
// (a black emitter's back among lit floor) are believed; and one firefly near the pixel (a
// variance far above the rest) does not lift its bound and so is not spread into it.
VKPT_FN vec3 centreTestVariances(DENOISE_SOURCE_PARAM uint x, uint y, DenoiseParams params) {
    vec3 total = vec3(0.0f);
    vec3 largest = vec3(0.0f);
    float count = 0.0f;
    for (int dy = -DENOISE_PRIOR_RADIUS; dy <= DENOISE_PRIOR_RADIUS; ++dy) {
        for (int dx = -DENOISE_PRIOR_RADIUS; dx <= DENOISE_PRIOR_RADIUS; ++dx) {
            int qx = int(x) + dx;
            int qy = int(y) + dy;
            if (qx < 0 || qy < 0 || qx >= int(params.width) || qy >= int(params.height)) continue;
            DenoiseValue value = DENOISE_VALUE(uint(qy) * params.width + uint(qx));
            vec3 variances = vec3(value.full.w, value.halfA.w, value.halfB.w);
            total += variances;
            largest = max(largest, variances);
            count += 1.0f;
        }
    }
    DenoiseValue centre = DENOISE_VALUE(y * params.width + x);
    vec3 own = vec3(centre.full.w, centre.halfA.w, centre.halfB.w);
    vec3 around = count > 1.0f ? (total - largest) / (count - 1.0f) : own;
    float samples = float(DENOISE_PIXEL(y * params.width + x).sampleCount);
    return max(own, (samples * own + DENOISE_PRIOR_SAMPLES * around) /
                        (samples + DENOISE_PRIOR_SAMPLES));
}

// The error estimate of the current iterate as the pixel's output: the pixels' shares
// (DenoiseValue.estimate, computed as each pass wrote them) averaged over its 5×5 neighbourhood
// with the tent weights (3 − |dx|)(3 − |dy|) (as many independent estimates as 18 pixels): one
// pixel's estimate is the square of a noisy difference, too noisy to choose by alone (and may come
// out negative), and a pixel left raw by a chance low estimate keeps all its noise. (Wider windows
// measured worse: they mix in the errors of other surfaces and edges.) DENOISE_NO_ESTIMATE where no
// pixel of the neighbourhood has two halves: the candidate is not taken.
VKPT_FN float neighbourhoodError(DENOISE_SOURCE_PARAM uint x, uint y, DenoiseParams params) {
    float total = 0.0f;
    float weights = 0.0f;
    for (int dy = -DENOISE_ERROR_RADIUS; dy <= DENOISE_ERROR_RADIUS; ++dy) {
        for (int dx = -DENOISE_ERROR_RADIUS; dx <= DENOISE_ERROR_RADIUS; ++dx) {
            int qx = int(x) + dx;
            int qy = int(y) + dy;
            if (qx < 0 || qy < 0 || qx >= int(params.width) || qy >= int(params.height)) continue;
            vec4 estimate = DENOISE_VALUE(uint(qy) * params.width + uint(qx)).estimate;
            float weight = estimate.y * float((DENOISE_ERROR_RADIUS + 1 - abs(dx)) *
                                              (DENOISE_ERROR_RADIUS + 1 - abs(dy)));
            total += weight * estimate.x;
            weights += weight;
        }
    }
    return weights > 0.0f ? total / weights : DENOISE_NO_ESTIMATE;
}

VKPT_FN vec3 rgbOf(vec4 value) {
    return vec3(value.x, value.y, value.z);
}

// One pass at pixel (x, y). First the blend: the current iterate (the raw estimate on the first
// pass, the result of k à-trous steps on pass k) joins the blend of the candidates so far with
// the weight 1 / error², its error estimated from the halves (neighbourhoodError). Inverse-error
// weights, as inverse variances combine estimates: each candidate's estimate is too noisy at a few
// samples to pick one outright — picking the lowest per pixel measured 1.72e-3 against
// 1.55e-3 for the blend (Cornell box, 16 spp; docs/trade/denoise.md) — and the blend tends to
// the choice where one candidate's error is far below the others'. The raw estimate is always the
// first candidate, so where filtering does not pay the pixel stays near raw, and as the samples
// grow every filtered candidate's bias stands out against the falling variance (its weight
// falls as 1 / bias² against the raw's n²) and the output converges to the raw image
// (docs/denoise.md). Then, unless this is the last pass (step 0), one à-trous iteration of each
// of the three estimates: the weighted mean of the 5×5 taps `step` apart and the variance of its
// luminance. The guides' weights are shared; each estimate's gate tests its own means, so the
// filtered half A depends on half A's samples only. A tap's variance enters the test capped at
// the centre's, so that a firefly (a mean far above its neighbours, with a variance to match)
// cannot pass its neighbours' tests on the strength of its own noise.
VKPT_FN DenoiseValue filterPixel(DENOISE_SOURCE_PARAM uint x, uint y, DenoiseParams params) {
    uint centreIndex = y * params.width + x;
    DenoisePixel centre = DENOISE_PIXEL(centreIndex);
    DenoiseValue centreValue = DENOISE_VALUE(centreIndex);
#ifdef __cplusplus
    float error = neighbourhoodError(source, x, y, params);
#else
    float error = neighbourhoodError(x, y, params);
#endif
    DenoiseValue result = centreValue;
    // The raw candidate's estimate (first pass) weighed up by 1 + DENOISE_RAW_PRIOR / n
    // (denoise.h).
    if (params.step == 1u && error != DENOISE_NO_ESTIMATE)
        error *= 1.0f + DENOISE_RAW_PRIOR / max(float(centre.sampleCount), 1.0f);
    if (error != DENOISE_NO_ESTIMATE) {
        float floored = max(error, DENOISE_ERROR_FLOOR / max(float(centre.sampleCount), 1.0f));
        float weight = 1.0f / (floored * floored);
        float total = centreValue.chosen.w + weight;
        vec3 before = rgbOf(centreValue.chosen);
        vec3 blended = before + (weight / total) * (rgbOf(centreValue.full) - before);
        result.chosen = vec4(blended.x, blended.y, blended.z, total);
    }
    if (params.step == 0u) return result;
#ifdef __cplusplus
    vec3 centreVariances = centreTestVariances(source, x, y, params);
#else
    vec3 centreVariances = centreTestVariances(x, y, params);
#endif
    // The centre plus the weighted differences, so that with every tap rejected the output is
    // the centre's value bit for bit (Σ w·x / Σ w need not round back to x).
    vec3 centreFull = rgbOf(centreValue.full);
    vec3 centreA = rgbOf(centreValue.halfA);
    vec3 centreB = rgbOf(centreValue.halfB);
    vec3 differenceFull = vec3(0.0f);
    vec3 differenceA = vec3(0.0f);
    vec3 differenceB = vec3(0.0f);
    vec3 weightSums = vec3(0.0f);
    vec3 varianceSums = vec3(0.0f);
    for (int j = -2; j <= 2; ++j) {
        for (int i = -2; i <= 2; ++i) {
            int qx = int(x) + i * int(params.step);
            int qy = int(y) + j * int(params.step);
            if (qx < 0 || qy < 0 || qx >= int(params.width) || qy >= int(params.height)) continue;
            uint index = uint(qy) * params.width + uint(qx);
            DenoiseValue value = DENOISE_VALUE(index);
            vec3 weights = vec3(atrousTap(i) * atrousTap(j));
            if (index != centreIndex) {
                float distance = float(params.step) * sqrt(float(i * i + j * j));
                vec3 variances =
                    centreVariances +
                    min(vec3(value.full.w, value.halfA.w, value.halfB.w), centreVariances);
                weights *= guideWeight(centre, DENOISE_PIXEL(index), distance, params);
                weights.x *= gateWeight(centreFull, rgbOf(value.full), variances.x, params.gateT);
                weights.y *= gateWeight(centreA, rgbOf(value.halfA), variances.y, params.gateT);
                weights.z *= gateWeight(centreB, rgbOf(value.halfB), variances.z, params.gateT);
            }
            differenceFull += weights.x * (rgbOf(value.full) - centreFull);
            differenceA += weights.y * (rgbOf(value.halfA) - centreA);
            differenceB += weights.z * (rgbOf(value.halfB) - centreB);
            weightSums += weights;
            varianceSums += weights * weights * vec3(value.full.w, value.halfA.w, value.halfB.w);
        }
    }
    vec3 variances = varianceSums / (weightSums * weightSums);
    result.full = vec4(centreFull + differenceFull / weightSums.x, variances.x);
    result.halfA = vec4(centreA + differenceA / weightSums.y, variances.y);
    result.halfB = vec4(centreB + differenceB / weightSums.z, variances.z);
    result.estimate = pixelEstimate(centre, result);
    return result;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_DENOISE_FILTER_H
