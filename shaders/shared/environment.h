// environment.h — what rays that leave the scene see, and how next-event estimation samples it:
// a constant radiance (uniform over the sphere) or an equirectangular map importance sampled by
// its luminance × sin θ CDF (pbrt-v3 §14.2.4, InfiniteAreaLight: a 2D piecewise-constant
// distribution in (u, v), marginal over rows then conditional within the row, and the
// Jacobian 2π² sin θ from (u, v) to solid angle).
//
// The map is read one element at a time through scene_view.h's accessors: a span of the
// SceneView on the C++ side, the kernels' arrays, which may be split across several buffers,
// on the GLSL side (lib/scene_view.glsl):
//   vec4 sceneEnvironmentTexel(i):  width × height RGB (w unused), row 0 at the top (+Y);
//   float sceneEnvironmentCdf(i):   height rows of width inclusive conditional entries (each
//                                   row ends at 1), then height inclusive marginal entries
//                                   (ending at 1).
#ifndef VKPT_ENVIRONMENT_H
#define VKPT_ENVIRONMENT_H

#include "host_device.h"
#include "sampling.h"
#include "scene_view.h"

#ifdef __cplusplus
namespace vkpt::gpu {
#endif

// GLSL's two-argument arctangent atan(y, x) (host_device.h maps it onto GLM), with the value
// at the origin, undefined in GLSL, taken as 0 on both sides.
VKPT_FN float environmentAtan2(float y, float x) {
    return (x == 0.0f && y == 0.0f) ? 0.0f : atan(y, x);
}

// Directions closer to a pole than this (sin θ below it) have pdf 0 and are never sampled:
// the (u, v) → solid angle Jacobian 1/sin θ would overflow there. The excluded cap has a
// solid angle of about 3e-12 sr.
#define VKPT_ENVIRONMENT_MIN_SIN_THETA 1e-6f

// The equirectangular parametrisation, +Y up (the glTF convention):
//   v = θ/π with θ the angle from +Y, so v = 0 is +Y (the map's top row), v = 1 is −Y;
//   u = 1/2 + φ/(2π) with φ = atan2(z, x), so u = 0 (the left edge) is −X, u = 1/4 is −Z,
//   u = 1/2 is +X and u = 3/4 is +Z.
// Seen from inside, the map is not mirrored: a camera looking along −Z with +Y up sees +X to
// its right, and u grows to the right. The arctangent of the pole (x = z = 0), undefined in
// GLSL, is taken as 0 on both sides. u lies in [0, 1), v in [0, 1].
VKPT_FN vec2 directionToEquirect(vec3 unitDirection) {
    float sinTheta = length(vec2(unitDirection.x, unitDirection.z));
    // atan2 rather than acos(y): acos loses the angle near the poles, where y is close to ±1.
    float theta = environmentAtan2(sinTheta, unitDirection.y);
    float phi = environmentAtan2(unitDirection.z, unitDirection.x);
    float u = 0.5f + phi * (0.5f / VKPT_PI);
    if (u >= 1.0f) u -= 1.0f;
    return vec2(u, theta * (1.0f / VKPT_PI));
}

VKPT_FN vec3 equirectToDirection(vec2 uv) {
    float phi = 2.0f * VKPT_PI * (uv.x - 0.5f);
    float theta = VKPT_PI * uv.y;
    float sinTheta = sin(theta);
    return vec3(sinTheta * cos(phi), cos(theta), sinTheta * sin(phi));
}

// The texel (or CDF entry) that coordinate x in [0, 1] falls in among n; NaN goes to 0, so a
// bad direction can never index outside the map.
VKPT_FN uint environmentCell(float x, uint n) {
    float scaled = x * float(n);
    return scaled > 0.0f ? uint(min(scaled, float(n - 1u))) : 0u;
}

VKPT_FN vec3 environmentRadiance(EnvironmentParams env, vec3 unitDirection VKPT_SCENE_PARAM) {
    if (env.width == 0u) return env.radiance;
    vec2 uv = directionToEquirect(unitDirection);
    uint texel = environmentCell(uv.y, env.height) * env.width + environmentCell(uv.x, env.width);
    return vec3(sceneEnvironmentTexel(texel VKPT_SCENE_ARG)) * env.radiance;
}

struct EnvironmentSample {
    vec3 direction; // unit, towards the environment
    vec3 radiance;  // arriving from `direction`
    float pdf;      // solid angle
    bool valid;     // false: a pole direction (pdf 0), or a map without weight in the row
};

VKPT_FN EnvironmentSample environmentNoSample() {
    EnvironmentSample none;
    none.direction = vec3(0.0f, 1.0f, 0.0f);
    none.radiance = vec3(0.0f);
    none.pdf = 0.0f;
    none.valid = false;
    return none;
}

// The first of `count` inclusive CDF entries starting at `first` that exceeds u
// (std::upper_bound), the last one if none does. An entry equal to its predecessor (weight 0)
// is never returned for u >= 0: any u below it is also below the predecessor.
VKPT_FN uint environmentUpperBound(uint first, uint count, float u VKPT_SCENE_PARAM) {
    uint lo = 0u;
    uint hi = count;
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (u < sceneEnvironmentCdf(first + mid VKPT_SCENE_ARG)) {
            hi = mid;
        } else {
            lo = mid + 1u;
        }
    }
    return min(lo, count - 1u);
}

