// gltf_nodes.h — the default scene's node tree: local transforms (TRS or matrix) and world
// transforms, visited depth first.
#pragma once

#include <functional>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkpt::gltf {

// The scene to load: the file's `scene` when it names one, else scene 0.
int defaultSceneIndex(const tinygltf::Model& model);

// A node's transform relative to its parent: its matrix, or T * R * S.
glm::dmat4 localTransform(const tinygltf::Node& node, int nodeIndex);

using NodeVisitor = std::function<void(int nodeIndex, const glm::dmat4& world)>;

// Calls visit for every node of the scene, each parent before its children, in the order of the
// scene's and each node's lists. Rejects cycles and node indices that do not exist. `root`
// applies to the whole scene: the world transform a visit receives is root × the node's.
void walkSceneNodes(const tinygltf::Model& model, int sceneIndex, const NodeVisitor& visit,
                    const glm::dmat4& root = glm::dmat4(1.0));

} // namespace vkpt::gltf
