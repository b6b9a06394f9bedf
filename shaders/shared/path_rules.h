// path_rules.h — the decisions of the path integrator that both renderers must make
// identically so that, at one seed, their paths are the same paths.
#ifndef VKPT_PATH_RULES_H
#define VKPT_PATH_RULES_H

#include "host_device.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// Russian roulette (Arvo and Kirk 1990), from the rrStartDepth-th scattering event on: the
// path continues with probability q = clamp(max(throughput), 0.05, 1) and its throughput is
// divided by q, which keeps the estimator unbiased. The floor bounds the weight 1/q by 20.
#define RR_MIN_SURVIVAL 0.05f

VKPT_FN float russianRouletteSurvival(vec3 throughput, uint scatterCount, uint rrStartDepth) {
    if (scatterCount < rrStartDepth) return 1.0f;
    float q = max(max(throughput.x, throughput.y), throughput.z);
    return clamp(q, RR_MIN_SURVIVAL, 1.0f);
}

// Path filters for --direct-only / --indirect-only: a contribution is kept by the number of
// scattering events on its path (0 = emitter seen directly, 1 = direct lighting).
#define PATH_FILTER_ALL 0u
#define PATH_FILTER_DIRECT_ONLY 1u
#define PATH_FILTER_INDIRECT_ONLY 2u

VKPT_FN bool pathFilterKeeps(uint pathFilter, uint scatterCount) {
    if (pathFilter == PATH_FILTER_DIRECT_ONLY) return scatterCount <= 1u;
    if (pathFilter == PATH_FILTER_INDIRECT_ONLY) return scatterCount >= 2u;
    return true;
}

// Solid-angle pdf of a point sampled on a surface with area pdf pdfArea, seen at squared
// distance distanceSquared under cosine cosAtLight; 0 where the point is seen edge-on.
VKPT_FN float areaToSolidAnglePdf(float pdfArea, float distanceSquared, float cosAtLight) {
    float c = abs(cosAtLight);
    return c > 0.0f ? pdfArea * distanceSquared / c : 0.0f;
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_PATH_RULES_H
