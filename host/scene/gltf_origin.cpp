// gltf_origin.cpp — a first walk over the default scene that measures its world-space bounds in
// double (vertices, or an instanced mesh's box, spheres and the positions of point and spot
// lights), and the rule that
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
#include "scene/gltf_mesh_instancing.h"
#include "scene/gltf_morph.h"
#include "scene/gltf_nodes.h"
#include "scene/gltf_shapes.h"
#include "scene/gltf_skins.h"

namespace vkpt::gltf {
namespace {

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Bounds in double, grown point by point.
class ExtentAccumulator {
public:
    void addPoint(const glm::dvec3& w) {
        if (!isFinite(w)) return;
        extent_.min = any_ ? glm::min(extent_.min, w) : w;
        extent_.max = any_ ? glm::max(extent_.max, w) : w;
        any_ = true;
    }
    void addBox(const WorldExtent& box, const glm::dmat4& transform) {
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p((corner & 1) ? box.max.x : box.min.x,
                               (corner & 2) ? box.max.y : box.min.y,
                               (corner & 4) ? box.max.z : box.min.z);
            addPoint(glm::dvec3(transform * glm::dvec4(p, 1.0)));
        }
    }
    std::optional<WorldExtent> extent() const {
        if (!any_) return std::nullopt;
        return extent_;
    }

private:
    WorldExtent extent_;
    bool any_ = false;
};

class ExtentBuilder {
public:
    ExtentBuilder(const tinygltf::Model& model, const InstancingPlan& plan,
                  const std::vector<Animation>& animations)
        : model_(model), plan_(plan), animations_(animations), meshBoxes_(model.meshes.size()) {
        worlds_.transforms.assign(model.nodes.size(), glm::dmat4(1.0));
        worlds_.placed.assign(model.nodes.size(), 0);
    }

    void visitNode(int nodeIndex, const glm::dmat4& world) {
        worlds_.transforms[static_cast<std::size_t>(nodeIndex)] = world;
        worlds_.placed[static_cast<std::size_t>(nodeIndex)] = 1;
        if (const std::optional<WorldSphere> sphere = placeSphere(model_, nodeIndex, world)) {
            extent_.addPoint(sphere->centre - glm::dvec3(sphere->radius));
            extent_.addPoint(sphere->centre + glm::dvec3(sphere->radius));
        }
        if (const std::optional<SceneLight> light = placeLight(model_, nodeIndex, world)) {
            // A directional light has no place; the others are points of the scene.
            if (light->kind != LightKind::Directional) extent_.addPoint(glm::dvec3(world[3]));
        }
        const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(nodeIndex)];
        const int mesh = node.mesh;
        if (mesh < 0 || static_cast<std::size_t>(mesh) >= model_.meshes.size()) return;
        if (node.skin >= 0) {
            // Placed by its joints, not by the node (glTF 2.0, section 3.7.3.1): once every
            // joint's world transform is known.
            skinned_.push_back(nodeIndex);
            return;
        }
        const std::vector<WeightRange> weights = morphWeightRanges(model_, nodeIndex, animations_);
        const std::optional<std::vector<glm::dmat4>> local =
            meshInstanceTransforms(model_, nodeIndex);
        if (!local) {
            addMeshPlacement(mesh, world, weights);
            return;
        }
        for (const glm::dmat4& transform : *local)
            addMeshPlacement(mesh, world * transform, weights);
    }

    // A skinned vertex is Σ wᵢ·Jᵢ·p with weights that sum to one (renormalised where they do
    // not): a point of the convex hull of its Jᵢ·p, so the union of the mesh's own box placed by
    // each joint matrix Jᵢ holds every skinned vertex, at rest as the skin places it.
    void addSkinnedMeshes() {
        for (int nodeIndex : skinned_) {
            const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(nodeIndex)];
            std::vector<glm::dmat4> joints;
            try {
                joints = jointMatrices(model_, node.skin, worlds_);
            } catch (const GltfProblem&) {
                continue; // the loading pass names the problem
            }
            ExtentAccumulator own;
            addMeshVertices(node.mesh, glm::dmat4(1.0), own,
                            morphWeightRanges(model_, nodeIndex, animations_));
            if (const std::optional<WorldExtent> box = own.extent())
                for (const glm::dmat4& joint : joints)
                    extent_.addBox(*box, joint);
        }
    }

    std::optional<WorldExtent> extent() const { return extent_.extent(); }

