// emitters.cpp — builds the power-proportional emitter list and samples it by its CDF.
#include "prepare/emitters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>

#include "common/math_constants.h"
#include "prepare/emission_mean.h"
#include "shared/intersect.h"
#include "shared/sampling.h"

namespace vkpt {

float triangleArea(const gpu::Triangle& triangle) {
    return gpu::triangleAreaOf(triangle.v0, triangle.v1, triangle.v2);
}

namespace {

double sides(const gpu::Material& material) {
    return (material.flags & MATERIAL_DOUBLE_SIDED) != 0 ? 2.0 : 1.0;
}

double luminanceOf(const glm::vec3& c) {
    return double(gpu::luminance(c));
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

gpu::Emitter surfaceEmitter(std::uint32_t kind, std::uint32_t primitive, float area) {
    gpu::Emitter e{};
    e.kind = kind;
    e.primitive = primitive;
    e.area = area;
    return e;
}

gpu::Emitter punctualEmitter(const SceneLight& light) {
    gpu::Emitter e{};
    e.kind = light.kind == LightKind::Point  ? EMITTER_POINT
             : light.kind == LightKind::Spot ? EMITTER_SPOT
                                             : EMITTER_DIRECTIONAL;
    e.position = light.position;
    e.direction = light.direction;
    e.primitive = NO_EMITTER;
    e.intensity = light.intensity;
    e.range = light.range;
    e.cosInnerCone = std::cos(light.innerConeAngle);
    e.cosOuterCone = std::cos(light.outerConeAngle);
    return e;
}

double punctualPower(const SceneLight& light, double sceneRadius) {
    const double intensity = luminanceOf(light.intensity);
    switch (light.kind) {
    case LightKind::Point:
        return 4.0 * kPi * intensity;
    case LightKind::Spot: {
        double meanCos = 0.5 * (std::cos(light.innerConeAngle) + std::cos(light.outerConeAngle));
        return 2.0 * kPi * (1.0 - meanCos) * intensity;
    }
    case LightKind::Directional:
        return kPi * sceneRadius * sceneRadius * intensity;
    }
    return 0.0;
}

class ListBuilder {
public:
    void add(const gpu::Emitter& emitter, double power) {
        list_.emitters.push_back(emitter);
        list_.powers.push_back(power);
        list_.totalPower += power;
    }
    std::uint32_t size() const { return std::uint32_t(list_.emitters.size()); }

    EmitterList finish() {
        double running = 0.0;
        list_.cdf.resize(list_.emitters.size());
        // Emitters all of power 0 (black textures) are never chosen: probabilities 0.
        const double total = list_.totalPower > 0.0 ? list_.totalPower : 1.0;
        for (std::size_t i = 0; i < list_.emitters.size(); ++i) {
            running += list_.powers[i];
            list_.emitters[i].selectProbability = float(list_.powers[i] / total);
            list_.cdf[i] = float(running / total);
        }
        // Rounding must not leave u close to 1 without an emitter.
        if (!list_.cdf.empty()) list_.cdf.back() = 1.0f;
        return std::move(list_);
    }

private:
    EmitterList list_;
};

// The emitting primitives in the loaded scene's order (its triangles, then its spheres) rather
// than the BVH's: the list, and so which emitter a random number selects, does not depend on how
// the BVH was built or laid out (a two-level scene's emitters sit in its own geometry's
// bottom level, in that level's BVH order).
std::vector<std::uint32_t>
emittingPrimitivesInSceneOrder(std::span<const gpu::Triangle> primitives,
                               std::span<const gpu::Material> materials) {
    std::vector<std::uint32_t> emitting;
    for (std::uint32_t i = 0; i < primitives.size(); ++i)
        if (luminanceOf(materials[primitives[i].materialIndex].emission) > 0.0)
            emitting.push_back(i);
    const auto sceneOrder = [&](std::uint32_t i) {
        const gpu::Triangle& p = primitives[i];
        return std::pair(gpu::isSpherePrimitive(p), p.sourceIndex & PRIMITIVE_SOURCE_MASK);
    };
    std::sort(emitting.begin(), emitting.end(),
              [&](std::uint32_t a, std::uint32_t b) { return sceneOrder(a) < sceneOrder(b); });
    return emitting;
}

} // namespace

EmitterList buildEmitters(const Scene& scene, std::span<gpu::Triangle> primitives,
                          std::span<const gpu::Material> materials, const EmitterSources& sources) {
    ListBuilder builder;
    std::map<SurfaceKey, std::uint32_t> surfaces;
    for (gpu::Triangle& primitive : primitives)
        primitive.emitterIndex = NO_EMITTER;
    for (std::uint32_t i : emittingPrimitivesInSceneOrder(primitives, materials)) {
        gpu::Triangle& primitive = primitives[i];
        const gpu::Material& material = materials[primitive.materialIndex];
        if (gpu::isSpherePrimitive(primitive)) {
            const double radiance = luminanceOf(material.emission);
            const double radius = primitive.v1.x;
            const double area = 4.0 * kPi * radius * radius;
            if (!(area > 0.0)) continue;
            primitive.emitterIndex = builder.size();
            builder.add(surfaceEmitter(EMITTER_SPHERE, i, float(area)),
                        kPi * radiance * area * sides(material));
            continue;
        }
        const float area = triangleArea(primitive);
        if (!(area > 0.0f)) continue;
        const double radiance =
            luminanceOf(meanTriangleEmission(scene, primitive.sourceIndex & PRIMITIVE_SOURCE_MASK));
        // A repeat of an emitting triangle (same corners, winding and material) shares the
        // first copy's record: light sampling must pick the surface once, as a ray finds it
        // once, and a ray that finds either copy must see the same light pdf.
        const auto [surface, added] = surfaces.try_emplace(surfaceKey(primitive), builder.size());
        primitive.emitterIndex = surface->second;
        if (!added) continue;
        builder.add(surfaceEmitter(EMITTER_TRIANGLE, i, area),
                    kPi * radiance * double(area) * sides(material));
    }
    for (const SceneLight& light : scene.lights) {
        const double power = punctualPower(light, sources.sceneRadius);
        if (power > 0.0) builder.add(punctualEmitter(light), power);
    }
    if (sources.environmentPower > 0.0) {
        gpu::Emitter environment{};
        environment.kind = EMITTER_ENVIRONMENT;
        environment.primitive = NO_EMITTER;
        builder.add(environment, sources.environmentPower);
    }
    return builder.finish();
}

} // namespace vkpt
