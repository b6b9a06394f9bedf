// emitters.cpp — builds the power-proportional emitter list and samples it by its CDF.
#include "prepare/emitters.h"

#include <algorithm>

#include "shared/sampling.h"

namespace vkpt {

float triangleArea(const gpu::Triangle& triangle) {
    return 0.5f * glm::length(glm::cross(triangle.v1 - triangle.v0, triangle.v2 - triangle.v0));
}

namespace {

double emitterPower(const gpu::Triangle& triangle, const gpu::Material& material) {
    double sides = (material.flags & MATERIAL_DOUBLE_SIDED) != 0 ? 2.0 : 1.0;
    return double(gpu::luminance(material.emission)) * double(triangleArea(triangle)) * sides;
}

void normaliseCdf(EmitterList& list, const std::vector<double>& powers) {
    double running = 0.0;
    for (std::size_t i = 0; i < list.emitters.size(); ++i) {
        running += powers[i];
        list.emitters[i].selectProbability = float(powers[i] / list.totalPower);
        list.emitters[i].cdf = float(running / list.totalPower);
    }
    // Rounding must not leave u close to 1 without an emitter.
    if (!list.emitters.empty()) list.emitters.back().cdf = 1.0f;
}

} // namespace

EmitterList buildEmitters(std::span<gpu::Triangle> triangles,
                          std::span<const gpu::Material> materials) {
    EmitterList list;
    std::vector<double> powers;
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
        gpu::Triangle& triangle = triangles[i];
        triangle.emitterIndex = NO_EMITTER;
        double power = emitterPower(triangle, materials[triangle.materialIndex]);
        if (!(power > 0.0)) continue;
        triangle.emitterIndex = std::uint32_t(list.emitters.size());
        list.emitters.push_back({i, triangleArea(triangle), 0.0f, 0.0f});
        powers.push_back(power);
        list.totalPower += power;
    }
    if (!list.emitters.empty()) normaliseCdf(list, powers);
    return list;
}

std::uint32_t selectEmitter(std::span<const gpu::Emitter> emitters, float u) {
    auto it = std::upper_bound(emitters.begin(), emitters.end(), u,
                               [](float value, const gpu::Emitter& e) { return value < e.cdf; });
    if (it == emitters.end()) --it;
    return std::uint32_t(it - emitters.begin());
}

} // namespace vkpt
