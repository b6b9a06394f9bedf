// gltf_loader.cpp — the loading pipeline: parse the file, check extensions and buffer views,
// convert the materials (decoding the textures they use), walk the default scene collecting
// triangles, spheres, lights and cameras, then say what was ignored.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "common/errors.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_animation.h"
#include "scene/gltf_cameras.h"
#include "scene/gltf_document.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_instancing_plan.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_mesh_instancing.h"
#include "scene/gltf_morph.h"
#include "scene/gltf_nodes.h"
#include "scene/gltf_origin.h"
#include "scene/gltf_primitives.h"
#include "scene/gltf_shapes.h"
#include "scene/gltf_skins.h"
#include "scene/gltf_textures.h"
#include "scene/gltf_variants.h"

namespace vkpt {
namespace gltf {

// Where a builder's walk left the meshes it keeps once: per glTF mesh, not read yet, or its slot
// in Scene::meshes (nullopt: nothing to keep); and the default material, once appended. The
// moving walk starts where the still walk ended.
struct MeshSlots {
    std::vector<std::optional<std::optional<std::uint32_t>>> slots;
    std::optional<std::uint32_t> defaultMaterial;
};

} // namespace gltf

namespace {

using gltf::GltfProblem;
using gltf::MeshSlots;

std::string joinNames(const std::vector<std::string>& names) {
    std::string joined;
    for (const std::string& name : names)
        joined += (joined.empty() ? "" : ", ") + name;
    return joined;
}

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", value);
    return text;
}

// Whether an instance may place a mesh by `transform`: the walk transforms rays into the mesh's
// space by its inverse, which must exist and be well conditioned. A placement that (nearly)
// flattens a dimension is flattened instead, where its triangles have no area and are skipped.
bool canInstance(const glm::dmat4& transform) {
    const glm::dmat3 linear(transform);
    const double scale = glm::length(linear[0]) * glm::length(linear[1]) * glm::length(linear[2]);
    const double det = glm::determinant(linear);
    return std::isfinite(det) && scale > 0.0 && std::abs(det) > 1e-6 * scale;
}

// Which of the nodes' contributions a walk collects. A scene that keeps what moves apart
// (LoadOptions::keepMovingApart) is built in two walks: the still part, the meshes of the nodes
// that no animation moves, skins or morphs, which every frame shares and which is read once; then
// per frame the moving part, the other meshes, and the cameras, lights and spheres of every node
// (few, and in walk order as a whole walk gives them). Everything else is one whole walk.
enum class WalkPart { Whole, Still, Moving };

// Collects the triangles, spheres, lights and cameras of the nodes the walk visits; a mesh the
// instancing plan keeps once is read into Scene::meshes at its first placement and placed by
// Scene::instances.
class SceneBuilder {
public:
    // `movingNodes` (per node, empty for none): the nodes an animation moves, whose meshes are
    // kept apart from the still geometry (LoadOptions::keepMovingApart). `slots`: where a walk
    // before this one left the kept meshes (empty: none yet).
    SceneBuilder(const tinygltf::Model& model, Scene& scene, gltf::Texcoords texcoords,
                 const gltf::InstancingPlan& plan, const gltf::ScenePose* pose,
                 const gltf::NodeWorlds& worlds, std::vector<char> movingNodes,
                 WalkPart part = WalkPart::Whole, MeshSlots slots = {})
        : model_(model), scene_(scene), texcoords_(texcoords), plan_(plan), pose_(pose),
          worlds_(worlds), movingNodes_(std::move(movingNodes)), part_(part),
          skinJoints_(model.skins.size()),
          withTangents_(std::any_of(scene.materials.begin(), scene.materials.end(),
                                    [](const SceneMaterial& m) { return m.needsTangents(); })),
          defaultMaterial_(slots.defaultMaterial), meshSlots_(std::move(slots.slots)) {
        meshSlots_.resize(model.meshes.size());
    }

    MeshSlots meshSlots() const { return {meshSlots_, defaultMaterial_}; }

