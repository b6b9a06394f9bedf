// path_integrator.cpp — the reference path tracer: NEE + BSDF sampling combined by MIS, the
// environment on rays that leave the scene.
#include "reference/integrators.h"

#include "reference/direct_lighting.h"
#include "shared/bsdf.h"
#include "shared/lights.h"
#include "shared/path_rules.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"
#include "shared/volume.h"

namespace vkpt {

namespace {

struct PathVertex {
    const gpu::SurfacePoint& surface;
    std::uint32_t bounce; // scattering events before this vertex
    glm::vec3 medium;     // σ of the medium the vertex's light samples travel in (volume.h)
    bool inVolume;        // the scene has volumes: light samples are attenuated by `medium`
};

// Light samples at one vertex, each weighted against the BSDF strategy (Veach 1997, 9.2.4:
// the multi-sample model with N light samples and one BSDF sample).
glm::vec3 estimateDirectWithMis(IntegratorContext& context, const SampleKey& key,
                                const PathVertex& vertex) {
    const std::uint32_t lightSamples = context.settings.lightSamples;
    const float n = float(lightSamples);
    glm::vec3 sum(0.0f);
    for (std::uint32_t i = 0; i < lightSamples; ++i) {
        glm::vec4 u = gpu::lightSampleOrder(sampleFloats(key, vertex.bounce, DIM_LIGHT_FIRST + i));
        DirectLightSample d = sampleDirectLight(context.tracer, vertex.surface, u);
        if (!d.contributes) continue;
        glm::vec3 unweighted = d.unweighted;
        if (vertex.inVolume)
            unweighted = unweighted * gpu::beerLambertTransmittance(vertex.medium, d.distance);
        // A punctual light has bsdfPdf 0: no BSDF sample can reach it, so its weight is 1.
        float weight = gpu::powerHeuristic(n, d.lightPdf, 1.0f, d.bsdfPdf);
        sum += unweighted * (weight / (n * d.lightPdf));
    }
    return sum;
}

struct ScatterSample {
    glm::vec3 direction{0.0f}; // world
    gpu::BsdfSample bsdf{};
    float russianRoulette = 0.0f; // the uniform number the roulette uses
};

// DIM_BSDF: u.xy the direction, u.z the roulette, u.w the lobe (docs/integrator.md).
ScatterSample sampleScatter(const SampleKey& key, const PathVertex& vertex) {
    glm::vec4 u = sampleFloats(key, vertex.bounce, DIM_BSDF);
    const gpu::SurfacePoint& s = vertex.surface;
    gpu::Basis basis = gpu::makeBasis(s.shadingNormal);
    ScatterSample sample;
    sample.bsdf =
        gpu::sampleBsdf(s.shading, gpu::worldToBasis(basis, s.outgoing), glm::vec2(u.x, u.y), u.w);
    sample.direction = gpu::basisToWorld(basis, sample.bsdf.direction);
    sample.russianRoulette = u.z;
    return sample;
}

// What a ray that leaves the scene brings back: the environment, weighted against light
// sampling's chance of choosing that direction.
glm::vec3 environmentSeen(const gpu::SceneView& view, const glm::vec3& direction,
                          std::uint32_t bounce, float previousBsdfPdf, float lightSamples) {
    glm::vec3 unit = glm::normalize(direction);
    glm::vec3 radiance = gpu::environmentRadianceAlong(unit, view);
    if (bounce == 0 || radiance == glm::vec3(0.0f)) return radiance;
    float pdfLight = gpu::environmentLightPdf(unit, view);
    return radiance * gpu::emissionMisWeight(previousBsdfPdf, lightSamples, pdfLight);
}

} // namespace

void recordFirstHit(const IntegratorContext& context, const gpu::SurfacePoint& surface, float t,
                    const CameraRay& ray, gpu::SampleFeatures* firstHit) {
    if (firstHit)
        *firstHit = gpu::surfaceFeatures(surface.shading.baseColor, surface.shadingNormal, t,
                                         ray.direction, context.camera.forward);
}

glm::vec3 integratePath(IntegratorContext& context, const SampleKey& key, const CameraRay& ray,
                        gpu::SampleFeatures* firstHit) {
    const RenderSettings& settings = context.settings;
    const PreparedScene& scene = context.tracer.scene();
    const gpu::SceneView& view = context.tracer.view();
    const auto filter = std::uint32_t(settings.pathFilter);
    const float lightSamples = float(settings.lightSamples);
    glm::vec3 radiance(0.0f);
    glm::vec3 throughput(1.0f);
    glm::vec3 origin = ray.origin;
    glm::vec3 direction = ray.direction;
    float previousBsdfPdf = 0.0f;
    const bool volumes = gpu::sceneHasTransmission(view);
    glm::vec3 medium(0.0f); // σ of the medium the ray travels in; 0 outside every volume
    float wavelength = VKPT_NO_WAVELENGTH; // nm, once the path meets dispersive glass
    for (std::uint32_t bounce = 0;; ++bounce) {
        RayKind kind = bounce == 0 ? RayKind::Camera : RayKind::Extension;
        ClosestHit hit = context.tracer.closest(origin, direction, kind);
        if (!hit.hit) {
            if (volumes) throughput *= gpu::beerLambertTransmittance(medium, VKPT_FAR);
            if (scene.features.environment && gpu::pathFilterKeeps(filter, bounce))
                radiance += throughput *
                            environmentSeen(view, direction, bounce, previousBsdfPdf, lightSamples);
            break;
        }
        if (volumes)
            throughput *=
                gpu::beerLambertTransmittance(medium, gpu::segmentLength(direction, hit.t));
        gpu::SurfacePoint surface = context.tracer.surfaceAt(hit, origin, direction);
        if (bounce == 0) recordFirstHit(context, surface, hit.t, ray, firstHit);
        glm::vec3 emitted = gpu::emittedRadiance(surface);
        if (emitted != glm::vec3(0.0f) && gpu::pathFilterKeeps(filter, bounce)) {
            float weight = 1.0f;
            if (bounce > 0) {
                float pdfLight = gpu::lightPdf(surface, origin, view);
                weight = gpu::emissionMisWeight(previousBsdfPdf, lightSamples, pdfLight);
            }
            radiance += throughput * emitted * weight;
        }
        if (bounce >= settings.maxDepth) break;
        if (scene.features.dispersion)
            wavelength = gpu::bindWavelength(surface.shading, throughput, wavelength,
                                             sampleFloats(key, 0, DIM_CAMERA).z);
        PathVertex vertex{surface, bounce, medium, volumes};
        if (gpu::pathFilterKeeps(filter, bounce + 1))
            radiance += throughput * estimateDirectWithMis(context, key, vertex);
        ScatterSample scatter = sampleScatter(key, vertex);
        if (!scatter.bsdf.valid || !(scatter.bsdf.pdf > 0.0f) ||
            !gpu::continuesOnItsSide(scatter.bsdf, scatter.direction, surface.geometricNormal))
            break;
        throughput *= scatter.bsdf.weight;
        float survival =
            gpu::russianRouletteSurvival(throughput, bounce + 1, settings.rrStartDepth);
        if (scatter.russianRoulette >= survival) break;
        throughput /= survival;
        previousBsdfPdf = gpu::misPdfOfBsdfSample(scatter.bsdf, surface.shading);
        origin = gpu::offsetFromSurface(
            surface.position, gpu::continuationNormal(scatter.bsdf, surface.geometricNormal),
            surface.coordinateScale);
        direction = scatter.direction;
        if (volumes && gpu::bsdfSampleTransmits(scatter.bsdf))
            medium = gpu::mediumAfterTransmission(medium, surface, view);
    }
    return radiance;
}

glm::vec3 integrateNormals(IntegratorContext& context, const CameraRay& ray,
                           gpu::SampleFeatures* firstHit) {
    ClosestHit hit = context.tracer.closest(ray.origin, ray.direction, RayKind::Camera);
    if (!hit.hit) return glm::vec3(0.0f);
    gpu::SurfacePoint surface = context.tracer.surfaceAt(hit, ray.origin, ray.direction);
    recordFirstHit(context, surface, hit.t, ray, firstHit);
    return 0.5f * surface.rawShadingNormal + 0.5f;
}

glm::vec3 integrate(IntegratorContext& context, const SampleKey& key, const CameraRay& ray,
                    gpu::SampleFeatures* firstHit) {
    switch (context.settings.integrator) {
    case Integrator::Path:
        return integratePath(context, key, ray, firstHit);
    case Integrator::Direct:
        return integrateDirect(context, key, ray, firstHit);
    case Integrator::Normals:
        return integrateNormals(context, ray, firstHit);
    }
    return glm::vec3(0.0f);
}

} // namespace vkpt
