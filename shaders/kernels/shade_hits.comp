// shade_hits.comp — the shade stage, one ray of the queue per invocation, making the
// reference's decisions in its order (docs/integrator.md): at a hit, emission with its MIS
// weight, N light samples as shadow records i·N + k, then the BSDF sample and Russian roulette
// that append the next bounce's ray; on a miss, the environment with its MIS weight.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/aovs.glsl"
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

#include "lib/kernel_bindings.h"

VKPT_DECLARE_BUFFERS(SHADE_HITS_BINDINGS)

#include "lib/counters.glsl"
#include "lib/lights.glsl"
#include "shared/sampler.h"
#include "shared/volume.h"

// Ray i of this bounce: what it hit, whose path it carries, and its light-sample records.
struct Vertex {
    uint ray;
    RayRecord record;
    SurfacePoint surface;
};

vec4 random4(PathState state, uint dimension) {
    return sampleFloats(frame.samplerSetup, frame.camera.width, frame.seed, state.pixel,
                        state.sampleIndex, passParams.bounce, dimension);
}

// Stores write only what a record needs, field by field: lavapipe writes a storage buffer one
// invocation and one word at a time (docs/gpu.md), so every word left out counts.

// A light-sample record: the flags alone when it cannot contribute (nothing reads the rest),
// the probe's factor only for a probe.
void storeLightSample(uint index, ShadowRay record) {
    shadowRays[index].flags = record.flags;
    if (record.flags == SHADOW_NONE) return;
    shadowRays[index].origin = record.origin;
    shadowRays[index].direction = record.direction;
    shadowRays[index].tMax = record.tMax;
    shadowRays[index].contribution = record.contribution;
    if (record.flags == SHADOW_PROBE) shadowRays[index].factor = record.factor;
}

bool sameBits(vec3 a, vec3 b) {
    return floatBitsToUint(a) == floatBitsToUint(b);
}

// The fields of a path's state that shading changed (the pixel and sample index never change).
void storePathState(uint slot, PathState before, PathState after) {
    if (!sameBits(after.throughput, before.throughput))
        pathStates[slot].throughput = after.throughput;
    if (!sameBits(after.radiance, before.radiance)) pathStates[slot].radiance = after.radiance;
    if (!sameBits(after.lightScale, before.lightScale))
        pathStates[slot].lightScale = after.lightScale;
    if (floatBitsToUint(after.previousBsdfPdf) != floatBitsToUint(before.previousBsdfPdf))
        pathStates[slot].previousBsdfPdf = after.previousBsdfPdf;
    if (featureTransmission && !sameBits(after.mediumCoefficient, before.mediumCoefficient))
        pathStates[slot].mediumCoefficient = after.mediumCoefficient;
    if (featureDispersion &&
        floatBitsToUint(after.wavelength) != floatBitsToUint(before.wavelength))
        pathStates[slot].wavelength = after.wavelength;
}

void clearLightSamples(uint ray) {
    uint n = frame.lightSamples;
    for (uint k = 0u; k < n; ++k)
        shadowRays[ray * n + k].flags = SHADOW_NONE;
}

// A light sample's shadow record with its estimator's weight: the path integrator's
// (misWeighted) carries the power heuristic against the BSDF strategy (Veach's multi-sample
// model, thesis 9.2.4); CS184's light-sampling estimator's is f·Le·cos / p_light, no MIS, times
// `scale`, the path's wavelength weight (1 without one).
ShadowRay weightedLightSample(LightConnection c, PathState state, float count, vec3 scale,
                              bool misWeighted) {
    ShadowRay shadow = shadowRecordOf(c);
    if (!c.valid) return shadow;
    if (!misWeighted) {
        shadow.contribution = (shadow.contribution / c.lightPdf) * scale;
        return shadow;
    }
    // Inside a volume the shadow ray crosses its medium (glass boundaries block it).
    if (featureTransmission)
        shadow.contribution =
            shadow.contribution *
            beerLambertTransmittance(state.mediumCoefficient,
                                     segmentLength(shadow.direction, shadow.tMax));
    // A punctual light has bsdfPdf 0: no BSDF sample can reach it, so its weight is 1.
    float weight = powerHeuristic(count, c.lightPdf, 1.0, c.bsdfPdf);
    shadow.contribution = shadow.contribution * (weight / (count * c.lightPdf));
    return shadow;
}