    void visitNode(int nodeIndex, const glm::dmat4& world) {
        const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(nodeIndex)];
        if (node.mesh != -1 && collectsMeshOf(nodeIndex)) appendMesh(nodeIndex, node.mesh, world);
        if (part_ == WalkPart::Still) return;
        if (node.camera != -1) appendCamera(nodeIndex, world);
        if (std::optional<SceneLight> light = gltf::placeLight(model_, nodeIndex, world)) {
            scene_.lights.push_back(std::move(*light));
        }
        if (const std::optional<gltf::WorldSphere> sphere =
                gltf::placeSphere(model_, nodeIndex, world)) {
            appendSphere(nodeIndex, *sphere);
        }
    }

private:
    bool collectsMeshOf(int nodeIndex) const {
        if (part_ == WalkPart::Whole) return true;
        return (part_ == WalkPart::Moving) == changesWithTheFrame(nodeIndex);
    }

    // Whether a frame's pose decides where the node's mesh is: an animation moves the node, a
    // skin places the mesh, or morph weights shape it (a frame keeps a morphed mesh as a posed
    // mesh of its own whatever its weights: placeMesh). A mesh that does not exist is the still
    // walk's, which reports it.
    bool changesWithTheFrame(int nodeIndex) const {
        const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(nodeIndex)];
        if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= model_.meshes.size())
            return false;
        if (movingNodes_[static_cast<std::size_t>(nodeIndex)] != 0 || node.skin != -1) return true;
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(node.mesh)];
        const bool morphs = std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                                        [](const auto& p) { return !p.targets.empty(); });
        return morphs && !gltf::morphWeights(model_, nodeIndex, pose_).empty();
    }

    // The node's mesh at each of its placements: the node itself, or each EXT_mesh_gpu_instancing
    // instance.
    void appendMesh(int nodeIndex, int meshIndex, const glm::dmat4& world) {
        if (meshIndex < 0 || static_cast<std::size_t>(meshIndex) >= model_.meshes.size()) {
            throw GltfProblem("node " + std::to_string(nodeIndex) + ": mesh " +
                              std::to_string(meshIndex) + " does not exist (the file has " +
                              std::to_string(model_.meshes.size()) + " meshes)");
        }
        const gltf::Deformation deformation = deformationOf(nodeIndex);
        if (deformation.joints != nullptr) {
            // The skin places the vertices; the node's own transform is ignored (glTF 2.0,
            // section 3.7.3.1), and its instances too: one skinned copy.
            if (!movingNodes_.empty()) {
                appendPosedMesh(meshIndex, glm::dmat4(1.0), deformation);
                return;
            }
            appendPrimitives(meshIndex, glm::dmat4(1.0), PrimitiveKinds::All, scene_, deformation);
            return;
        }
        const bool nodeMoves =
            !movingNodes_.empty() && movingNodes_[static_cast<std::size_t>(nodeIndex)] != 0;
        const std::optional<std::vector<glm::dmat4>> local =
            gltf::meshInstanceTransforms(model_, nodeIndex);
        if (!local) {
            placeMesh(meshIndex, world, deformation, nodeMoves);
            return;
        }
        for (const glm::dmat4& transform : *local)
            placeMesh(meshIndex, world * transform, deformation, nodeMoves);
    }

    // The node's morph weights and skin; a mesh moved by either is flattened at this placement
    // (its instanced copy, if any, is the one the file stores).
    gltf::Deformation deformationOf(int nodeIndex) {
        gltf::Deformation deformation;
        const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(nodeIndex)];
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(node.mesh)];
        const bool morphs = std::any_of(mesh.primitives.begin(), mesh.primitives.end(),
                                        [](const auto& p) { return !p.targets.empty(); });
        if (morphs) deformation.morphWeights = gltf::morphWeights(model_, nodeIndex, pose_);
        if (node.skin != -1) deformation.joints = &skinJoints(node.skin, nodeIndex);
        return deformation;
    }

    const std::vector<glm::dmat4>& skinJoints(int skinIndex, int nodeIndex) {
        if (skinIndex < 0 || static_cast<std::size_t>(skinIndex) >= model_.skins.size()) {
            const std::size_t count = model_.skins.size();
            throw GltfProblem("node " + std::to_string(nodeIndex) + ": skin " +
                              std::to_string(skinIndex) + " does not exist (the file has " +
                              std::to_string(count) + (count == 1 ? " skin)" : " skins)"));
        }
        std::optional<std::vector<glm::dmat4>>& joints =
            skinJoints_[static_cast<std::size_t>(skinIndex)];
        if (!joints) joints = gltf::jointMatrices(model_, skinIndex, worlds_);
        return *joints;
    }

    static bool moves(const gltf::Deformation& deformation) {
        return deformation.joints != nullptr ||
               std::any_of(deformation.morphWeights.begin(), deformation.morphWeights.end(),
                           [](double w) { return w != 0.0; });
    }

    // `nodeMoves`: an animation moves the placement (keepMovingApart), which then places the
    // mesh's one copy by an instance whatever the plan says, so that the next frame only moves
    // the instance; a deformed mesh there is a posed mesh of its own.
    void placeMesh(int meshIndex, const glm::dmat4& placement, const gltf::Deformation& deformation,
                   bool nodeMoves) {
        // Any morph weights, zero or not: a frame whose weights are all zero keeps the layout.
        if (!movingNodes_.empty() && !deformation.morphWeights.empty()) {
            appendPosedMesh(meshIndex, placement, deformation);
            return;
        }
        const bool instanced =
            plan_.isInstanced(meshIndex) || (nodeMoves && plan_.geometryOf(meshIndex) >= 0);
        if (!instanced || !canInstance(placement) || moves(deformation)) {
            appendPrimitives(meshIndex, placement, PrimitiveKinds::All, scene_, deformation);
            return;
        }
        // Emitters stay in world space at every placement (light sampling lists each one).
        appendPrimitives(meshIndex, placement, PrimitiveKinds::Emitting, scene_);
        const int geometry = plan_.geometryOf(meshIndex);
        const std::optional<std::uint32_t> slot = meshSlot(geometry);
        if (!slot) return;
        const glm::dvec3 origin = scene_.meshes[*slot].origin;
        const std::uint32_t material =
            geometry == meshIndex ? SceneInstance::kKeepMaterial : soleKeptMaterial(meshIndex);
        scene_.instances.push_back(
            {*slot, placement * glm::translate(glm::dmat4(1.0), origin), material});
    }

    // The material of a mesh that places another mesh's geometry: of its one primitive that
    // does not emit (the plan groups meshes of several such primitives only when their
    // materials agree, and then the triangles keep theirs).
    std::uint32_t soleKeptMaterial(int meshIndex) {
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(meshIndex)];
        std::optional<std::uint32_t> sole;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string where =
                "mesh " + std::to_string(meshIndex) + ", primitive " + std::to_string(p);
            const std::uint32_t material = materialIndex(mesh.primitives[p].material, where);
            if (scene_.materials[material].emits()) continue;
            if (sole) return SceneInstance::kKeepMaterial;
            sole = material;
        }
        return sole.value_or(SceneInstance::kKeepMaterial);
    }

    // A skinned or morphed mesh of a frame (keepMovingApart): its posed triangles as a mesh of
    // their own, placed unmoved, so that the still geometry's bottom level stays what it was and
    // only this one is built again; its emitters go to the scene's own soup like any other's.
    void appendPosedMesh(int meshIndex, const glm::dmat4& placement,
                         const gltf::Deformation& deformation) {
        appendPrimitives(meshIndex, placement, PrimitiveKinds::Emitting, scene_, deformation);
        SceneMesh mesh;
        const tinygltf::Mesh& source = model_.meshes[static_cast<std::size_t>(meshIndex)];
        mesh.name = "posed mesh " + std::to_string(meshIndex) +
                    (source.name.empty() ? "" : " (" + source.name + ")");
        appendPrimitives(meshIndex, placement, PrimitiveKinds::NotEmitting, mesh, deformation);
        if (mesh.triangleCount() == 0) return;
        const auto slot = static_cast<std::uint32_t>(scene_.meshes.size());
        scene_.meshes.push_back(std::move(mesh));
        scene_.instances.push_back({slot, glm::dmat4(1.0), SceneInstance::kKeepMaterial});
    }

    // The mesh's own copy in Scene::meshes, read at its first placement; nullopt when it has no
    // triangles to keep (all of them emit, or have no area).
    std::optional<std::uint32_t> meshSlot(int meshIndex) {
        std::optional<std::optional<std::uint32_t>>& slot =
            meshSlots_[static_cast<std::size_t>(meshIndex)];
        if (slot) return *slot;
        SceneMesh mesh;
        const tinygltf::Mesh& source = model_.meshes[static_cast<std::size_t>(meshIndex)];
        mesh.name = "mesh " + std::to_string(meshIndex) +
                    (source.name.empty() ? "" : " (" + source.name + ")");
        appendPrimitives(meshIndex, glm::dmat4(1.0), PrimitiveKinds::NotEmitting, mesh);
        recentre(mesh);
        slot = std::optional<std::uint32_t>();
        if (mesh.triangleCount() > 0) {
            *slot = static_cast<std::uint32_t>(scene_.meshes.size());
            scene_.meshes.push_back(std::move(mesh));
        }
        return *slot;
    }

    // Moves the mesh's positions to be measured from its centre when that lies far from its
    // origin (gltf::chooseWorldOrigin's rule), in double: the file's floats there are as coarse
    // as they are, but the rays moved into this space are then as fine as the mesh is small.
    static void recentre(SceneMesh& mesh) {
        if (mesh.positions.empty()) return;
        gltf::WorldExtent extent{glm::dvec3(mesh.positions[0]), glm::dvec3(mesh.positions[0])};
        for (const glm::vec3& p : mesh.positions) {
            extent.min = glm::min(extent.min, glm::dvec3(p));
            extent.max = glm::max(extent.max, glm::dvec3(p));
        }
        mesh.origin = gltf::chooseWorldOrigin(extent);
        if (mesh.origin == glm::dvec3(0.0)) return;
        for (glm::vec3& p : mesh.positions)
            p = glm::vec3(glm::dvec3(p) - mesh.origin);
    }

    enum class PrimitiveKinds { All, Emitting, NotEmitting };

    void appendPrimitives(int meshIndex, const glm::dmat4& transform, PrimitiveKinds kinds,
                          TriangleSoup& soup, const gltf::Deformation& deformation = {}) {
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(meshIndex)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string where =
                "mesh " + std::to_string(meshIndex) + ", primitive " + std::to_string(p);
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            const std::uint32_t material =
                materialIndex(gltf::variantMaterial(primitive, scene_.materialVariant,
                                                    scene_.materialVariants.size(), where),
                              where);
            const bool emitting = scene_.materials[material].emits();
            if ((kinds == PrimitiveKinds::Emitting && !emitting) ||
                (kinds == PrimitiveKinds::NotEmitting && emitting))
                continue;
            gltf::appendPrimitiveTriangles(model_, primitive, transform, material, texcoords_,
                                           tangentsFor(material), where, soup, scene_.repairs,
                                           deformation);
        }
    }

    void appendSphere(int nodeIndex, const gltf::WorldSphere& sphere) {
        SceneSphere converted;
        converted.centre = glm::vec3(sphere.centre);
        converted.radius = static_cast<float>(sphere.radius);
        // A radius below the float range would make a sphere no ray can hit; far above it,
        // one that fills every float. Either is reported rather than drawn wrongly.
        if (!(converted.radius > 0.0f) || !std::isfinite(converted.radius) ||
            !std::isfinite(converted.centre.x + converted.centre.y + converted.centre.z)) {
            throw GltfProblem("node " + std::to_string(nodeIndex) + ": the sphere's radius " +
                              formatNumber(sphere.radius) + " is outside the float range");
        }
        converted.material = sphere.material < 0 ? defaultMaterialIndex()
                                                 : static_cast<std::uint32_t>(sphere.material);
        scene_.spheres.push_back(converted);
    }

    void appendCamera(int nodeIndex, const glm::dmat4& world) {
        scene_.cameras.push_back(gltf::placeCamera(model_, nodeIndex, world));
    }

    // Tangents only where a scene has normal textures or anisotropy, generated or read only for
    // the primitives whose material needs them.
    gltf::Tangents tangentsFor(std::uint32_t material) const {
        if (!withTangents_) return gltf::Tangents::Skip;
        return scene_.materials[material].needsTangents() ? gltf::Tangents::Read
                                                          : gltf::Tangents::Zero;
    }

    // glTF material indices carry over; a primitive without one gets the default material,
    // appended after the file's materials the first time it is needed.
    std::uint32_t materialIndex(int gltfIndex, const std::string& where) {
        if (gltfIndex == -1) return defaultMaterialIndex();
        if (gltfIndex < 0 || static_cast<std::size_t>(gltfIndex) >= model_.materials.size()) {
            throw GltfProblem(where + ": material " + std::to_string(gltfIndex) +
                              " does not exist (the file has " +
                              std::to_string(model_.materials.size()) + " materials)");
        }
        return static_cast<std::uint32_t>(gltfIndex);
    }

    std::uint32_t defaultMaterialIndex() {
        if (!defaultMaterial_) {
            defaultMaterial_ = static_cast<std::uint32_t>(scene_.materials.size());
            scene_.materials.push_back(gltf::defaultMaterial());
        }
        return *defaultMaterial_;
    }

    const tinygltf::Model& model_;
    Scene& scene_;
    gltf::Texcoords texcoords_;
    const gltf::InstancingPlan& plan_;
    const gltf::ScenePose* pose_; // nullptr: at rest
    const gltf::NodeWorlds& worlds_;
    std::vector<char> movingNodes_; // per node; empty: nothing kept apart
    WalkPart part_;
    std::vector<std::optional<std::vector<glm::dmat4>>> skinJoints_; // per skin, when first used
    bool withTangents_; // some material has a normal texture or anisotropy
    std::optional<std::uint32_t> defaultMaterial_;
    // Per glTF mesh: not read yet, or its slot in Scene::meshes (nullopt: nothing to keep).
    std::vector<std::optional<std::optional<std::uint32_t>>> meshSlots_;
};

