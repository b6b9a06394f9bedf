// gltf_loader.cpp — the loading pipeline: parse the file, check extensions and buffer views,
// convert the materials (decoding the textures they use), walk the default scene collecting
// triangles, spheres, lights and cameras, then say what was ignored.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "common/errors.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_cameras.h"
#include "scene/gltf_document.h"
#include "scene/gltf_lights.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_nodes.h"
#include "scene/gltf_origin.h"
#include "scene/gltf_primitives.h"
#include "scene/gltf_shapes.h"
#include "scene/gltf_textures.h"

namespace vkpt {
namespace {

using gltf::GltfProblem;

// Extensions that change what vkpt renders and that it implements. (KHR_implicit_shapes only
// for spheres, gltf_shapes.cpp; KHR_materials_specular without its textures;
// KHR_materials_clearcoat without its clearcoatNormalTexture.)
const std::vector<std::string> kSupportedExtensions = {"KHR_materials_emissive_strength",
                                                       "KHR_materials_specular",
                                                       "KHR_materials_clearcoat",
                                                       "KHR_materials_sheen",
                                                       "KHR_texture_transform",
                                                       "KHR_lights_punctual",
                                                       "KHR_implicit_shapes"};

bool isSupported(const std::string& extension) {
    return std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), extension) !=
           kSupportedExtensions.end();
}

// An extension the file requires changes the meaning of the data; rendering without it would
// give a silently wrong image.
void checkRequiredExtensions(const tinygltf::Model& model) {
    for (const std::string& extension : model.extensionsRequired) {
        if (!isSupported(extension)) {
            throw GltfProblem("required extension " + extension + " is not supported");
        }
    }
}

std::vector<std::string> ignoredExtensions(const tinygltf::Model& model) {
    std::vector<std::string> ignored;
    for (const std::string& extension : model.extensionsUsed) {
        if (!isSupported(extension) &&
            std::find(ignored.begin(), ignored.end(), extension) == ignored.end()) {
            ignored.push_back(extension);
        }
    }
    return ignored;
}

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

// Collects the triangles, spheres, lights and cameras of the nodes the walk visits.
class SceneBuilder {
public:
    SceneBuilder(const tinygltf::Model& model, Scene& scene, gltf::Texcoords texcoords)
        : model_(model), scene_(scene), texcoords_(texcoords) {}

    void visitNode(int nodeIndex, const glm::dmat4& world) {
        const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(nodeIndex)];
        if (node.mesh != -1) appendMesh(nodeIndex, node.mesh, world);
        if (node.camera != -1) appendCamera(nodeIndex, world);
        if (std::optional<SceneLight> light = gltf::placeLight(model_, nodeIndex, world)) {
            scene_.lights.push_back(std::move(*light));
        }
        if (const std::optional<gltf::WorldSphere> sphere =
                gltf::placeSphere(model_, nodeIndex, world)) {
            appendSphere(nodeIndex, *sphere);
        }
    }

    int orthographicCameras() const { return orthographicCameras_; }

private:
    void appendMesh(int nodeIndex, int meshIndex, const glm::dmat4& world) {
        if (meshIndex < 0 || static_cast<std::size_t>(meshIndex) >= model_.meshes.size()) {
            throw GltfProblem("node " + std::to_string(nodeIndex) + ": mesh " +
                              std::to_string(meshIndex) + " does not exist (the file has " +
                              std::to_string(model_.meshes.size()) + " meshes)");
        }
        const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(meshIndex)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string where =
                "mesh " + std::to_string(meshIndex) + ", primitive " + std::to_string(p);
            const tinygltf::Primitive& primitive = mesh.primitives[p];
            gltf::appendPrimitiveTriangles(model_, primitive, world,
                                           materialIndex(primitive.material, where), texcoords_,
                                           where, scene_);
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
        if (std::optional<SceneCamera> camera = gltf::placeCamera(model_, nodeIndex, world)) {
            scene_.cameras.push_back(std::move(*camera));
        } else {
            ++orthographicCameras_;
        }
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
    std::optional<std::uint32_t> defaultMaterial_;
    int orthographicCameras_ = 0;
};

std::string formatPoint(const glm::dvec3& p) {
    return "(" + formatNumber(p.x) + ", " + formatNumber(p.y) + ", " + formatNumber(p.z) + ")";
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
    return notes;
}

// What the load ignored or changed, said once it has succeeded, so that a failing load prints
// one line.
std::vector<std::string> loadNotes(const tinygltf::Model& model, int orthographicCameras,
                                   const LoadOptions& options) {
    std::vector<std::string> notes = gltf::materialNotes(model);
    const std::vector<std::string> ignored = ignoredExtensions(model);
    if (options.warnUnsupportedExtensions && !ignored.empty()) {
        notes.push_back("ignoring unsupported extensions: " + joinNames(ignored));
    }
    if (orthographicCameras > 0) {
        notes.push_back("ignoring " + std::to_string(orthographicCameras) + " orthographic " +
                        (orthographicCameras == 1 ? "camera" : "cameras") +
                        " (only perspective cameras are supported)");
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

Scene buildScene(const std::string& path, const LoadOptions& options) {
    const tinygltf::Model model = gltf::parseGltfFile(path);
    checkRequiredExtensions(model);
    gltf::checkBufferViews(model);
    Scene scene;
    scene.sourcePath = path;
    gltf::TextureTable textures(model, scene.textures, scene.images);
    scene.materials = gltf::convertMaterials(model, textures);
    // TEXCOORD_0 is read only to look textures up.
    const gltf::Texcoords texcoords =
        scene.textures.empty() ? gltf::Texcoords::Skip : gltf::Texcoords::Read;
    const int sceneIndex = gltf::defaultSceneIndex(model);
    // First the scene's extent in double, so that a far-away scene is recentred before its
    // positions are rounded to float.
    const std::optional<gltf::WorldExtent> extent = gltf::worldExtent(model, sceneIndex);
    scene.worldOrigin = extent ? gltf::chooseWorldOrigin(*extent) : glm::dvec3(0.0);
    SceneBuilder builder(model, scene, texcoords);
    gltf::walkSceneNodes(
        model, sceneIndex,
        [&](int node, const glm::dmat4& world) { builder.visitNode(node, world); },
        glm::translate(glm::dmat4(1.0), -scene.worldOrigin));
    if (scene.triangleCount() == 0 && scene.spheres.empty()) {
        throw GltfProblem(noTrianglesMessage(scene));
    }
    std::vector<std::string> notes = loadNotes(model, builder.orthographicCameras(), options);
    for (const std::string& note : geometryNotes(scene, extent))
        notes.push_back(note);
    for (const std::string& note : notes)
        std::cerr << path << ": " << note << '\n';
    return scene;
}

} // namespace

Scene loadGltfScene(const std::string& path, const LoadOptions& options) {
    try {
        return buildScene(path, options);
    } catch (const GltfProblem& problem) {
        throw InputError(path + ": " + problem.what());
    }
}

} // namespace vkpt
