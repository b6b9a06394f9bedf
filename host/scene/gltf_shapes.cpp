// gltf_shapes.cpp — which nodes are rendered as analytic spheres, and where.
//
// How a glTF file asks vkpt for a sphere
// ---------------------------------------
// KHR_implicit_shapes (a draft Khronos extension) lists shapes at the document level,
//     "extensions": {"KHR_implicit_shapes": {"shapes": [{"type": "sphere",
//                                                        "sphere": {"radius": 0.5}}]}}
// a sphere of that radius (default 0.5, must be > 0) centred at the origin of the local space of
// whatever references it. The extension gives shapes no meaning of their own; others reference
// them. vkpt renders a sphere for a node that references a sphere shape in one of two ways:
//   1. node.extensions.KHR_implicit_shapes = {"shape": s} — vkpt's own use of the extension
//      (no Khronos extension references shapes for rendering). Any node may do this, with or
//      without a mesh; a shape that is not a sphere is an error here, since the file asks for
//      something to be drawn that vkpt cannot draw.
//   2. node.extensions.KHR_physics_rigid_bodies.collider.geometry.shape = s — a physics
//      collider, drawn only when the node has no mesh: a collider on a node with a mesh stands in
//      for that mesh, which is what is seen. Colliders of other shape types, and triggers, are
//      physics only and are not drawn.
// The sphere's material is node.extras.vkpt_material (an index into the file's materials) when
// present, else the glTF default material. extras is where glTF puts application-specific data
// (glTF 2.0, section 3.12); the name is prefixed so that it cannot clash with other tools'.
// The node's world transform places the sphere: its centre is the image of the local origin and
// its radius the shape's radius times the transform's scale, which must be uniform (a sphere
// under a non-uniform scale is an ellipsoid, an error); a negative scale counts by its absolute
// value and a scale of zero on every axis disables the shape (KHR_physics_rigid_bodies,
// "Geometry").
#include "scene/gltf_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "scene/gltf_document.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kImplicitShapes = "KHR_implicit_shapes";
constexpr const char* kRigidBodies = "KHR_physics_rigid_bodies";
constexpr const char* kMaterialKey = "vkpt_material";

// Quaternions and matrices in files are rounded to float, so a rotation's columns differ from
// unit length by a few 1e-7; a real non-uniform scale differs by far more.
constexpr double kUniformTolerance = 1e-5;

struct ShapeReference {
    int shape = -1;
    bool explicitRequest = false; // rule 1: vkpt's own reference; rule 2: a collider
};

std::optional<ShapeReference> shapeReference(const tinygltf::Node& node, int nodeIndex) {
    const std::string where = nodeName(nodeIndex);
    if (const tinygltf::Value* own = findExtension(node.extensions, kImplicitShapes)) {
        const int shape = readIndex(*own, "shape", where + ": " + kImplicitShapes);
        if (shape < 0) throw GltfProblem(where + ": " + kImplicitShapes + ": no shape index");
        return ShapeReference{shape, true};
    }
    if (node.mesh != -1) return std::nullopt;
    const tinygltf::Value* bodies = findExtension(node.extensions, kRigidBodies);
    const tinygltf::Value* collider = bodies ? findMember(*bodies, "collider") : nullptr;
    const tinygltf::Value* geometry = collider ? findMember(*collider, "geometry") : nullptr;
    if (geometry == nullptr) return std::nullopt;
    const int shape =
        readIndex(*geometry, "shape", where + ": " + kRigidBodies + " collider geometry");
    if (shape < 0) return std::nullopt; // a mesh collider (geometry.node)
    return ShapeReference{shape, false};
}

const tinygltf::Value& findShape(const tinygltf::Model& model, int shape, int nodeIndex) {
    static const tinygltf::Value kNone;
    const tinygltf::Value* document = findExtension(model.extensions, kImplicitShapes);
    const tinygltf::Value* shapes = document ? findMember(*document, "shapes") : nullptr;
    return arrayElement(shapes ? *shapes : kNone, shape, "implicit shape", nodeName(nodeIndex));
}