// Appended piece by piece: `"(" + std::string` trips GCC 12's -Wrestrict at -O3 (a false
// positive inside libstdc++'s string::replace, reported by many projects).
std::string formatPoint(const glm::dvec3& p) {
    std::string point = "(";
    point += formatNumber(p.x);
    point += ", ";
    point += formatNumber(p.y);
    point += ", ";
    point += formatNumber(p.z);
    point += ")";
    return point;
}

std::string plural(std::size_t count, const char* one, const char* many) {
    return std::to_string(count) + " " + (count == 1 ? one : many);
}

// What the load changed about the geometry: a recentred origin, repaired normals, skipped
// triangles (docs/numerical-stability.md).
std::vector<std::string> geometryNotes(const Scene& scene,
                                       const std::optional<gltf::WorldExtent>& extent) {
    std::vector<std::string> notes;
    if (scene.worldOrigin != glm::dvec3(0.0) && extent) {
        notes.push_back("the scene is centred at " + formatPoint(scene.worldOrigin) +
                        ", more than " + formatNumber(gltf::kRecentreRatio) + " times its size (" +
                        formatNumber(extent->size()) +
                        ") from the origin; coordinates are measured from that centre to keep "
                        "float precision");
    }
    const GeometryRepairs& repairs = scene.repairs;
    if (repairs.zeroAreaTriangles > 0) {
        notes.push_back("skipped " + plural(repairs.zeroAreaTriangles, "triangle", "triangles") +
                        " of zero area");
    }
    if (repairs.invalidNormals > 0) {
        notes.push_back(plural(repairs.invalidNormals, "vertex normal was", "vertex normals were") +
                        " zero or not finite; the triangles' face normals are used there");
    }
    if (repairs.renormalisedSkinWeights > 0) {
        notes.push_back(
            plural(repairs.renormalisedSkinWeights, "skinned vertex has", "skinned vertices have") +
            " weights that do not sum to one; they are renormalised");
    }
    return notes;
}