// CS184's hemisphere estimator's probe from `s` along a uniform direction (`local` in the
// shading frame): it counts the emission it reaches, or the environment when it leaves the
// scene, times f·cos / p (trace_shadow multiplies it in). Punctual lights cannot be hit, so this
// estimator does not see them.
ShadowRay hemisphereProbe(SurfacePoint s, vec3 direction, vec3 local, vec3 f) {
    vec3 origin = offsetFromSurface(s.position, s.geometricNormal, s.coordinateScale);
    return ShadowRay(origin, SHADOW_PROBE, direction, VKPT_FAR, f,
                     local.z / uniformHemispherePdf());
}

// What shading one ray decided: whether light-sample records were written, and the ray its
// path continues with (continues false when the path ends).
struct Shading {
    bool lit;
    bool continues;
    RayRecord next;
};

// The path goes on with BSDF sample `bsdf` (in `basis`, the shading frame) and Russian roulette
// (uRoulette); a surviving path's next ray goes to the other half of the queue (main appends it;
// its position there does not matter: nothing depends on it).
void continuePath(Vertex vertex, inout PathState state, inout Shading shading, Basis basis,
                  BsdfSample bsdf, float uRoulette) {
    SurfacePoint s = vertex.surface;
    vec3 direction = basisToWorld(basis, bsdf.direction);
    if (!bsdf.valid || !(bsdf.pdf > 0.0) || !continuesOnItsSide(bsdf, direction, s.geometricNormal))
        return;
    state.throughput *= bsdf.weight;
    float survival =
        russianRouletteSurvival(state.throughput, passParams.bounce + 1u, frame.rrStartDepth);
    if (uRoulette >= survival) return;
    state.throughput /= survival;
    state.previousBsdfPdf = misPdfOfBsdfSample(bsdf, s.shading);
    vec3 origin = offsetFromSurface(s.position, continuationNormal(bsdf, s.geometricNormal),
                                    s.coordinateScale);
    if (featureTransmission && bsdfSampleTransmits(bsdf))
        state.mediumCoefficient = mediumAfterTransmission(state.mediumCoefficient, s);
    shading.continues = true;
    shading.next = RayRecord(origin, vertex.record.slot, direction, 0u);
}

