// gltf_origin.cpp — a first walk over the default scene that measures its world-space bounds in
// double (vertices, spheres and the positions of point and spot lights), and the rule that
// decides whether to recentre it. The loading walk then moves all of them alike, through the
// root transform it applies to every node.
#include "scene/gltf_origin.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scene/gltf_accessors.h"
#include "scene/gltf_document.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_nodes.h"
#include "scene/gltf_shapes.h"

namespace vkpt::gltf {
namespace {

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

class ExtentBuilder {
public:
    explicit ExtentBuilder(const tinygltf::Model& model) : model_(model) {}

    void visitNode(int nodeIndex, const glm::dmat4& world) {
        if (const std::optional<WorldSphere> sphere = placeSphere(model_, nodeIndex, world)) {
            addPoint(sphere->centre - glm::dvec3(sphere->radius));
            addPoint(sphere->centre + glm::dvec3(sphere->radius));
        }
        if (const std::optional<SceneLight> light = placeLight(model_, nodeIndex, world)) {
            // A directional light has no place; the others are points of the scene.
            if (light->kind != LightKind::Directional) addPoint(glm::dvec3(world[3]));
        }
        const int mesh = model_.nodes[static_cast<std::size_t>(nodeIndex)].mesh;
        if (mesh < 0 || static_cast<std::size_t>(mesh) >= model_.meshes.size()) return;
        for (const tinygltf::Primitive& primitive :
             model_.meshes[static_cast<std::size_t>(mesh)].primitives) {
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) continue;
            if (isDracoPrimitive(primitive)) {
                addAccessorBounds(position->second, world);
            } else {
                addVertices(position->second, world);
            }
        }
    }

    std::optional<WorldExtent> extent() const {
        if (!any_) return std::nullopt;
        return extent_;
    }

private:
    // A Draco primitive's POSITION accessor has no data of its own, but the min and max that
    // glTF requires of every POSITION accessor bound it; its 8 corners bound the transformed
    // vertices.
    void addAccessorBounds(int accessor, const glm::dmat4& world) {
        if (accessor < 0 || static_cast<std::size_t>(accessor) >= model_.accessors.size()) return;
        const tinygltf::Accessor& bounds = model_.accessors[static_cast<std::size_t>(accessor)];
        if (bounds.minValues.size() != 3 || bounds.maxValues.size() != 3) return;
        for (int corner = 0; corner < 8; ++corner) {
            glm::dvec3 p;
            for (int axis = 0; axis < 3; ++axis) {
                const auto a = static_cast<std::size_t>(axis);
                p[axis] = (corner >> axis) & 1 ? bounds.maxValues[a] : bounds.minValues[a];
            }
            addPoint(glm::dvec3(world * glm::dvec4(p, 1.0)));
        }
    }

    void addVertices(int accessor, const glm::dmat4& world) {
        for (const glm::vec3& p : readPositions(model_, accessor, "POSITION"))
            addPoint(glm::dvec3(world * glm::dvec4(glm::dvec3(p), 1.0)));
    }

    void addPoint(const glm::dvec3& w) {
        if (!isFinite(w)) return;
        extent_.min = any_ ? glm::min(extent_.min, w) : w;
        extent_.max = any_ ? glm::max(extent_.max, w) : w;
        any_ = true;
    }

    const tinygltf::Model& model_;
    WorldExtent extent_;
    bool any_ = false;
};

} // namespace

double WorldExtent::size() const {
    const glm::dvec3 side = max - min;
    return std::max(side.x, std::max(side.y, side.z));
}

std::optional<WorldExtent> worldExtent(const tinygltf::Model& model, int sceneIndex) {
    ExtentBuilder builder(model);
    try {
        walkSceneNodes(model, sceneIndex,
                       [&](int node, const glm::dmat4& world) { builder.visitNode(node, world); });
    } catch (const GltfProblem&) {
        return std::nullopt; // the loading pass names the problem
    }
    return builder.extent();
}

glm::dvec3 chooseWorldOrigin(const WorldExtent& extent) {
    const glm::dvec3 centre = extent.centre();
    const double distance =
        std::max(std::abs(centre.x), std::max(std::abs(centre.y), std::abs(centre.z)));
    return distance > kRecentreRatio * extent.size() ? centre : glm::dvec3(0.0);
}

} // namespace vkpt::gltf
