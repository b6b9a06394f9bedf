// shade_hits.comp — the shade stage, one hit per invocation, making the reference's decisions
// in its order (docs/integrator.md): emission with its MIS weight, N light samples as shadow
// records i·N + k, then the BSDF sample and Russian roulette that append the next bounce's ray.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "lib/frame.glsl"

layout(local_size_x = WORKGROUP_SIZE) in;

VKPT_READONLY_BUFFER(BINDING_TRIANGLES, Triangle, triangles)
VKPT_READONLY_BUFFER(BINDING_TRIANGLE_NORMALS, TriangleNormals, triangleNormals)
VKPT_READONLY_BUFFER(BINDING_MATERIALS, Material, materials)
VKPT_READONLY_BUFFER(BINDING_EMITTERS, Emitter, emitters)
VKPT_BUFFER(BINDING_PATH_STATES, PathState, pathStates)
VKPT_BUFFER(BINDING_RAYS, RayRecord, rays)
VKPT_READONLY_BUFFER(BINDING_HITS, HitRecord, hits)
VKPT_WRITEONLY_BUFFER(BINDING_SHADOW_RAYS, ShadowRay, shadowRays)
VKPT_BUFFER(BINDING_QUEUE_COUNTERS, uint, queueCounters)

#include "lib/lights.glsl"
#include "shared/rng.h"

// Ray i of this bounce: what it hit, whose path it carries, and its light-sample records.
struct Vertex {
    uint ray;
    RayRecord record;
    SurfacePoint surface;
};

vec4 random4(PathState state, uint dimension) {
    return randomFloats(frame.seed, state.pixel, state.sampleIndex, passParams.bounce, dimension);
}

void clearLightSamples(uint ray) {
    uint n = frame.lightSamples;
    for (uint k = 0u; k < n; ++k)
        shadowRays[ray * n + k].flags = SHADOW_NONE;
}

// Next-event estimation of the path integrator: each light sample's contribution carries its
// power-heuristic weight against the BSDF strategy (Veach's multi-sample model, thesis 9.2.4).
void writePathLightSamples(Vertex vertex, PathState state) {
    uint n = frame.lightSamples;
    float count = float(n);
    for (uint k = 0u; k < n; ++k) {
        float pdfLight, pdfBsdf;
        ShadowRay shadow = makeLightSampleRay(vertex.surface, random4(state, DIM_LIGHT_FIRST + k),
                                              pdfLight, pdfBsdf);
        if (shadow.flags != SHADOW_NONE) {
            float weight = powerHeuristic(count, pdfLight, 1.0, pdfBsdf);
            shadow.contribution = shadow.contribution * (weight / (count * pdfLight));
        }
        shadowRays[vertex.ray * n + k] = shadow;
    }
}

// The Lambertian BSDF sample and Russian roulette; a surviving path appends its next ray to the
// other half of the queue (its position there does not matter: nothing depends on it).
void continuePath(Vertex vertex, inout PathState state) {
    vec4 u = random4(state, DIM_BSDF);
    vec3 local = sampleCosineHemisphere(vec2(u.x, u.y));
    vec3 direction = basisToWorld(makeBasis(vertex.surface.shadingNormal), local);
    float pdf = cosineHemispherePdf(local.z);
    if (!(pdf > 0.0) || dot(direction, vertex.surface.geometricNormal) <= 0.0) return;
    state.throughput *= lambertAlbedo(vertex.surface); // f·cos/pdf = (ρ/π)·cos/(cos/π)
    float survival =
        russianRouletteSurvival(state.throughput, passParams.bounce + 1u, frame.rrStartDepth);
    if (u.z >= survival) return;
    state.throughput /= survival;
    state.previousBsdfPdf = pdf;
    uint nextHalf = (passParams.bounce & 1u) ^ 1u;
    uint next = atomicAdd(queueCounters[COUNTER_RAYS + nextHalf], 1u);
    vec3 origin = offsetFromSurface(vertex.surface.position, vertex.surface.geometricNormal,
                                    vertex.surface.coordinateScale);
    rays[nextHalf * frame.slotCount + next] = RayRecord(origin, vertex.record.slot, direction, 0u);
}

