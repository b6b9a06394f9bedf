// path_integrator.cpp — the reference path tracer: NEE + BSDF sampling combined by MIS.
#include "reference/integrators.h"

#include "reference/direct_lighting.h"
#include "reference/light_sampling.h"
#include "reference/surface.h"
#include "shared/path_rules.h"
#include "shared/ray_offset.h"
#include "shared/rng.h"
#include "shared/sampling.h"

namespace vkpt {

namespace {

struct PathVertex {
    const SurfacePoint& surface;
    std::uint32_t bounce; // scattering events before this vertex
};

// Light samples at one vertex, each weighted against the BSDF strategy (Veach 1997, 9.2.4:
// the multi-sample model with N light samples and one BSDF sample).
glm::vec3 estimateDirectWithMis(IntegratorContext& context, const SampleKey& key,
                                const PathVertex& vertex) {
    const std::uint32_t lightSamples = context.settings.lightSamples;
    const float n = float(lightSamples);
    glm::vec3 sum(0.0f);
    for (std::uint32_t i = 0; i < lightSamples; ++i) {
        glm::vec4 u = gpu::randomFloats(key.seed, key.pixel, key.sampleIndex, vertex.bounce,
                                        DIM_LIGHT_FIRST + i);
        DirectLightSample d = sampleDirectLight(context.tracer, vertex.surface, u);
        if (!d.contributes) continue;
        float weight = gpu::powerHeuristic(n, d.lightPdf, 1.0f, d.bsdfPdf);
        sum += d.unweighted * (weight / (n * d.lightPdf));
    }
    return sum;
}

struct BsdfSample {
    glm::vec3 direction{0.0f};
    float pdf = 0.0f;
    float russianRoulette = 0.0f; // the uniform number the roulette uses
};

BsdfSample sampleLambert(const SampleKey& key, const PathVertex& vertex) {
    glm::vec4 u =
        gpu::randomFloats(key.seed, key.pixel, key.sampleIndex, vertex.bounce, DIM_BSDF);
    glm::vec3 local = gpu::sampleCosineHemisphere(glm::vec2(u.x, u.y));
    BsdfSample sample;
    sample.direction = gpu::basisToWorld(gpu::makeBasis(vertex.surface.shadingNormal), local);
    sample.pdf = gpu::cosineHemispherePdf(local.z);
    sample.russianRoulette = u.z;
    return sample;
}

} // namespace

glm::vec3 integratePath(IntegratorContext& context, const SampleKey& key, const CameraRay& ray) {
    const RenderSettings& settings = context.settings;
    const auto filter = std::uint32_t(settings.pathFilter);
    const float lightSamples = float(settings.lightSamples);
    glm::vec3 radiance(0.0f);
    glm::vec3 throughput(1.0f);
    glm::vec3 origin = ray.origin;
    glm::vec3 direction = ray.direction;
    float previousBsdfPdf = 0.0f;
    for (std::uint32_t bounce = 0;; ++bounce) {
        RayKind kind = bounce == 0 ? RayKind::Camera : RayKind::Extension;
        ClosestHit hit = context.tracer.closest(origin, direction, kind);
        if (!hit.hit) break;
        SurfacePoint surface = makeSurfacePoint(context.tracer.scene(), hit, direction);
        glm::vec3 emitted = emittedRadiance(surface);
        if (emitted != glm::vec3(0.0f) && gpu::pathFilterKeeps(filter, bounce)) {
            float weight = 1.0f;
            if (bounce > 0) {
                float pdfLight = lightPdf(context.tracer.scene(), surface, origin);
                weight = gpu::powerHeuristic(1.0f, previousBsdfPdf, lightSamples, pdfLight);
            }
            radiance += throughput * emitted * weight;
        }
        if (bounce >= settings.maxDepth) break;
        PathVertex vertex{surface, bounce};
        if (gpu::pathFilterKeeps(filter, bounce + 1))
            radiance += throughput * estimateDirectWithMis(context, key, vertex);
        BsdfSample bsdf = sampleLambert(key, vertex);
        if (!(bsdf.pdf > 0.0f) || glm::dot(bsdf.direction, surface.geometricNormal) <= 0.0f) break;
        throughput *= lambertAlbedo(surface); // f·cos/pdf = (ρ/π)·cos/(cos/π)
        float survival = gpu::russianRouletteSurvival(throughput, bounce + 1, settings.rrStartDepth);
        if (bsdf.russianRoulette >= survival) break;
        throughput /= survival;
        previousBsdfPdf = bsdf.pdf;
        origin = gpu::offsetFromSurface(surface.position, surface.geometricNormal,
                                        surface.coordinateScale);
        direction = bsdf.direction;
    }
    return radiance;
}

glm::vec3 integrateNormals(IntegratorContext& context, const CameraRay& ray) {
    ClosestHit hit = context.tracer.closest(ray.origin, ray.direction, RayKind::Camera);
    if (!hit.hit) return glm::vec3(0.0f);
    SurfacePoint surface = makeSurfacePoint(context.tracer.scene(), hit, ray.direction);
    return 0.5f * surface.rawShadingNormal + 0.5f;
}

glm::vec3 integrate(IntegratorContext& context, const SampleKey& key, const CameraRay& ray) {
    switch (context.settings.integrator) {
    case Integrator::Path:
        return integratePath(context, key, ray);
    case Integrator::Direct:
        return integrateDirect(context, key, ray);
    case Integrator::Normals:
        return integrateNormals(context, ray);
    }
    return glm::vec3(0.0f);
}

} // namespace vkpt