// What the load ignored or changed, said once it has succeeded, so that a failing load prints
// one line.
std::vector<std::string> loadNotes(const tinygltf::Model& model, const LoadOptions& options) {
    std::vector<std::string> notes = gltf::materialNotes(model);
    const std::vector<std::string> ignored = gltf::ignoredExtensions(model.extensionsUsed);
    if (options.warnUnsupportedExtensions && !ignored.empty()) {
        notes.push_back("ignoring unsupported extensions: " + joinNames(ignored));
    }
    return notes;
}

// A scene of spheres alone is a scene; one with neither triangles nor spheres has nothing to
// show (lights light nothing).
std::string noTrianglesMessage(const Scene& scene) {
    const std::size_t skipped = scene.repairs.zeroAreaTriangles;
    if (skipped == 0) return "the scene has no triangles";
    return "the scene has no triangles of non-zero area (" +
           plural(skipped, "triangle", "triangles") + " of zero area)";
}

std::vector<SceneAnimation> summarise(const std::vector<gltf::Animation>& animations) {
    std::vector<SceneAnimation> summaries;
    for (const gltf::Animation& animation : animations)
        summaries.push_back(
            {animation.name, animation.start, animation.end, animation.channels.size()});
    return summaries;
}

// Every node's world transform, for the joints of skins (a skinned mesh may come before its
// joints in the walk); nothing to walk for a file without skins.
gltf::NodeWorlds nodeWorlds(const tinygltf::Model& model, int sceneIndex, const glm::dmat4& root,
                            const gltf::ScenePose* pose) {
    gltf::NodeWorlds worlds;
    if (model.skins.empty()) return worlds;
    worlds.transforms.assign(model.nodes.size(), glm::dmat4(1.0));
    worlds.placed.assign(model.nodes.size(), 0);
    gltf::walkSceneNodes(
        model, sceneIndex,
        [&](int node, const glm::dmat4& world) {
            worlds.transforms[static_cast<std::size_t>(node)] = world;
            worlds.placed[static_cast<std::size_t>(node)] = 1;
        },
        root, pose);
    return worlds;
}

} // namespace

