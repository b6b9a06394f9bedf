// gltf_animation.cpp — reads animation samplers into keyframe tracks with every index, type and
// count checked, samples them (glTF 2.0, Appendix C) and poses the node tree.
#include "scene/gltf_animation.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "scene/gltf_accessors.h"
#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

std::string channelPlace(std::size_t animation, std::size_t channel) {
    return "animation " + std::to_string(animation) + ", channel " + std::to_string(channel);
}

std::string samplerPlace(std::size_t animation, int sampler) {
    return "animation " + std::to_string(animation) + ", sampler " + std::to_string(sampler);
}

Interpolation interpolationOf(const std::string& name, const std::string& where) {
    if (name == "LINEAR" || name.empty()) return Interpolation::Linear;
    if (name == "STEP") return Interpolation::Step;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    throw GltfProblem(where + ": interpolation '" + name +
                      "' is not one of LINEAR, STEP, CUBICSPLINE");
}

std::optional<AnimatedPath> pathOf(const std::string& name) {
    if (name == "translation") return AnimatedPath::Translation;
    if (name == "rotation") return AnimatedPath::Rotation;
    if (name == "scale") return AnimatedPath::Scale;
    if (name == "weights") return AnimatedPath::Weights;
    return std::nullopt;
}

// The number of morph targets of the node's mesh, which a weights channel must animate.
std::size_t morphTargetCount(const tinygltf::Model& model, int nodeIndex) {
    const int mesh = model.nodes[static_cast<std::size_t>(nodeIndex)].mesh;
    if (mesh < 0 || static_cast<std::size_t>(mesh) >= model.meshes.size()) return 0;
    const auto& primitives = model.meshes[static_cast<std::size_t>(mesh)].primitives;
    return primitives.empty() ? 0 : primitives[0].targets.size();
}

std::vector<double> readTimes(const tinygltf::Model& model, int accessor,
                              const std::string& where) {
    const std::vector<float> raw =
        readFloatComponents(model, accessor, TINYGLTF_TYPE_SCALAR, false, where + ": input");
    if (raw.empty()) throw GltfProblem(where + ": input has no keyframes");
    std::vector<double> times(raw.begin(), raw.end());
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (!std::isfinite(times[k])) {
            throw GltfProblem(where + ": input time " + std::to_string(k) + " is not finite");
        }
        if (k > 0 && !(times[k] > times[k - 1])) {
            throw GltfProblem(where + ": input times do not increase at keyframe " +
                              std::to_string(k));
        }
    }
    return times;
}

std::vector<double> readOutputs(const tinygltf::Model& model, int accessor, AnimatedPath path,
                                const std::string& where) {
    const int type = path == AnimatedPath::Rotation  ? TINYGLTF_TYPE_VEC4
                     : path == AnimatedPath::Weights ? TINYGLTF_TYPE_SCALAR
                                                     : TINYGLTF_TYPE_VEC3;
    // Rotations and weights may be stored as normalized integers; translations and scales not.
    const bool normalized = path == AnimatedPath::Rotation || path == AnimatedPath::Weights;
    const std::vector<float> raw =
        readFloatComponents(model, accessor, type, normalized, where + ": output");
    std::vector<double> values(raw.begin(), raw.end());
    for (double value : values) {
        if (!std::isfinite(value)) throw GltfProblem(where + ": an output value is not finite");
    }
    return values;
}

KeyframeTrack readTrack(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler,
                        AnimatedPath path, std::size_t width, const std::string& where) {
    KeyframeTrack track;
    track.interpolation = interpolationOf(sampler.interpolation, where);
    track.width = width;
    track.times = readTimes(model, sampler.input, where);
    track.values = readOutputs(model, sampler.output, path, where);
    const std::size_t perKeyframe =
        width * (track.interpolation == Interpolation::CubicSpline ? 3 : 1);
    if (track.values.size() != track.times.size() * perKeyframe) {
        throw GltfProblem(where + ": output has " + std::to_string(track.values.size()) +
                          " numbers, " + std::to_string(track.times.size()) + " keyframes need " +
                          std::to_string(track.times.size() * perKeyframe));
    }
    return track;
}