private:
    // A flattened placement adds its vertices, as the loader will place them; an instanced one
    // the corners of its mesh's own box (read once), which is as good for choosing an origin. A
    // morphed mesh adds its vertices with every shape `weights` allow, at each placement (the
    // weights are the node's).
    void addMeshPlacement(int mesh, const glm::dmat4& transform,
                          const std::vector<WeightRange>& weights) {
        if (!plan_.isInstanced(mesh) || !weights.empty()) {
            addMeshVertices(mesh, transform, extent_, weights);
            return;
        }
        std::optional<std::optional<WorldExtent>>& box = meshBoxes_[static_cast<std::size_t>(mesh)];
        if (!box) {
            ExtentAccumulator own;
            addMeshVertices(mesh, glm::dmat4(1.0), own);
            box = own.extent();
        }
        if (*box) extent_.addBox(**box, transform);
    }

    void addMeshVertices(int mesh, const glm::dmat4& transform, ExtentAccumulator& target,
                         const std::vector<WeightRange>& weights = {}) const {
        for (const tinygltf::Primitive& primitive :
             model_.meshes[static_cast<std::size_t>(mesh)].primitives) {
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) continue;
            if (isDracoPrimitive(primitive)) {
                addAccessorBounds(position->second, transform, target);
            } else if (!weights.empty() && !primitive.targets.empty()) {
                addMorphedVertices(primitive, position->second, transform, weights, target);
            } else {
                addVertices(position->second, transform, target);
            }
        }
    }

    // Each vertex p as the box of p + Σ wₜ·dₜ over the weights' ranges: per axis, each target
    // adds the least and the most of wₜ·dₜ, at an end of its range (linear in wₜ).
    void addMorphedVertices(const tinygltf::Primitive& primitive, int accessor,
                            const glm::dmat4& transform, const std::vector<WeightRange>& weights,
                            ExtentAccumulator& target) const {
        const std::vector<glm::vec3> positions = readPositions(model_, accessor, "POSITION");
        std::vector<WorldExtent> boxes(positions.size());
        for (std::size_t i = 0; i < positions.size(); ++i)
            boxes[i] = {glm::dvec3(positions[i]), glm::dvec3(positions[i])};
        for (std::size_t t = 0; t < primitive.targets.size() && t < weights.size(); ++t) {
            const auto moved = primitive.targets[t].find("POSITION");
            if (moved == primitive.targets[t].end()) continue;
            const std::vector<glm::vec3> displacements =
                readPositions(model_, moved->second, "morph target POSITION");
            if (displacements.size() != positions.size()) continue; // the loading pass says so
            for (std::size_t i = 0; i < positions.size(); ++i) {
                const glm::dvec3 low = weights[t].low * glm::dvec3(displacements[i]);
                const glm::dvec3 high = weights[t].high * glm::dvec3(displacements[i]);
                boxes[i].min += glm::min(low, high);
                boxes[i].max += glm::max(low, high);
            }
        }
        for (const WorldExtent& box : boxes)
            target.addBox(box, transform);
    }

    // A Draco primitive's POSITION accessor has no data of its own, but the min and max that
    // glTF requires of every POSITION accessor bound it; its 8 corners bound the transformed
    // vertices.
    void addAccessorBounds(int accessor, const glm::dmat4& transform,
                           ExtentAccumulator& target) const {
        if (accessor < 0 || static_cast<std::size_t>(accessor) >= model_.accessors.size()) return;
        const tinygltf::Accessor& bounds = model_.accessors[static_cast<std::size_t>(accessor)];
        if (bounds.minValues.size() != 3 || bounds.maxValues.size() != 3) return;
        WorldExtent box;
        box.min = glm::dvec3(bounds.minValues[0], bounds.minValues[1], bounds.minValues[2]);
        box.max = glm::dvec3(bounds.maxValues[0], bounds.maxValues[1], bounds.maxValues[2]);
        target.addBox(box, transform);
    }

    void addVertices(int accessor, const glm::dmat4& transform, ExtentAccumulator& target) const {
        for (const glm::vec3& p : readPositions(model_, accessor, "POSITION"))
            target.addPoint(glm::dvec3(transform * glm::dvec4(glm::dvec3(p), 1.0)));
    }

    const tinygltf::Model& model_;
    const InstancingPlan& plan_;
    const std::vector<Animation>& animations_; // for the weights a morphed mesh can take
    ExtentAccumulator extent_;
    NodeWorlds worlds_;        // per node: its world transform at rest, once visited
    std::vector<int> skinned_; // nodes with a skinned mesh, measured after the walk
    // Per mesh: not yet read, or its own box (nullopt: no finite vertex).
    std::vector<std::optional<std::optional<WorldExtent>>> meshBoxes_;
};

} // namespace

double WorldExtent::size() const {
    const glm::dvec3 side = max - min;
    return std::max(side.x, std::max(side.y, side.z));
}

std::optional<WorldExtent> worldExtent(const tinygltf::Model& model, int sceneIndex,
                                       const InstancingPlan& plan,
                                       const std::vector<Animation>& animations) {
    ExtentBuilder builder(model, plan, animations);
    try {
        walkSceneNodes(model, sceneIndex,
                       [&](int node, const glm::dmat4& world) { builder.visitNode(node, world); });
    } catch (const GltfProblem&) {
        return std::nullopt; // the loading pass names the problem
    }
    builder.addSkinnedMeshes();
    return builder.extent();
}

glm::dvec3 chooseWorldOrigin(const WorldExtent& extent) {
    const glm::dvec3 centre = extent.centre();
    const double distance =
        std::max(std::abs(centre.x), std::max(std::abs(centre.y), std::abs(centre.z)));
    return distance > kRecentreRatio * extent.size() ? centre : glm::dvec3(0.0);
}

} // namespace vkpt::gltf
