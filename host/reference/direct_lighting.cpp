// direct_lighting.cpp — a light connection and its visibility test.
#include "reference/direct_lighting.h"

#include "shared/light_connection.h"
#include "shared/volume.h"

namespace vkpt {

DirectLightSample sampleDirectLight(SceneTracer& tracer, const gpu::SurfacePoint& surface,
                                    const glm::vec4& u) {
    DirectLightSample result;
    const gpu::LightConnection c = gpu::connectLightSample(surface, u, tracer.view());
    if (!c.valid || tracer.occluded(c.origin, c.direction, c.tMax)) return result;
    result.unweighted = c.contribution;
    result.lightPdf = c.lightPdf;
    result.bsdfPdf = c.bsdfPdf;
    result.distance = gpu::segmentLength(c.direction, c.tMax);
    result.contributes = true;
    return result;
}

} // namespace vkpt