AnimationChannel readChannel(const tinygltf::Model& model, const tinygltf::Animation& animation,
                             std::size_t animationIndex, std::size_t channelIndex) {
    const tinygltf::AnimationChannel& source = animation.channels[channelIndex];
    const std::string where = channelPlace(animationIndex, channelIndex);
    if (source.target_node < 0 ||
        static_cast<std::size_t>(source.target_node) >= model.nodes.size()) {
        throw GltfProblem(where + ": node " + std::to_string(source.target_node) +
                          " does not exist (the file has " + std::to_string(model.nodes.size()) +
                          " nodes)");
    }
    const std::optional<AnimatedPath> path = pathOf(source.target_path);
    if (!path) {
        throw GltfProblem(where + ": path '" + source.target_path +
                          "' is not one of translation, rotation, scale, weights");
    }
    if (source.sampler < 0 ||
        static_cast<std::size_t>(source.sampler) >= animation.samplers.size()) {
        throw GltfProblem(where + ": sampler " + std::to_string(source.sampler) +
                          " does not exist (the animation has " +
                          std::to_string(animation.samplers.size()) + " samplers)");
    }
    AnimationChannel channel;
    channel.node = source.target_node;
    channel.path = *path;
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(channel.node)];
    if (*path != AnimatedPath::Weights && !node.matrix.empty()) {
        throw GltfProblem(where + ": node " + std::to_string(channel.node) +
                          " has a matrix, which animations may not target (only TRS)");
    }
    std::size_t width = *path == AnimatedPath::Rotation ? 4 : 3;
    if (*path == AnimatedPath::Weights) {
        width = morphTargetCount(model, channel.node);
        if (width == 0) {
            throw GltfProblem(where + ": node " + std::to_string(channel.node) +
                              " has no mesh with morph targets for its weights");
        }
    }
    channel.track = readTrack(model, animation.samplers[static_cast<std::size_t>(source.sampler)],
                              *path, width, samplerPlace(animationIndex, source.sampler));
    return channel;
}

// Appendix C's slerp: along the shorter arc, linear where the quaternions (nearly) coincide.
std::vector<double> slerp(const double* a, const double* b, double u) {
    double dot = 0.0;
    for (int i = 0; i < 4; ++i)
        dot += a[i] * b[i];
    const double sign = dot < 0.0 ? -1.0 : 1.0;
    dot = std::abs(dot);
    double wa = 1.0 - u;
    double wb = u;
    if (dot < 1.0 - 1e-9) {
        const double angle = std::acos(dot);
        wa = std::sin((1.0 - u) * angle) / std::sin(angle);
        wb = std::sin(u * angle) / std::sin(angle);
    }
    std::vector<double> q(4);
    for (int i = 0; i < 4; ++i)
        q[std::size_t(i)] = wa * a[i] + sign * wb * b[i];
    return q;
}

void normalise(std::vector<double>& q) {
    double length = 0.0;
    for (double c : q)
        length += c * c;
    length = std::sqrt(length);
    if (!(length > 0.0)) {
        q = {0.0, 0.0, 0.0, 1.0}; // a zero quaternion (opposite keys met halfway): no rotation
        return;
    }
    for (double& c : q)
        c /= length;
}

// Appendix C's cubic Hermite spline between keyframes k and k + 1: the value v, the out-tangent
// b of k and the in-tangent a of k + 1, tangents scaled by the keyframe interval.
std::vector<double> cubicSpline(const KeyframeTrack& track, std::size_t k, double u) {
    const std::size_t w = track.width;
    const double* first = track.values.data() + 3 * w * k;
    const double* second = first + 3 * w;
    const double interval = track.times[k + 1] - track.times[k];
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u;
    const double h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    std::vector<double> value(w);
    for (std::size_t i = 0; i < w; ++i) {
        value[i] = h00 * first[w + i] + h10 * interval * first[2 * w + i] + h01 * second[w + i] +
                   h11 * interval * second[i];
    }
    return value;
}

std::vector<double> keyframeValue(const KeyframeTrack& track, std::size_t k) {
    const std::size_t w = track.width;
    const std::size_t stride = track.interpolation == Interpolation::CubicSpline ? 3 * w : w;
    const std::size_t offset = track.interpolation == Interpolation::CubicSpline ? w : 0;
    const auto first = track.values.begin() + static_cast<std::ptrdiff_t>(k * stride + offset);
    return std::vector<double>(first, first + static_cast<std::ptrdiff_t>(w));
}

