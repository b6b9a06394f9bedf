// direct_lighting.cpp — light sample, visibility test and the Lambertian BSDF at one point.
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
    // Both ends move off their surfaces, so the shadow ray can hit neither of them.
    glm::vec3 origin =
        gpu::offsetFromSurface(surface.position, surface.geometricNormal, surface.coordinateScale);
    glm::vec3 target =
        gpu::offsetFromSurface(light.position, light.towardsReceiver, light.coordinateScale);
    if (tracer.occluded(origin, target - origin)) return result;
    result.unweighted = lambertAlbedo(surface) * VKPT_INV_PI * light.radiance * cosSurface;
    result.lightPdf = light.pdfSolidAngle;
    result.bsdfPdf = gpu::cosineHemispherePdf(cosSurface);
    result.contributes = true;
    return result;
}

} // namespace vkpt
