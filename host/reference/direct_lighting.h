// direct_lighting.h — one shadow-tested light sample at a surface point, the building block
// of both the path integrator's NEE and CS184's light-sampling direct integrator: the shared
// light connection (shaders/shared/light_connection.h), traced at once.
#pragma once

#include "reference/scene_tracer.h"
#include "shared/surface.h"

namespace vkpt {

struct DirectLightSample {
    glm::vec3 unweighted{0.0f}; // f·Le·cos θ (punctual: f·E·cos θ), before division by the pdf
    float lightPdf = 0.0f;      // solid angle; for a punctual light its selection probability
    float bsdfPdf = 0.0f;       // of the BSDF sampler in the same direction; 0 for punctual
    float distance = 0.0f;      // length of the shadow ray; VKPT_FAR to a light at infinity
    bool contributes = false;   // false: no emitter, back face, below the surface or shadowed
};

// u.x picks the emitter, u.yz the point on it (see shared/rng.h, DIM_LIGHT_FIRST).
DirectLightSample sampleDirectLight(SceneTracer& tracer, const gpu::SurfacePoint& surface,
                                    const glm::vec4& u);

} // namespace vkpt