namespace gltf {

// The layout at rest, the same for every pose under one instancing mode: which meshes are kept
// once, and the extent that chooses the origin and frames the scene.
struct RestLayout {
    Instancing instancing = Instancing::Auto;
    gltf::InstancingPlan plan;
    std::optional<gltf::WorldExtent> extent;
};

// A frame's still part (WalkPart::Still): the scene as the still walk left it, for the poses of
// the same variant and animations to start from (the instancing mode is the rest layout's).
struct StillPart {
    int materialVariant = -1;
    std::vector<std::size_t> playing;
    Scene scene;
    MeshSlots slots;
};

} // namespace gltf

// What every pose of the file shares: the parsed document, its decoded textures and converted
// materials, and its checked animations; and, kept by the first pose for those after (poses are
// not taken concurrently), the rest layout and a frame's still part.
struct GltfSceneSource::Parsed {
    std::string path;
    tinygltf::Model model;
    Scene base; // sourcePath, textures, images, materials, animations
    gltf::Texcoords texcoords = gltf::Texcoords::Skip;
    int sceneIndex = 0;
    std::vector<gltf::Animation> animations;
    std::optional<gltf::RestLayout> rest;
    std::optional<gltf::StillPart> still;
};

namespace {

std::unique_ptr<GltfSceneSource::Parsed> parse(const std::string& path) {
    auto parsed = std::make_unique<GltfSceneSource::Parsed>();
    parsed->path = path;
    parsed->model = gltf::parseGltfFile(path);
    const tinygltf::Model& model = parsed->model;
    gltf::checkBufferViews(model);
    Scene& scene = parsed->base;
    scene.sourcePath = path;
    gltf::TextureTable textures(model, scene.textures, scene.images);
    scene.materials = gltf::convertMaterials(model, textures);
    scene.materialVariants = gltf::materialVariantNames(model);
    // TEXCOORD_0 is read only to look textures up, or to generate the tangents of an anisotropic
    // material (the direction follows the texture's axes).
    const bool anisotropy = std::any_of(scene.materials.begin(), scene.materials.end(),
                                        [](const SceneMaterial& m) { return m.hasAnisotropy(); });
    parsed->texcoords =
        scene.textures.empty() && !anisotropy ? gltf::Texcoords::Skip : gltf::Texcoords::Read;
    parsed->sceneIndex = gltf::defaultSceneIndex(model);
    parsed->animations = gltf::readAnimations(model);
    scene.animations = summarise(parsed->animations);
    return parsed;
}

// Per node: whether a playing animation moves it, by a translation, rotation or scale channel on
// it or on one of its ancestors in the default scene.
std::vector<char> movingNodes(const tinygltf::Model& model, int sceneIndex,
                              const std::vector<gltf::Animation>& animations,
                              const std::vector<std::size_t>& playing) {
    std::vector<char> animated(model.nodes.size(), 0);
    for (std::size_t a : playing)
        for (const gltf::AnimationChannel& channel : animations[a].channels)
            if (channel.path != gltf::AnimatedPath::Weights && channel.node >= 0 &&
                static_cast<std::size_t>(channel.node) < animated.size())
                animated[static_cast<std::size_t>(channel.node)] = 1;
    // The walk visits parents first: a node moves when it is animated or its parent moves.
    std::vector<char> moving(model.nodes.size(), 0);
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        if (animated[n]) moving[n] = 1;
    gltf::walkSceneNodes(model, sceneIndex, [&](int node, const glm::dmat4&) {
        if (!moving[static_cast<std::size_t>(node)]) return;
        for (int child : model.nodes[static_cast<std::size_t>(node)].children)
            if (child >= 0 && static_cast<std::size_t>(child) < moving.size())
                moving[static_cast<std::size_t>(child)] = 1;
    });
    // Sized by the nodes whether any moves or not: the builder takes a non-empty list as "on".
    return moving;
}

const gltf::RestLayout& restLayout(GltfSceneSource::Parsed& parsed, Instancing instancing) {
    if (parsed.rest && parsed.rest->instancing == instancing) return *parsed.rest;
    parsed.still.reset(); // walked under the plan it replaces
    gltf::RestLayout& rest = parsed.rest.emplace();
    rest.instancing = instancing;
    rest.plan =
        gltf::planInstancing(parsed.model, parsed.sceneIndex, instancing, parsed.base.materials);
    rest.extent = gltf::worldExtent(parsed.model, parsed.sceneIndex, rest.plan, parsed.animations);
    return rest;
}

// The scene before any walk: the file's materials and textures with the variant chosen, at the
// origin the rest extent chooses, and framed by that extent when posed (Scene::framingBounds).
Scene startingScene(const GltfSceneSource::Parsed& parsed, int variant,
                    const std::optional<gltf::WorldExtent>& extent, bool posed) {
    Scene scene = parsed.base;
    scene.materialVariant = variant;
    scene.worldOrigin = extent ? gltf::chooseWorldOrigin(*extent) : glm::dvec3(0.0);
    if (posed && extent)
        scene.framingBounds = Bounds{glm::vec3(extent->min - scene.worldOrigin),
                                     glm::vec3(extent->max - scene.worldOrigin)};
    return scene;
}

// The still part of the poses of `variant` and `playing`: the one kept, or walked now (from this
// pose: a still node is where it is at any time) and kept.
const gltf::StillPart& stillPart(GltfSceneSource::Parsed& parsed, int variant,
                                 const std::vector<std::size_t>& playing,
                                 const gltf::RestLayout& rest, const gltf::ScenePose* pose,
                                 const gltf::NodeWorlds& worlds, const glm::dmat4& root,
                                 const std::vector<char>& moving) {
    if (parsed.still && parsed.still->materialVariant == variant &&
        parsed.still->playing == playing)
        return *parsed.still;
    parsed.still.reset();
    gltf::StillPart still{variant, playing, startingScene(parsed, variant, rest.extent, true), {}};
    SceneBuilder builder(parsed.model, still.scene, parsed.texcoords, rest.plan, pose, worlds,
                         moving, WalkPart::Still);
    gltf::walkSceneNodes(
        parsed.model, parsed.sceneIndex,
        [&](int node, const glm::dmat4& world) { builder.visitNode(node, world); }, root, pose);
    still.slots = builder.meshSlots();
    return parsed.still.emplace(std::move(still));
}

Scene buildScene(GltfSceneSource::Parsed& parsed, const LoadOptions& options) {
    const tinygltf::Model& model = parsed.model;
    const int sceneIndex = parsed.sceneIndex;
    const int variant = gltf::chooseMaterialVariant(parsed.base.materialVariants, options.variant);
    const std::vector<std::size_t> playing =
        gltf::selectAnimations(parsed.animations, options.animation);
    std::optional<gltf::ScenePose> pose;
    if (options.time) pose = gltf::poseAt(model, parsed.animations, playing, *options.time);
    const gltf::ScenePose* posed = pose ? &*pose : nullptr;
    // First the scene's extent in double, so that a far-away scene is recentred before its
    // positions are rounded to float; measured at rest, so that every frame of an animation has
    // the same origin (gltf_origin.h).
    const gltf::RestLayout& rest = restLayout(parsed, options.instancing);
    const std::optional<gltf::WorldExtent>& extent = rest.extent;
    const glm::dvec3 origin = extent ? gltf::chooseWorldOrigin(*extent) : glm::dvec3(0.0);
    const glm::dmat4 root = glm::translate(glm::dmat4(1.0), -origin);
    const gltf::NodeWorlds worlds = nodeWorlds(model, sceneIndex, root, posed);
    Scene scene;
    if (options.keepMovingApart && pose) {
        // The still part read once for every frame; this frame walks what moves.
        std::vector<char> moving = movingNodes(model, sceneIndex, parsed.animations, playing);
        const gltf::StillPart& still =
            stillPart(parsed, variant, playing, rest, posed, worlds, root, moving);
        scene = still.scene;
        SceneBuilder builder(model, scene, parsed.texcoords, rest.plan, posed, worlds,
                             std::move(moving), WalkPart::Moving, still.slots);
        gltf::walkSceneNodes(
            model, sceneIndex,
            [&](int node, const glm::dmat4& world) { builder.visitNode(node, world); }, root,
            posed);
    } else {
        scene = startingScene(parsed, variant, extent, pose.has_value());
        SceneBuilder builder(model, scene, parsed.texcoords, rest.plan, posed, worlds, {});
        gltf::walkSceneNodes(
            model, sceneIndex,
            [&](int node, const glm::dmat4& world) { builder.visitNode(node, world); }, root,
            posed);
    }
    if (scene.triangleCount() == 0 && scene.instances.empty() && scene.spheres.empty()) {
        throw GltfProblem(noTrianglesMessage(scene));
    }
    std::vector<std::string> notes = loadNotes(model, options);
    for (const std::string& note : geometryNotes(scene, extent))
        notes.push_back(note);
    for (const std::string& note : notes)
        std::cerr << parsed.path << ": " << note << '\n';
    return scene;
}

} // namespace

GltfSceneSource::GltfSceneSource(const std::string& path) {
    try {
        parsed_ = parse(path);
    } catch (const GltfProblem& problem) {
        throw InputError(path + ": " + problem.what());
    }
}

GltfSceneSource::~GltfSceneSource() = default;
GltfSceneSource::GltfSceneSource(GltfSceneSource&&) noexcept = default;

const std::string& GltfSceneSource::path() const {
    return parsed_->path;
}

Scene GltfSceneSource::pose(const LoadOptions& options) const {
    try {
        return buildScene(*parsed_, options);
    } catch (const GltfProblem& problem) {
        throw InputError(parsed_->path + ": " + problem.what());
    }
}

Scene loadGltfScene(const std::string& path, const LoadOptions& options) {
    return GltfSceneSource(path).pose(options);
}

} // namespace vkpt
