// gltf_nodes.h — the default scene's node tree: local transforms (TRS or matrix) and world
// transforms, visited depth first.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

namespace vkpt::gltf {

// The scene to load: the file's `scene` when it names one, else scene 0.
int defaultSceneIndex(const tinygltf::Model& model);

// A node's translation, rotation and scale: the parts animations target (glTF 2.0, section 3.5.3).
struct NodeTrs {
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0}; // unit
    glm::dvec3 scale{1.0};

    glm::dmat4 matrix() const; // T * R * S
};

// The node's TRS as the file stores it (the defaults where absent; the rotation renormalised).
NodeTrs restTrs(const tinygltf::Node& node, int nodeIndex);

// A node's transform relative to its parent: its matrix, or T * R * S.
glm::dmat4 localTransform(const tinygltf::Node& node, int nodeIndex);

// What animations change at one moment (gltf_animation.h); the file's values elsewhere.
struct ScenePose {
    std::vector<std::optional<glm::dmat4>> locals;           // per node: its posed local transform
    std::vector<std::optional<std::vector<double>>> weights; // per node: its posed morph weights
};

using NodeVisitor = std::function<void(int nodeIndex, const glm::dmat4& world)>;

// Calls visit for every node of the scene, each parent before its children, in the order of the
// scene's and each node's lists. Rejects cycles and node indices that do not exist. `root`
// applies to the whole scene: the world transform a visit receives is root × the node's. A
// `pose` replaces the local transforms it lists.
void walkSceneNodes(const tinygltf::Model& model, int sceneIndex, const NodeVisitor& visit,
                    const glm::dmat4& root = glm::dmat4(1.0), const ScenePose* pose = nullptr);

} // namespace vkpt::gltf
