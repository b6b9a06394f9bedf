// emitters.h — the area-light list: every emitting triangle, selected in proportion to power.
#pragma once

#include <span>
#include <vector>

#include "shared/host_device.h"

namespace vkpt {

struct EmitterList {
    std::vector<gpu::Emitter> emitters;
    double totalPower = 0.0; // Σ luminance(emission) × area × emitting sides
};

// Builds the list and writes each emitting triangle's emitterIndex (NO_EMITTER elsewhere).
// Zero-area triangles cannot be hit or sampled, so they are left out; a triangle that repeats an
// earlier emitting one (same corners in the same order, same material) shares its record.
EmitterList buildEmitters(std::span<gpu::Triangle> triangles,
                          std::span<const gpu::Material> materials);

// The emitter whose cdf interval contains u in [0, 1): the first i with u < cdf[i].
std::uint32_t selectEmitter(std::span<const gpu::Emitter> emitters, float u);

float triangleArea(const gpu::Triangle& triangle);

} // namespace vkpt