// The CDF below entry `index`, and the entry's probability: its CDF step. The pdf is read from
// the stored floats, not from the weights they came from, so that it is exactly the
// probability the search realises.
VKPT_FN float environmentCdfBelow(uint first, uint index VKPT_SCENE_PARAM) {
    return index > 0u ? sceneEnvironmentCdf(first + index - 1u VKPT_SCENE_ARG) : 0.0f;
}

VKPT_FN float environmentCdfStep(uint first, uint index VKPT_SCENE_PARAM) {
    return sceneEnvironmentCdf(first + index VKPT_SCENE_ARG) -
           environmentCdfBelow(first, index VKPT_SCENE_ARG);
}

// (u, v) density → solid-angle density: dω = 2π² sin θ du dv. sin θ is taken from the
// direction itself, so that sampling and evaluating the same direction agree.
VKPT_FN float environmentSolidAnglePdf(float pdfUv, vec3 unitDirection) {
    float sinTheta = length(vec2(unitDirection.x, unitDirection.z));
    if (!(sinTheta >= VKPT_ENVIRONMENT_MIN_SIN_THETA)) return 0.0f;
    return pdfUv / (2.0f * VKPT_PI * VKPT_PI * sinTheta);
}

// Where u falls inside the CDF step [below, below + step), in [0, 1): the continuous offset
// within the chosen texel (pbrt-v3's Distribution1D::SampleContinuous).
VKPT_FN float environmentOffsetInStep(float u, float below, float step) {
    return min((u - below) / step, 0.99999994f);
}

// u.x chooses the row by the marginal CDF, u.y the column by that row's conditional CDF.
VKPT_FN EnvironmentSample sampleEnvironment(EnvironmentParams env, vec2 u VKPT_SCENE_PARAM) {
    EnvironmentSample result = environmentNoSample();
    if (env.width == 0u) {
        result.direction = sampleUniformSphere(u);
        result.radiance = env.radiance;
        result.pdf = uniformSpherePdf();
        result.valid = true;
        return result;
    }
    uint marginal = env.width * env.height;
    uint row = environmentUpperBound(marginal, env.height, u.x VKPT_SCENE_ARG);
    float rowProbability = environmentCdfStep(marginal, row VKPT_SCENE_ARG);
    uint rowStart = row * env.width;
    uint column = environmentUpperBound(rowStart, env.width, u.y VKPT_SCENE_ARG);
    float columnProbability = environmentCdfStep(rowStart, column VKPT_SCENE_ARG);
    if (!(rowProbability > 0.0f) || !(columnProbability > 0.0f)) return result;

    float rowBelow = environmentCdfBelow(marginal, row VKPT_SCENE_ARG);
    float columnBelow = environmentCdfBelow(rowStart, column VKPT_SCENE_ARG);
    float dv = environmentOffsetInStep(u.x, rowBelow, rowProbability);
    float du = environmentOffsetInStep(u.y, columnBelow, columnProbability);
    vec2 uv = vec2((float(column) + du) / float(env.width), (float(row) + dv) / float(env.height));
    result.direction = equirectToDirection(uv);
    float pdfUv = rowProbability * columnProbability * float(env.width) * float(env.height);
    result.pdf = environmentSolidAnglePdf(pdfUv, result.direction);
    // The chosen texel's own radiance: a lookup by direction could land in the neighbour when
    // the point rounds onto a texel edge, and radiance/pdf must belong to the same texel.
    result.radiance = vec3(sceneEnvironmentTexel(rowStart + column VKPT_SCENE_ARG)) * env.radiance;
    result.valid = result.pdf > 0.0f;
    return result;
}

// The solid-angle pdf with which sampleEnvironment produces unitDirection.
VKPT_FN float environmentPdf(EnvironmentParams env, vec3 unitDirection VKPT_SCENE_PARAM) {
    if (env.width == 0u) return uniformSpherePdf();
    vec2 uv = directionToEquirect(unitDirection);
    uint row = environmentCell(uv.y, env.height);
    uint column = environmentCell(uv.x, env.width);
    float rowProbability = environmentCdfStep(env.width * env.height, row VKPT_SCENE_ARG);
    float columnProbability = environmentCdfStep(row * env.width, column VKPT_SCENE_ARG);
    float pdfUv = rowProbability * columnProbability * float(env.width) * float(env.height);
    return environmentSolidAnglePdf(pdfUv, unitDirection);
}

#ifdef __cplusplus
} // namespace vkpt::gpu
#endif

#endif // VKPT_ENVIRONMENT_H
