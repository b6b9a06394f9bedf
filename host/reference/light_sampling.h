// light_sampling.h — next-event estimation's half of the reference: an emitter chosen by
// power, a point or direction on it, and the solid-angle pdf of reaching an emitter (or the
// environment) by any direction.
#pragma once

#include "prepare/prepared_scene.h"
#include "reference/surface.h"

namespace vkpt {

struct LightSample {
    glm::vec3 position{0.0f};
    glm::vec3 towardsReceiver{0.0f}; // unit emitter normal turned towards the receiver
    glm::vec3 direction{0.0f};       // unit, receiver → light
    // Area and environment samples: radiance emitted towards the receiver (0 from a back face).
    // Punctual (delta) samples: the irradiance they cause on a surface facing them.
    glm::vec3 radiance{0.0f};
    float pdfSolidAngle = 0.0f;   // punctual: the selection probability alone
    float coordinateScale = 0.0f; // of the emitter primitive, for gpu::offsetFromSurface
    bool valid = false;           // false: no emitters, or the point is seen edge-on
    bool delta = false;           // a punctual light: no MIS, no BSDF sample can reach it
    bool atInfinity = false;      // directional or environment: shadow ray without an end point
};

// u.x selects the emitter, u.yz the point or direction on it.
LightSample sampleLight(const PreparedScene& scene, const glm::vec3& receiver, const glm::vec4& u);

// Solid-angle pdf with which sampleLight would have produced the hit `surface` from `origin`.
float lightPdf(const PreparedScene& scene, const SurfacePoint& surface, const glm::vec3& origin);

// Solid-angle pdf with which sampleLight would have chosen the environment along `direction`.
float environmentLightPdf(const PreparedScene& scene, const glm::vec3& direction);

// The environment's radiance along a unit direction (0 without one).
glm::vec3 environmentRadianceAlong(const PreparedScene& scene, const glm::vec3& direction);

} // namespace vkpt
