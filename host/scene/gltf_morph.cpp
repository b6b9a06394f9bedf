// gltf_morph.cpp — reads each morph target's displacement accessors and adds them, weighted, to
// the vertices. Displacements of NORMAL and TANGENT are added before renormalising, as the glTF
// 2.0 specification (section 3.7.2.2) prescribes; tangents keep their w.
#include "scene/gltf_morph.h"

#include <algorithm>
#include <cmath>

#include "scene/gltf_accessors.h"
#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

std::string targetPlace(const std::string& where, std::size_t target, const char* attribute) {
    return where + ": morph target " + std::to_string(target) + " " + attribute;
}

// Adds weight × the target's `attribute` displacements to the first three components of
// `values`; nothing when the target does not displace that attribute.
template <typename Vector>
void addDisplacements(const tinygltf::Model& model, const std::map<std::string, int>& target,
                      const char* attribute, double weight, std::vector<Vector>& values,
                      std::size_t targetIndex, const std::string& where) {
    const auto accessor = target.find(attribute);
    if (accessor == target.end()) return;
    const std::string place = targetPlace(where, targetIndex, attribute);
    const std::vector<glm::vec3> displacements = readPositions(model, accessor->second, place);
    if (displacements.size() != values.size()) {
        throw GltfProblem(place + " has " + std::to_string(displacements.size()) +
                          " elements but POSITION has " + std::to_string(values.size()));
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        const glm::dvec3 moved =
            glm::dvec3(glm::vec3(values[i])) + weight * glm::dvec3(displacements[i]);
        for (int c = 0; c < 3; ++c)
            values[i][c] = static_cast<float>(moved[c]);
    }
}

void checkWeights(const std::vector<double>& weights, std::size_t targets,
                  const std::string& where) {
    if (weights.size() != targets) {
        throw GltfProblem(where + ": " + std::to_string(weights.size()) + " morph weights for " +
                          std::to_string(targets) + " morph targets");
    }
    for (double weight : weights) {
        if (!std::isfinite(weight)) throw GltfProblem(where + ": a morph weight is not finite");
    }
}

} // namespace

std::vector<double> morphWeights(const tinygltf::Model& model, int nodeIndex,
                                 const ScenePose* pose) {
    const auto index = static_cast<std::size_t>(nodeIndex);
    if (pose != nullptr && index < pose->weights.size() && pose->weights[index])
        return *pose->weights[index];
    const tinygltf::Node& node = model.nodes[index];
    if (!node.weights.empty()) return node.weights;
    if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= model.meshes.size()) return {};
    return model.meshes[static_cast<std::size_t>(node.mesh)].weights;
}

std::vector<WeightRange> morphWeightRanges(const tinygltf::Model& model, int nodeIndex,
                                           const std::vector<Animation>& animations) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(nodeIndex)];
    if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= model.meshes.size()) return {};
    std::size_t targets = 0;
    for (const tinygltf::Primitive& primitive :
         model.meshes[static_cast<std::size_t>(node.mesh)].primitives)
        targets = std::max(targets, primitive.targets.size());
    std::vector<WeightRange> ranges(targets);
    const std::vector<double> rest = morphWeights(model, nodeIndex, nullptr);
    for (std::size_t t = 0; t < targets && t < rest.size(); ++t)
        if (std::isfinite(rest[t])) ranges[t] = {rest[t], rest[t]};
    auto include = [&](std::size_t t, double weight) {
        if (t >= targets || !std::isfinite(weight)) return;
        ranges[t].low = std::min(ranges[t].low, weight);
        ranges[t].high = std::max(ranges[t].high, weight);
    };
    for (const Animation& animation : animations) {
        for (const AnimationChannel& channel : animation.channels) {
            if (channel.node != nodeIndex || channel.path != AnimatedPath::Weights) continue;
            const KeyframeTrack& track = channel.track;
            const std::size_t width = track.width;
            if (width == 0) continue;
            if (track.interpolation != Interpolation::CubicSpline) {
                for (std::size_t i = 0; i < track.values.size(); ++i)
                    include(i % width, track.values[i]);
                continue;
            }
            // Per keyframe: in-tangents, values, out-tangents, `width` each.
            const auto at = [&](std::size_t k, std::size_t part, std::size_t t) {
                return track.values[(3 * k + part) * width + t];
            };
            for (std::size_t k = 0; k < track.times.size(); ++k) {
                for (std::size_t t = 0; t < width; ++t) {
                    include(t, at(k, 1, t));
                    if (k + 1 == track.times.size()) continue;
                    const double dt = track.times[k + 1] - track.times[k];
                    include(t, at(k, 1, t) + dt * at(k, 2, t) / 3.0);
                    include(t, at(k + 1, 1, t) - dt * at(k + 1, 0, t) / 3.0);
                }
            }
        }
    }
    return ranges;
}

void applyMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                       const std::vector<double>& weights, MorphableVertices vertices,
                       const std::string& where) {
    if (weights.empty() || primitive.targets.empty()) return;
    checkWeights(weights, primitive.targets.size(), where);
    for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
        if (weights[t] == 0.0) continue;
        const std::map<std::string, int>& target = primitive.targets[t];
        addDisplacements(model, target, "POSITION", weights[t], vertices.positions, t, where);
        if (vertices.normals != nullptr)
            addDisplacements(model, target, "NORMAL", weights[t], *vertices.normals, t, where);
        if (vertices.tangents != nullptr)
            addDisplacements(model, target, "TANGENT", weights[t], *vertices.tangents, t, where);
    }
}

} // namespace vkpt::gltf
