// gltf_nodes.cpp — node transforms and an iterative depth-first walk (a deep hierarchy cannot
// overflow the stack, and a cyclic one is reported instead of looping).
#include "scene/gltf_nodes.h"

#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

void requireLength(const std::vector<double>& values, std::size_t length, const char* property,
                   int nodeIndex) {
    if (values.size() == length) return;
    throw GltfProblem(nodeName(nodeIndex) + ": " + property + " has " +
                      std::to_string(values.size()) + " numbers, expected " +
                      std::to_string(length));
}

glm::dquat rotationOf(const std::vector<double>& rotation, int nodeIndex) {
    requireLength(rotation, 4, "rotation", nodeIndex);
    // glTF stores quaternions as (x, y, z, w); glm's constructor takes w first.
    const glm::dquat q(rotation[3], rotation[0], rotation[1], rotation[2]);
    const double length = glm::length(q);
    if (!(length > 0.0)) throw GltfProblem(nodeName(nodeIndex) + ": rotation is a zero quaternion");
    // Exporters write quaternions rounded to a few digits; renormalise so no scale creeps in.
    return q / length;
}

glm::dvec3 vectorOf(const std::vector<double>& values, const char* property, int nodeIndex) {
    requireLength(values, 3, property, nodeIndex);
    return glm::dvec3(values[0], values[1], values[2]);
}

// A node waiting to be visited, or (leaving) one whose subtree is done.
struct PendingNode {
    int index;
    int parent; // -1 for a root of the scene
    glm::dmat4 parentWorld;
    bool leaving;
};

void pushChildren(std::vector<PendingNode>& stack, const std::vector<int>& children, int parent,
                  const glm::dmat4& world) {
    // Reversed, so that the first child is popped first.
    for (auto child = children.rbegin(); child != children.rend(); ++child) {
        stack.push_back({*child, parent, world, false});
    }
}

void checkNodeExists(const tinygltf::Model& model, const PendingNode& pending, int sceneIndex) {
    if (pending.index >= 0 && static_cast<std::size_t>(pending.index) < model.nodes.size()) return;
    const std::string where =
        pending.parent < 0 ? "scene " + std::to_string(sceneIndex) : nodeName(pending.parent);
    throw GltfProblem(where + ": " + nodeName(pending.index) + " does not exist (the file has " +
                      std::to_string(model.nodes.size()) + " nodes)");
}

} // namespace

int defaultSceneIndex(const tinygltf::Model& model) {
    if (model.scenes.empty()) throw GltfProblem("the file has no scene");
    const int index = model.defaultScene == -1 ? 0 : model.defaultScene; // -1: no `scene`
    if (index < 0 || static_cast<std::size_t>(index) >= model.scenes.size()) {
        throw GltfProblem("scene " + std::to_string(index) + " does not exist (the file has " +
                          std::to_string(model.scenes.size()) + " scenes)");
    }
    return index;
}

glm::dmat4 NodeTrs::matrix() const {
    return glm::scale(glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation),
                      scale);
}

NodeTrs restTrs(const tinygltf::Node& node, int nodeIndex) {
    NodeTrs trs;
    if (!node.translation.empty())
        trs.translation = vectorOf(node.translation, "translation", nodeIndex);
    if (!node.rotation.empty()) trs.rotation = rotationOf(node.rotation, nodeIndex);
    if (!node.scale.empty()) trs.scale = vectorOf(node.scale, "scale", nodeIndex);
    return trs;
}

glm::dmat4 localTransform(const tinygltf::Node& node, int nodeIndex) {
    if (!node.matrix.empty()) {
        requireLength(node.matrix, 16, "matrix", nodeIndex);
        return glm::make_mat4(node.matrix.data()); // both column-major
    }
    return restTrs(node, nodeIndex).matrix();
}

void walkSceneNodes(const tinygltf::Model& model, int sceneIndex, const NodeVisitor& visit,
                    const glm::dmat4& root, const ScenePose* pose) {
    std::vector<char> onPath(model.nodes.size(), 0);
    std::vector<PendingNode> stack;
    pushChildren(stack, model.scenes[static_cast<std::size_t>(sceneIndex)].nodes, -1, root);
    while (!stack.empty()) {
        const PendingNode pending = stack.back();
        stack.pop_back();
        const auto index = static_cast<std::size_t>(pending.index);
        if (pending.leaving) {
            onPath[index] = 0;
            continue;
        }
        checkNodeExists(model, pending, sceneIndex);
        if (onPath[index]) {
            throw GltfProblem(nodeName(pending.index) + ": the node hierarchy has a cycle");
        }
        const tinygltf::Node& node = model.nodes[index];
        const bool posed = pose != nullptr && index < pose->locals.size() && pose->locals[index];
        const glm::dmat4 world =
            pending.parentWorld *
            (posed ? *pose->locals[index] : localTransform(node, pending.index));
        visit(pending.index, world);
        onPath[index] = 1;
        stack.push_back({pending.index, pending.parent, world, true});
        pushChildren(stack, node.children, pending.index, world);
    }
}

} // namespace vkpt::gltf