std::vector<double> interpolate(const KeyframeTrack& track, double time, bool quaternion) {
    const std::size_t last = track.times.size() - 1;
    if (last == 0 || time <= track.times.front()) return keyframeValue(track, 0);
    if (time >= track.times.back()) return keyframeValue(track, last);
    // times[k] <= time < times[k + 1]
    const std::size_t k = static_cast<std::size_t>(
        std::upper_bound(track.times.begin(), track.times.end(), time) - track.times.begin() - 1);
    const double u = (time - track.times[k]) / (track.times[k + 1] - track.times[k]);
    switch (track.interpolation) {
    case Interpolation::Step:
        return keyframeValue(track, k);
    case Interpolation::CubicSpline:
        return cubicSpline(track, k, u);
    case Interpolation::Linear:
        break;
    }
    const std::vector<double> a = keyframeValue(track, k);
    const std::vector<double> b = keyframeValue(track, k + 1);
    if (quaternion) return slerp(a.data(), b.data(), u);
    std::vector<double> value(track.width);
    for (std::size_t i = 0; i < track.width; ++i)
        value[i] = (1.0 - u) * a[i] + u * b[i];
    return value;
}

// `trs` is set unless the channel animates weights.
void applyChannel(const AnimationChannel& channel, double time, std::optional<NodeTrs>& trs,
                  std::optional<std::vector<double>>& weights) {
    std::vector<double> v =
        sampleTrack(channel.track, time, channel.path == AnimatedPath::Rotation);
    switch (channel.path) {
    case AnimatedPath::Translation:
        trs->translation = glm::dvec3(v[0], v[1], v[2]);
        break;
    case AnimatedPath::Rotation:
        trs->rotation = glm::dquat(v[3], v[0], v[1], v[2]); // stored x, y, z, w
        break;
    case AnimatedPath::Scale:
        trs->scale = glm::dvec3(v[0], v[1], v[2]);
        break;
    case AnimatedPath::Weights:
        weights = std::move(v);
        break;
    }
}

} // namespace

std::vector<double> sampleTrack(const KeyframeTrack& track, double time, bool quaternion) {
    std::vector<double> value = interpolate(track, time, quaternion);
    if (quaternion) normalise(value);
    return value;
}

std::vector<Animation> readAnimations(const tinygltf::Model& model) {
    std::vector<Animation> animations;
    for (std::size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& source = model.animations[a];
        Animation animation;
        animation.name = source.name.empty() ? "animation " + std::to_string(a) : source.name;
        bool any = false;
        for (std::size_t c = 0; c < source.channels.size(); ++c) {
            // A channel without a node is for an extension to define (glTF 2.0, 5.6): ignored.
            if (source.channels[c].target_node == -1) continue;
            AnimationChannel channel = readChannel(model, source, a, c);
            const double start = channel.track.times.front();
            const double end = channel.track.times.back();
            animation.start = any ? std::min(animation.start, start) : start;
            animation.end = any ? std::max(animation.end, end) : end;
            any = true;
            animation.channels.push_back(std::move(channel));
        }
        animations.push_back(std::move(animation));
    }
    return animations;
}

std::vector<std::size_t> selectAnimations(const std::vector<Animation>& animations,
                                          const std::string& choice) {
    std::vector<std::size_t> playing;
    if (choice.empty()) {
        for (std::size_t a = 0; a < animations.size(); ++a)
            playing.push_back(a);
        return playing;
    }
    for (std::size_t a = 0; a < animations.size(); ++a) {
        if (animations[a].name == choice || std::to_string(a) == choice) return {a};
    }
    throw GltfProblem("animation '" + choice + "' does not exist (the file has " +
                      std::to_string(animations.size()) + " animations)");
}

ScenePose poseAt(const tinygltf::Model& model, const std::vector<Animation>& animations,
                 const std::vector<std::size_t>& playing, double time) {
    ScenePose pose;
    pose.locals.resize(model.nodes.size());
    pose.weights.resize(model.nodes.size());
    std::vector<std::optional<NodeTrs>> trs(model.nodes.size());
    for (std::size_t a : playing) {
        for (const AnimationChannel& channel : animations[a].channels) {
            const auto node = static_cast<std::size_t>(channel.node);
            if (channel.path != AnimatedPath::Weights && !trs[node])
                trs[node] = restTrs(model.nodes[node], channel.node);
            applyChannel(channel, time, trs[node], pose.weights[node]);
        }
    }
    for (std::size_t node = 0; node < trs.size(); ++node) {
        if (trs[node]) pose.locals[node] = trs[node]->matrix();
    }
    return pose;
}

} // namespace vkpt::gltf
