// gltf_lights.cpp — validates a KHR_lights_punctual light (tinygltf parses the document-level
// array into Model::lights but checks none of its values) and places it by its node.
#include "scene/gltf_lights.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "scene/gltf_document.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kLightsPunctual = "KHR_lights_punctual";

std::string lightName(std::size_t index) {
    return "light " + std::to_string(index);
}

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", value);
    return text;
}

LightKind kindOf(const tinygltf::Light& light, std::size_t index) {
    if (light.type == "point") return LightKind::Point;
    if (light.type == "spot") return LightKind::Spot;
    if (light.type == "directional") return LightKind::Directional;
    throw GltfProblem(lightName(index) + ": type '" + light.type +
                      "' is not point, spot or directional");
}

// colour × intensity, both checked: a negative or infinite light would make radiance negative
// or infinite in every pixel it reaches.
glm::vec3 intensityOf(const tinygltf::Light& light, std::size_t index) {
    const std::string name = lightName(index);
    glm::dvec3 color(1.0); // the extension's default: white
    if (!light.color.empty()) {
        if (light.color.size() != 3) throw GltfProblem(name + ": color must have 3 numbers");
        color = glm::dvec3(light.color[0], light.color[1], light.color[2]);
    }
    if (!std::isfinite(color.x + color.y + color.z) || glm::any(glm::lessThan(color, {}))) {
        throw GltfProblem(name + ": color must be finite and not negative");
    }
    if (!std::isfinite(light.intensity)) throw GltfProblem(name + ": intensity is not finite");
    if (light.intensity < 0.0) throw GltfProblem(name + ": intensity must not be negative");
    return glm::vec3(color * light.intensity);
}

// The extension requires 0 <= innerConeAngle < outerConeAngle <= π/2. Equal angles (a hard-edged
// cone) are accepted all the same: Blender writes them for a spot without blend.
void readCone(const tinygltf::SpotLight& spot, std::size_t index, SceneLight& light) {
    const std::string name = lightName(index) + ": spot ";
    const double inner = spot.innerConeAngle;
    const double outer = spot.outerConeAngle;
    if (!(outer > 0.0 && outer <= std::numbers::pi / 2.0)) {
        throw GltfProblem(name + "outerConeAngle " + formatNumber(outer) + " is not in (0, pi/2]");
    }
    if (!(inner >= 0.0)) {
        throw GltfProblem(name + "innerConeAngle " + formatNumber(inner) + " is negative");
    }
    if (inner > outer) {
        throw GltfProblem(name + "innerConeAngle " + formatNumber(inner) +
                          " exceeds outerConeAngle " + formatNumber(outer));
    }
    light.innerConeAngle = static_cast<float>(inner);
    light.outerConeAngle = static_cast<float>(outer);
}

SceneLight convertLight(const tinygltf::Light& gltfLight, std::size_t index) {
    SceneLight light;
    light.name = gltfLight.name;
    light.kind = kindOf(gltfLight, index);
    light.intensity = intensityOf(gltfLight, index);
    // tinygltf reads a missing range as 0, which SceneLight takes for "unlimited" too.
    if (!(gltfLight.range >= 0.0) || !std::isfinite(gltfLight.range)) {
        throw GltfProblem(lightName(index) + ": range must be finite and not negative");
    }
    light.range = static_cast<float>(gltfLight.range);
    if (light.kind == LightKind::Spot) readCone(gltfLight.spot, index, light);
    return light;
}

// The node's −Z axis in world space, the way the light shines. Scale does not change a light
// (the extension), so only the direction is kept.
glm::vec3 worldDirection(const glm::dmat4& world, int nodeIndex) {
    const glm::dvec3 axis = -glm::dvec3(world[2]);
    const double length = glm::length(axis);
    if (!(length > 0.0) || !std::isfinite(length)) {
        throw GltfProblem("node " + std::to_string(nodeIndex) +
                          ": the light's transform is degenerate (no -Z direction)");
    }
    return glm::vec3(axis / length);
}

} // namespace

std::optional<SceneLight> placeLight(const tinygltf::Model& model, int nodeIndex,
                                     const glm::dmat4& world) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(nodeIndex)];
    const tinygltf::Value* extension = findExtension(node.extensions, kLightsPunctual);
    if (extension == nullptr) return std::nullopt;
    const std::string where = "node " + std::to_string(nodeIndex) + ": " + kLightsPunctual;
    const int index = readIndex(*extension, "light", where);
    if (index < 0) throw GltfProblem(where + ": no light index");
    if (static_cast<std::size_t>(index) >= model.lights.size()) {
        throw GltfProblem(where + ": light " + std::to_string(index) +
                          " does not exist (the file has " + std::to_string(model.lights.size()) +
                          " lights)");
    }
    SceneLight light = convertLight(model.lights[static_cast<std::size_t>(index)],
                                    static_cast<std::size_t>(index));
    const glm::dvec3 position(world[3]);
    if (!std::isfinite(position.x + position.y + position.z)) {
        throw GltfProblem("node " + std::to_string(nodeIndex) +
                          ": the light's position is not finite");
    }
    light.position = glm::vec3(position);
    if (light.kind != LightKind::Point) light.direction = worldDirection(world, nodeIndex);
    return light;
}

} // namespace vkpt::gltf