double sphereRadius(const tinygltf::Value& shape, int shapeIndex) {
    const std::string where = std::string(kImplicitShapes) + " shape " + std::to_string(shapeIndex);
    const tinygltf::Value* sphere = findMember(shape, "sphere");
    const double radius = sphere ? readNumber(*sphere, "radius", 0.5, where + ": sphere") : 0.5;
    if (!(radius > 0.0)) throw GltfProblem(where + ": sphere radius must be > 0");
    return radius;
}

std::string formatScale(const glm::dvec3& scale) {
    char text[96];
    std::snprintf(text, sizeof(text), "(%.6g, %.6g, %.6g)", scale.x, scale.y, scale.z);
    return text;
}

// The factor by which `world` scales every length, when it scales them all alike: its linear
// part must be a rotation (or reflection) times that factor, so its columns are orthogonal and
// of one length. 0 for a transform that collapses everything (a disabled shape).
double uniformScale(const glm::dmat4& world, int nodeIndex) {
    const glm::dmat3 linear(world);
    const glm::dvec3 lengths(glm::length(linear[0]), glm::length(linear[1]),
                             glm::length(linear[2]));
    const double largest = std::max(lengths.x, std::max(lengths.y, lengths.z));
    if (largest == 0.0) return 0.0;
    const double smallest = std::min(lengths.x, std::min(lengths.y, lengths.z));
    const double skew = std::max(std::abs(glm::dot(linear[0], linear[1])),
                                 std::max(std::abs(glm::dot(linear[1], linear[2])),
                                          std::abs(glm::dot(linear[2], linear[0]))));
    if (!std::isfinite(largest) || largest - smallest > kUniformTolerance * largest ||
        skew > kUniformTolerance * largest * largest) {
        throw GltfProblem(nodeName(nodeIndex) + ": sphere under non-uniform scale " +
                          formatScale(lengths));
    }
    return (lengths.x + lengths.y + lengths.z) / 3.0;
}

int sphereMaterial(const tinygltf::Model& model, const tinygltf::Node& node, int nodeIndex) {
    const std::string where = nodeName(nodeIndex) + ": extras";
    const int material = readIndex(node.extras, kMaterialKey, where);
    if (material >= 0 && static_cast<std::size_t>(material) >= model.materials.size()) {
        throw GltfProblem(where + ": " + kMaterialKey + " " + std::to_string(material) +
                          " does not exist (the file has " +
                          std::to_string(model.materials.size()) + " materials)");
    }
    return material;
}

} // namespace

std::optional<WorldSphere> placeSphere(const tinygltf::Model& model, int nodeIndex,
                                       const glm::dmat4& world) {
    const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(nodeIndex)];
    const std::optional<ShapeReference> reference = shapeReference(node, nodeIndex);
    if (!reference) return std::nullopt;
    const tinygltf::Value& shape = findShape(model, reference->shape, nodeIndex);
    const std::string type =
        readString(shape, "type", "",
                   std::string(kImplicitShapes) + " shape " + std::to_string(reference->shape));
    if (type != "sphere") {
        if (!reference->explicitRequest) return std::nullopt; // a physics-only collider
        throw GltfProblem(nodeName(nodeIndex) + ": implicit shape " +
                          std::to_string(reference->shape) + " is a " +
                          (type.empty() ? std::string("shape without type") : type) +
                          "; only spheres are rendered");
    }
    const double radius = sphereRadius(shape, reference->shape);
    const double scale = uniformScale(world, nodeIndex);
    if (scale == 0.0) return std::nullopt;
    WorldSphere sphere;
    sphere.centre = glm::dvec3(world[3]);
    sphere.radius = radius * scale;
    sphere.material = sphereMaterial(model, node, nodeIndex);
    if (!std::isfinite(sphere.centre.x + sphere.centre.y + sphere.centre.z + sphere.radius)) {
        throw GltfProblem(nodeName(nodeIndex) + ": the sphere's centre or radius is not finite");
    }
    return sphere;
}

} // namespace vkpt::gltf
