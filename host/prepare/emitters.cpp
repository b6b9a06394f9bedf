// emitters.cpp — builds the power-proportional emitter list and samples it by its CDF.
#include "prepare/emitters.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <map>

#include "shared/intersect.h"
#include "shared/sampling.h"

namespace vkpt {

float triangleArea(const gpu::Triangle& triangle) {
    return gpu::triangleAreaOf(triangle.v0, triangle.v1, triangle.v2);
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

// An emitting triangle's corners (as bits, rotated to start at the smallest corner, −0 as +0)
// and material: two triangles with the same key are one emitting surface listed twice.
using SurfaceKey = std::array<std::uint32_t, 10>;

SurfaceKey surfaceKey(const gpu::Triangle& triangle) {
    std::array<std::array<std::uint32_t, 3>, 3> corners{};
    const glm::vec3 v[3] = {triangle.v0, triangle.v1, triangle.v2};
    for (std::size_t k = 0; k < 3; ++k) {
        const glm::vec3 canonical = v[k] + glm::vec3(0.0f);
        std::memcpy(corners[k].data(), &canonical, sizeof(corners[k]));
    }
    const std::size_t first =
        std::size_t(std::min_element(corners.begin(), corners.end()) - corners.begin());
    SurfaceKey key{};
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t c = 0; c < 3; ++c)
            key[3 * k + c] = corners[(first + k) % 3][c];
    key[9] = triangle.materialIndex;
    return key;
}

} // namespace

EmitterList buildEmitters(std::span<gpu::Triangle> triangles,
                          std::span<const gpu::Material> materials) {
    EmitterList list;
    std::vector<double> powers;
    std::map<SurfaceKey, std::uint32_t> surfaces;
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
        gpu::Triangle& triangle = triangles[i];
        triangle.emitterIndex = NO_EMITTER;
        double power = emitterPower(triangle, materials[triangle.materialIndex]);
        if (!(power > 0.0)) continue;
        // A repeat of an emitting triangle (same corners, winding and material) shares the
        // first copy's record: light sampling must pick the surface once, as a ray finds it
        // once, and a ray that finds either copy must see the same light pdf.
        const auto [surface, added] =
            surfaces.try_emplace(surfaceKey(triangle), std::uint32_t(list.emitters.size()));
        triangle.emitterIndex = surface->second;
        if (!added) continue;
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