// Returns whether light-sample records were written for this vertex.
bool shadePathVertex(Vertex vertex, inout PathState state) {
    uint bounce = passParams.bounce;
    vec3 emitted = emittedRadiance(vertex.surface);
    if (emitted != vec3(0.0) && pathFilterKeeps(frame.pathFilter, bounce)) {
        float weight = 1.0;
        if (bounce > 0u) {
            float pdfLight = lightPdf(vertex.surface, vertex.record.origin);
            weight =
                powerHeuristic(1.0, state.previousBsdfPdf, float(frame.lightSamples), pdfLight);
        }
        state.radiance += state.throughput * emitted * weight;
    }
    if (bounce >= frame.maxDepth) return false;
    bool lit = pathFilterKeeps(frame.pathFilter, bounce + 1u);
    if (lit) {
        writePathLightSamples(vertex, state);
        state.lightScale = state.throughput;
    }
    continuePath(vertex, state);
    return lit;
}

// CS184's hemisphere estimator: N uniform directions, each a probe that counts the emission
// it reaches (trace_shadow multiplies it in).
void writeHemisphereProbes(Vertex vertex, PathState state) {
    SurfacePoint s = vertex.surface;
    vec3 f = lambertAlbedo(s) * VKPT_INV_PI;
    Basis basis = makeBasis(s.shadingNormal);
    vec3 origin = offsetFromSurface(s.position, s.geometricNormal, s.coordinateScale);
    uint n = frame.lightSamples;
    for (uint k = 0u; k < n; ++k) {
        vec4 u = random4(state, DIM_LIGHT_FIRST + k);
        vec3 local = sampleUniformHemisphere(vec2(u.y, u.z));
        vec3 direction = basisToWorld(basis, local);
        ShadowRay probe = ShadowRay(vec3(0.0), SHADOW_NONE, vec3(0.0), VKPT_FAR, vec3(0.0), 0.0);
        if (dot(direction, s.geometricNormal) > 0.0) {
            probe = ShadowRay(origin, SHADOW_PROBE, direction, VKPT_FAR, f,
                              local.z / uniformHemispherePdf());
        }
        shadowRays[vertex.ray * n + k] = probe;
    }
}

// CS184's light-sampling estimator: Σ f·Le·cos / p_light, no MIS.
void writeDirectLightSamples(Vertex vertex, PathState state) {
    uint n = frame.lightSamples;
    for (uint k = 0u; k < n; ++k) {
        float pdfLight, pdfBsdf;
        ShadowRay shadow = makeLightSampleRay(vertex.surface, random4(state, DIM_LIGHT_FIRST + k),
                                              pdfLight, pdfBsdf);
        if (shadow.flags != SHADOW_NONE) shadow.contribution = shadow.contribution / pdfLight;
        shadowRays[vertex.ray * n + k] = shadow;
    }
}

// The direct integrator: emission seen directly, then one bounce of light samples or probes.
bool shadeDirect(Vertex vertex, inout PathState state) {
    if (pathFilterKeeps(frame.pathFilter, 0u)) state.radiance += emittedRadiance(vertex.surface);
    if (frame.maxDepth == 0u || frame.lightSamples == 0u || !pathFilterKeeps(frame.pathFilter, 1u))
        return false;
    if (frame.integrator == INTEGRATOR_DIRECT_HEMISPHERE) {
        writeHemisphereProbes(vertex, state);
    } else {
        writeDirectLightSamples(vertex, state);
    }
    return true;
}

void main() {
    uint i = flatInvocationIndex();
    uint queueHalf = passParams.bounce & 1u;
    if (i >= queueCounters[COUNTER_RAYS + queueHalf]) return;
    HitRecord hit = hits[i];
    bool lit = false;
    if (hit.triangle != NO_HIT) {
        Vertex vertex;
        vertex.ray = i;
        vertex.record = rays[queueHalf * frame.slotCount + i];
        vertex.surface = makeSurfacePoint(hit, vertex.record.direction);
        PathState state = pathStates[vertex.record.slot];
        if (frame.integrator == INTEGRATOR_NORMALS) {
            state.radiance = 0.5 * vertex.surface.rawShadingNormal + 0.5;
        } else if (frame.integrator == INTEGRATOR_PATH) {
            lit = shadePathVertex(vertex, state);
        } else {
            lit = shadeDirect(vertex, state);
        }
        pathStates[vertex.record.slot] = state;
    }
    if (!lit) clearLightSamples(i);
}
