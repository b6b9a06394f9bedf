// gltf_animation.h — glTF animations (glTF 2.0, section 3.11): samplers read and checked, sampled
// at a time (STEP, LINEAR with quaternion slerp, CUBICSPLINE per Appendix C; clamped outside
// each sampler's range), and applied to the node tree as a ScenePose.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/gltf_nodes.h"

namespace vkpt::gltf {

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimatedPath { Translation, Rotation, Scale, Weights };

// Keyframes of one sampler: times strictly increasing, and per keyframe `width` values (for
// CUBICSPLINE 3 × width: in-tangent, value, out-tangent, as the file stores them).
struct KeyframeTrack {
    std::vector<double> times;
    std::vector<double> values;
    std::size_t width = 0;
    Interpolation interpolation = Interpolation::Linear;
};

// The track's `width` values at `time`: the first keyframe's before the first time, the last's
// after the last. `quaternion`: LINEAR interpolates by slerp (the shorter arc, Appendix C) and
// every result is renormalised.
std::vector<double> sampleTrack(const KeyframeTrack& track, double time, bool quaternion);

struct AnimationChannel {
    int node = -1;
    AnimatedPath path = AnimatedPath::Translation;
    KeyframeTrack track;
};

struct Animation {
    std::string name; // the file's, else "animation N"
    std::vector<AnimationChannel> channels;
    double start = 0.0; // the earliest and latest keyframe of its channels
    double end = 0.0;
};

// Every animation of the file, checked: samplers' accessors (input SCALAR floats strictly
// increasing; output of the path's type, as many as the keyframes need), channel nodes,
// weights channels as wide as the node's morph targets, no animated node with a matrix. Throws
// GltfProblem naming "animation A, channel C" or "animation A, sampler S".
std::vector<Animation> readAnimations(const tinygltf::Model& model);

// Which animations to play: "" all (the specification allows playing them together), else one,
// by index or by name; a GltfProblem for one that does not exist.
std::vector<std::size_t> selectAnimations(const std::vector<Animation>& animations,
                                          const std::string& choice);

// The pose of the node tree at `time` seconds under `animations` (all of their channels; a
// later channel on the same property wins).
ScenePose poseAt(const tinygltf::Model& model, const std::vector<Animation>& animations,
                 const std::vector<std::size_t>& playing, double time);

} // namespace vkpt::gltf