// What a vertex scatters, in one loop with one evaluation of the BSDF: lavapipe inlines every
// call, so each call site of the BSDF (or of the light connection) is another copy of it in the
// compiled kernel. With one for each estimator and one for the BSDF sample, the general kernel
// took LLVM 23 s to compile instead of 5.5 (`vkpt --general --stats` with an empty Mesa cache).
// - With shading.lit, the vertex's N light samples as shadow records i·N + k (docs/integrator.md):
//   the path integrator's next-event estimation (misWeighted), or the direct integrator's light
//   samples or, under INTEGRATOR_DIRECT_HEMISPHERE, its probes along uniform directions.
// - Then, where the path goes on, the BSDF sample (DIM_BSDF: u.xy the direction, u.z the
//   roulette, u.w the lobe), after the light samples: they see the medium before it.
void scatter(Vertex vertex, inout PathState state, inout Shading shading, vec3 scale,
             bool misWeighted, bool continues) {
    SurfacePoint s = vertex.surface;
    uint n = frame.lightSamples;
    uint lightSamples = shading.lit ? n : 0u;
    bool probes = !misWeighted && frame.integrator == INTEGRATOR_DIRECT_HEMISPHERE;
    Basis basis = makeBasis(s.shadingNormal);
    vec3 wo = worldToBasis(basis, s.outgoing);
    uint evaluations = lightSamples + (continues ? 1u : 0u);
    for (uint k = 0u; k < evaluations; ++k) {
        bool bsdfSample = k == lightSamples;
        vec4 u = random4(state, bsdfSample ? DIM_BSDF : DIM_LIGHT_FIRST + k);
        // The direction to evaluate (wi, in the shading frame) and what it belongs to.
        BsdfDirection sampled;
        LightApproach approach;
        vec3 direction, probeLocal, wi;
        bool evaluate;
        if (bsdfSample) {
            sampled = sampleBsdfDirection(s.shading, wo, vec2(u.x, u.y), u.w);
            wi = sampled.wi;
            evaluate = !sampled.finished;
        } else {
            u = lightSampleOrder(u);
            if (probes) {
                probeLocal = sampleUniformHemisphere(vec2(u.y, u.z));
                direction = basisToWorld(basis, probeLocal);
                evaluate = dot(direction, s.geometricNormal) > 0.0;
            } else {
                approach = approachLight(s, u);
                direction = approach.light.direction;
                evaluate = approach.valid;
            }
            wi = worldToBasis(basis, direction); // as evaluateSurfaceBsdf turns it
        }
        BsdfValue bsdf = BsdfValue(vec3(0.0), 0.0);
        if (evaluate) bsdf = evaluateBsdfValue(s.shading, wo, wi);
        if (bsdfSample) {
            continuePath(vertex, state, shading, basis,
                         sampled.finished ? sampled.whole : weighBsdfSample(wi, bsdf), u.z);
        } else {
            ShadowRay shadow =
                ShadowRay(vec3(0.0), SHADOW_NONE, vec3(0.0), VKPT_FAR, vec3(0.0), 0.0);
            if (evaluate)
                shadow = probes ? hemisphereProbe(s, direction, probeLocal, bsdf.f * scale)
                                : weightedLightSample(completeLightConnection(s, approach, bsdf),
                                                      state, float(n), scale, misWeighted);
            storeLightSample(vertex.ray * n + k, shadow);
        }
    }
}

// The number a path takes its wavelength from: DIM_CAMERA's z at bounce 0 (docs/integrator.md).
float wavelengthNumber(PathState state) {
    vec4 camera = sampleFloats(frame.samplerSetup, frame.camera.width, frame.seed, state.pixel,
                               state.sampleIndex, 0u, DIM_CAMERA);
    return camera.z;
}

// The path integrator at a hit before its light samples: emission with its MIS weight, and the
// path's wavelength, which binds the vertex's material to it (dispersion). Returns whether the
// path goes on (light samples where shading.lit, then the BSDF sample): false at the depth limit.
bool shadePathVertex(inout Vertex vertex, inout PathState state, inout Shading shading) {
    uint bounce = passParams.bounce;
    vec3 emitted = emittedRadiance(vertex.surface);
    if (emitted != vec3(0.0) && pathFilterKeeps(frame.pathFilter, bounce)) {
        float weight = 1.0;
        if (bounce > 0u) {
            float pdfLight = lightPdf(vertex.surface, vertex.record.origin);
            weight = emissionMisWeight(state.previousBsdfPdf, float(frame.lightSamples), pdfLight);
        }
        state.radiance += state.throughput * emitted * weight;
    }
    if (bounce >= frame.maxDepth) return false;
    if (featureDispersion)
        state.wavelength = bindWavelength(vertex.surface.shading, state.throughput,
                                          state.wavelength, wavelengthNumber(state));
    shading.lit = pathFilterKeeps(frame.pathFilter, bounce + 1u);
    return true;
}

// The direct integrator at a hit: emission seen directly. Returns whether one bounce of light
// samples or probes follows, and their scale. Dispersive glass is lit at the path's wavelength
// (bound into the vertex's material), as the path integrator lights it (docs/integrator.md,
// "Dispersion"): the same λ and weight as vkpt-ref's integrateDirect.
bool shadeDirect(inout Vertex vertex, inout PathState state, out vec3 scale) {
    scale = vec3(1.0);
    if (pathFilterKeeps(frame.pathFilter, 0u)) state.radiance += emittedRadiance(vertex.surface);
    if (frame.maxDepth == 0u || frame.lightSamples == 0u || !pathFilterKeeps(frame.pathFilter, 1u))
        return false;
    if (featureDispersion)
        bindWavelength(vertex.surface.shading, scale, VKPT_NO_WAVELENGTH, wavelengthNumber(state));
    return true;
}

