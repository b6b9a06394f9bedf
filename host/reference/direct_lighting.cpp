// direct_lighting.cpp — light sample, visibility test and the BSDF at one point.
#include "reference/direct_lighting.h"

#include "reference/light_sampling.h"
#include "shared/ray_offset.h"
#include "shared/sampling.h"

namespace vkpt {

DirectLightSample sampleDirectLight(SceneTracer& tracer, const SurfacePoint& surface,
                                    const glm::vec4& u) {
    DirectLightSample result;
    LightSample light = sampleLight(tracer.scene(), surface.position, u);
    if (!light.valid || light.radiance == glm::vec3(0.0f)) return result;
    float cosSurface = glm::dot(light.direction, surface.shadingNormal);
    if (cosSurface <= 0.0f || glm::dot(light.direction, surface.geometricNormal) <= 0.0f)
        return result;
    BsdfValue bsdf = evaluateSurfaceBsdf(surface, light.direction);
    if (bsdf.f == glm::vec3(0.0f)) return result;
    // Both ends move off their surfaces, so the shadow ray can hit neither of them; a light at
    // infinity (directional, environment) is a ray along its direction without an end.
    glm::vec3 origin =
        gpu::offsetFromSurface(surface.position, surface.geometricNormal, surface.coordinateScale);
    bool blocked = false;
    if (light.atInfinity) {
        blocked = tracer.occluded(origin, light.direction, VKPT_FAR);
    } else {
        glm::vec3 target = light.delta
                               ? light.position
                               : gpu::offsetFromSurface(light.position, light.towardsReceiver,
                                                        light.coordinateScale);
        blocked = tracer.occluded(origin, target - origin, 1.0f);
    }
    if (blocked) return result;
    result.unweighted = bsdf.f * light.radiance * cosSurface;
    result.lightPdf = light.pdfSolidAngle;
    result.bsdfPdf = light.delta ? 0.0f : bsdf.pdf;
    result.contributes = true;
    return result;
}

} // namespace vkpt
