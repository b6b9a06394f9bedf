// direct_integrator.cpp — CS184's direct lighting: hemisphere sampling or light sampling.
#include "reference/integrators.h"

#include "reference/direct_lighting.h"
#include "shared/materials.h"
#include "shared/path_rules.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"
#include "shared/scene_environment.h"
#include "shared/surface.h"

namespace vkpt {

namespace {

// Σ f·Le·cos / p over N uniform directions: a direction counts when it reaches an emitter.
// `scale` is the path's wavelength weight (1 without one).
glm::vec3 directByHemisphere(IntegratorContext& context, const SampleKey& key,
                             const gpu::SurfacePoint& s, glm::vec3 scale) {
    gpu::Basis basis = gpu::makeBasis(s.shadingNormal);
    glm::vec3 origin = gpu::offsetFromSurface(s.position, s.geometricNormal, s.coordinateScale);
    glm::vec3 sum(0.0f);
    for (std::uint32_t i = 0; i < context.settings.lightSamples; ++i) {
        glm::vec4 u = gpu::lightSampleOrder(sampleFloats(key, 0, DIM_LIGHT_FIRST + i));
        glm::vec3 local = gpu::sampleUniformHemisphere(glm::vec2(u.y, u.z));
        glm::vec3 direction = gpu::basisToWorld(basis, local);
        if (glm::dot(direction, s.geometricNormal) <= 0.0f) continue;
        glm::vec3 f = gpu::evaluateSurfaceBsdf(s, direction).f * scale;
        ClosestHit hit = context.tracer.closest(origin, direction, RayKind::Extension);
        // Emission reached, or the environment when the probe leaves the scene; punctual
        // lights cannot be hit, so this estimator does not see them.
        const gpu::SceneView& view = context.tracer.view();
        glm::vec3 found =
            hit.hit
                ? gpu::emissionTowards(hit.triangle, gpu::TriangleHit{hit.t, hit.u, hit.v, true},
                                       origin, direction, view)
                : gpu::environmentRadianceAlong(direction, view);
        sum += f * found * (local.z / gpu::uniformHemispherePdf());
    }
    return sum / float(context.settings.lightSamples);
}

// Σ f·Le·cos / p over N points chosen on the emitters by power; `scale` as above.
glm::vec3 directByLights(IntegratorContext& context, const SampleKey& key,
                         const gpu::SurfacePoint& s, glm::vec3 scale) {
    glm::vec3 sum(0.0f);
    for (std::uint32_t i = 0; i < context.settings.lightSamples; ++i) {
        glm::vec4 u = gpu::lightSampleOrder(sampleFloats(key, 0, DIM_LIGHT_FIRST + i));
        DirectLightSample d = sampleDirectLight(context.tracer, s, u);
        if (d.contributes) sum += (d.unweighted / d.lightPdf) * scale;
    }
    return sum / float(context.settings.lightSamples);
}

} // namespace

glm::vec3 integrateDirect(IntegratorContext& context, const SampleKey& key, const CameraRay& ray,
                          gpu::SampleFeatures* firstHit) {
    const auto filter = std::uint32_t(context.settings.pathFilter);
    ClosestHit hit = context.tracer.closest(ray.origin, ray.direction, RayKind::Camera);
    if (!hit.hit) {
        if (!gpu::pathFilterKeeps(filter, 0)) return glm::vec3(0.0f);
        return gpu::environmentRadianceAlong(glm::normalize(ray.direction), context.tracer.view());
    }
    gpu::SurfacePoint surface = context.tracer.surfaceAt(hit, ray.origin, ray.direction);
    recordFirstHit(context, surface, hit.t, ray, firstHit);
    glm::vec3 radiance(0.0f);
    if (gpu::pathFilterKeeps(filter, 0)) radiance += gpu::emittedRadiance(surface);
    if (context.settings.maxDepth == 0 || context.settings.lightSamples == 0 ||
        !gpu::pathFilterKeeps(filter, 1))
        return radiance;
    // Dispersive glass is lit at the path's wavelength, as the path integrator lights it
    // (docs/integrator.md, "Dispersion"); shade_hits.comp's shadeDirect takes the same λ.
    glm::vec3 scale(1.0f);
    if (context.tracer.scene().features.dispersion)
        gpu::bindWavelength(surface.shading, scale, VKPT_NO_WAVELENGTH,
                            sampleFloats(key, 0, DIM_CAMERA).z);
    if (context.settings.lightSampling == LightSampling::Hemisphere)
        return radiance + directByHemisphere(context, key, surface, scale);
    return radiance + directByLights(context, key, surface, scale);
}

} // namespace vkpt