// A ray that left the scene: the environment it sees, for the path tracer weighted against
// light sampling's chance of choosing that direction (Veach's power heuristic, as at a hit).
void shadeMiss(RayRecord record) {
    uint bounce = passParams.bounce;
    if (!hasEnvironment() || frame.integrator == INTEGRATOR_NORMALS ||
        !pathFilterKeeps(frame.pathFilter, bounce))
        return;
    vec3 unit = normalize(record.direction);
    vec3 radiance = environmentRadianceAlong(unit);
    if (radiance == vec3(0.0)) return;
    PathState state = fetchPathState(record.slot);
    if (featureTransmission && frame.integrator == INTEGRATOR_PATH)
        state.throughput *= beerLambertTransmittance(state.mediumCoefficient, VKPT_FAR);
    if (frame.integrator == INTEGRATOR_PATH && bounce > 0u) {
        float pdfLight = environmentLightPdf(unit);
        radiance = radiance *
                   emissionMisWeight(state.previousBsdfPdf, float(frame.lightSamples), pdfLight);
    }
    pathStates[record.slot].radiance = state.radiance + state.throughput * radiance;
}

// Shades ray i of the current queue.
Shading shadeRay(uint i) {
    Shading shading;
    shading.lit = false;
    shading.continues = false;
    uint queueHalf = passParams.bounce & 1u;
    HitRecord hit = fetchHit(i);
    RayRecord record = fetchRay(queueHalf * frame.slotCount + i);
    if (hit.triangle != NO_HIT) {
        Vertex vertex;
        vertex.ray = i;
        vertex.record = record;
#if VKPT_INSTANCES
        uint instance = hitInstances[i];
#else
        uint instance = NO_INSTANCE;
#endif
        vertex.surface = makeSurfacePoint(hit.triangle, instance, triangleHitOf(hit), record.origin,
                                          record.direction);
        // The camera sample's AOVs, from the hit its colour starts from.
        if (renderAovs() && passParams.bounce == 0u)
            sampleFeatures[record.slot] =
                surfaceFeatures(vertex.surface.shading.baseColor, vertex.surface.shadingNormal,
                                hit.t, record.direction, frame.camera.forward);
        PathState before = fetchPathState(record.slot);
        PathState state = before;
        // The segment to this hit crossed the path's medium (Beer–Lambert, shared/volume.h).
        if (featureTransmission && frame.integrator == INTEGRATOR_PATH)
            state.throughput *= beerLambertTransmittance(state.mediumCoefficient,
                                                         segmentLength(record.direction, hit.t));
        bool path = frame.integrator == INTEGRATOR_PATH;
        bool continues = false;
        vec3 scale = vec3(1.0);
        if (frame.integrator == INTEGRATOR_NORMALS) {
            state.radiance = 0.5 * vertex.surface.rawShadingNormal + 0.5;
        } else if (path) {
            continues = shadePathVertex(vertex, state, shading);
        } else {
            shading.lit = shadeDirect(vertex, state, scale);
        }
        if (shading.lit && path) state.lightScale = state.throughput;
        scatter(vertex, state, shading, scale, path, continues);
        storePathState(record.slot, before, state);
    } else {
        shadeMiss(record);
    }
    if (!shading.lit) clearLightSamples(i);
    return shading;
}

void main() {
    uint i = flatInvocationIndex();
    uint queueHalf = passParams.bounce & 1u;
    bool continues = false;
    RayRecord next;
    if (i < queueCounters[COUNTER_RAYS + queueHalf]) {
        Shading shading = shadeRay(i);
        continues = shading.continues;
        next = shading.next;
    }
    uint nextHalf = queueHalf ^ 1u;
    uint slot = appendToQueue(COUNTER_RAYS + nextHalf, continues);
    if (continues) {
        uint index = nextHalf * frame.slotCount + slot;
        rays[index].origin = next.origin;
        rays[index].slot = next.slot;
        rays[index].direction = next.direction;
    }
}
