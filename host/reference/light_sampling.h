// light_sampling.h — next-event estimation's half of the reference: a point on an emitter
// chosen by power, and the solid-angle pdf of reaching an emitter by any direction.
#pragma once

#include "prepare/prepared_scene.h"
#include "reference/surface.h"

namespace vkpt {

struct LightSample {
    glm::vec3 position{0.0f};
    glm::vec3 towardsReceiver{0.0f}; // unit emitter normal turned towards the receiver
    glm::vec3 direction{0.0f};       // unit, receiver → light
    glm::vec3 radiance{0.0f};        // emitted towards the receiver (0 from a back face)
    float pdfSolidAngle = 0.0f;
    float coordinateScale = 0.0f;    // of the emitter triangle, for gpu::offsetFromSurface
    bool valid = false;              // false: no emitters, or the point is seen edge-on
};

// u.x selects the emitter, u.yz the point on it.
LightSample sampleLight(const PreparedScene& scene, const glm::vec3& receiver, const glm::vec4& u);

// Solid-angle pdf with which sampleLight would have produced the hit `surface` from `origin`.
float lightPdf(const PreparedScene& scene, const SurfacePoint& surface, const glm::vec3& origin);

} // namespace vkpt
