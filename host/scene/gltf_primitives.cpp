// gltf_primitives.cpp — reads a primitive's attributes and indices, checks them, and emits
// triangles in world space.
#include "scene/gltf_primitives.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <span>
#include <utility>

#include "scene/gltf_accessors.h"
#include "scene/gltf_document.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_morph.h"
#include "scene/gltf_skins.h"
#include "scene/tangents.h"

namespace vkpt::gltf {
namespace {

// A primitive's vertices in world space, and the corner order of its triangles.
struct WorldGeometry {
    std::vector<glm::vec3> positions;
    std::optional<std::vector<glm::vec3>> normals; // nullopt: generate flat normals
    std::vector<std::uint32_t> indices;
    bool mirrored = false; // the transform has a negative determinant
    bool withTexcoords = false;
    std::optional<std::vector<glm::vec2>> texcoords; // nullopt: (0, 0) at every vertex
    Tangents tangentMode = Tangents::Skip;
    std::optional<std::vector<glm::vec4>> tangents; // Read: nullopt generates them
};

const char* modeName(int mode) {
    switch (mode) {
    case TINYGLTF_MODE_POINTS:
        return "POINTS";
    case TINYGLTF_MODE_LINE:
        return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
        return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
        return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_STRIP:
        return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN:
        return "TRIANGLE_FAN";
    default:
        return nullptr;
    }
}

void requireTriangles(int mode, const std::string& where) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return;
    const char* name = modeName(mode);
    if (name == nullptr) {
        throw GltfProblem(where + ": mode " + std::to_string(mode) +
                          " is not a glTF primitive mode");
    }
    throw GltfProblem(where + ": mode " + name + " is not supported, only TRIANGLES");
}

std::optional<int> attributeAccessor(const tinygltf::Primitive& primitive, const char* name) {
    const auto attribute = primitive.attributes.find(name);
    if (attribute == primitive.attributes.end()) return std::nullopt;
    return attribute->second;
}

bool isFinite(const glm::vec3& v) {
    return !glm::any(glm::isnan(v)) && !glm::any(glm::isinf(v));
}

// A primitive's vertices as stored (from accessors or decoded from Draco), before the node
// transform.
struct LocalVertices {
    std::vector<glm::vec3> positions;
    std::optional<std::vector<glm::vec3>> normals;
    std::optional<std::vector<glm::vec2>> texcoords;
    std::optional<std::vector<glm::vec4>> tangents; // the file's TANGENT, when asked for
    std::vector<std::uint32_t> indices;
    bool indexed = false; // indices came from the file, not 0, 1, 2, ...
};

void transformPositions(std::vector<glm::vec3>& positions, const glm::dmat4& world,
                        const std::string& where) {
    for (std::size_t i = 0; i < positions.size(); ++i) {
        // Transform in double: scenes such as ToyCar scale by 1e-4 in the node tree.
        positions[i] = glm::vec3(world * glm::dvec4(glm::dvec3(positions[i]), 1.0));
        if (!isFinite(positions[i])) {
            throw GltfProblem(where + ": vertex " + std::to_string(i) +
                              " has a non-finite position");
        }
    }
}

// Normals transform by the inverse transpose of the linear part. The cofactor matrix is that
// times the determinant, so it exists even for a singular transform; flipping its sign for a
// negative determinant keeps each normal on the side of the surface it was on.
glm::dmat3 normalMatrix(const glm::dmat3& m) {
    const glm::dmat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]),
                              glm::cross(m[0], m[1]));
    return glm::determinant(m) < 0.0 ? -cofactor : cofactor;
}

void transformNormals(std::vector<glm::vec3>& normals, const glm::dmat4& world) {
    const glm::dmat3 transform = normalMatrix(glm::dmat3(world));
    for (glm::vec3& normal : normals)
        normal = glm::vec3(transform * glm::dvec3(normal));
}

// TANGENT in world space: xyz by the transform's linear part (tangents lie along the surface,
// like edges), w = ±1 flipped by a mirroring transform, since the world normals keep their side
// (normalMatrix) while cross(n, t) turns over. nullopt when some tangent is zero or not finite:
// the primitive's frames are generated instead.
std::optional<std::vector<glm::vec4>> worldTangents(std::vector<glm::vec4> tangents,
                                                    const glm::dmat4& world) {
    const glm::dmat3 linear(world);
    const double mirror = glm::determinant(linear) < 0.0 ? -1.0 : 1.0;
    for (glm::vec4& tangent : tangents) {
        const glm::dvec3 t = linear * glm::dvec3(glm::vec3(tangent));
        const double length = glm::length(t);
        if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(tangent.w)) {
            return std::nullopt;
        }
        tangent = glm::vec4(glm::vec3(t / length), tangent.w < 0.0f ? -mirror : mirror);
    }
    return tangents;
}

void checkAttributeCount(std::size_t count, const char* attribute, std::size_t vertexCount,
                         const std::string& where) {
    if (count == vertexCount) return;
    throw GltfProblem(where + ": " + attribute + " has " + std::to_string(count) +
                      " elements but POSITION has " + std::to_string(vertexCount));
}

// TEXCOORD_0 as stored: texture coordinates do not depend on the node transform. A NaN would
// become a texel index on the GPU, so non-finite values are rejected.
void checkTexcoords(const std::vector<glm::vec2>& texcoords, std::size_t vertexCount,
                    const std::string& where) {
    if (texcoords.size() != vertexCount) {
        throw GltfProblem(where + ": TEXCOORD_0 has " + std::to_string(texcoords.size()) +
                          " elements but POSITION has " + std::to_string(vertexCount));
    }
    for (std::size_t i = 0; i < texcoords.size(); ++i) {
        if (!std::isfinite(texcoords[i].x) || !std::isfinite(texcoords[i].y)) {
            throw GltfProblem(where + ": vertex " + std::to_string(i) +
                              " has a non-finite TEXCOORD_0");
        }
    }
}

void checkTriangleIndices(const LocalVertices& vertices, const std::string& where) {
    const std::size_t vertexCount = vertices.positions.size();
    if (vertices.indices.size() % 3 != 0) {
        throw GltfProblem(where + ": " + std::to_string(vertices.indices.size()) +
                          (vertices.indexed ? " indices" : " vertices") +
                          " do not make whole triangles");
    }
    for (std::uint32_t index : vertices.indices) {
        if (index >= vertexCount) {
            throw GltfProblem(where + ": index " + std::to_string(index) + " >= vertex count " +
                              std::to_string(vertexCount));
        }
    }
}

// The attributes not decoded from Draco are read from their accessors, as
// KHR_draco_mesh_compression allows for attributes it does not list.
void readRemainingAttributes(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                             bool withTexcoords, const std::string& where,
                             LocalVertices& vertices) {
    if (const std::optional<int> normal = attributeAccessor(primitive, "NORMAL");
        normal && !vertices.normals) {
        vertices.normals = readNormals(model, *normal, where + ": NORMAL");
    }
    if (const std::optional<int> texcoord = attributeAccessor(primitive, "TEXCOORD_0");
        texcoord && withTexcoords && !vertices.texcoords) {
        vertices.texcoords = readTexcoords(model, *texcoord, where + ": TEXCOORD_0");
    }
}

LocalVertices readDracoVertices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                bool withTexcoords, const std::string& where) {
    DracoPrimitive decoded = decodeDracoPrimitive(model, primitive, withTexcoords, where);
    LocalVertices vertices;
    vertices.positions = std::move(decoded.positions);
    vertices.normals = std::move(decoded.normals);
    vertices.texcoords = std::move(decoded.texcoords);
    vertices.indices = std::move(decoded.indices);
    vertices.indexed = true;
    return vertices;
}

LocalVertices readAccessorVertices(const tinygltf::Model& model,
                                   const tinygltf::Primitive& primitive, const std::string& where) {
    const std::optional<int> position = attributeAccessor(primitive, "POSITION");
    if (!position) throw GltfProblem(where + ": no POSITION attribute");
    LocalVertices vertices;
    vertices.positions = readPositions(model, *position, where + ": POSITION");
    vertices.indexed = primitive.indices >= 0;
    if (vertices.indexed) {
        vertices.indices = readIndices(model, primitive.indices, where + ": indices");
    } else {
        vertices.indices.resize(vertices.positions.size());
        std::iota(vertices.indices.begin(), vertices.indices.end(), 0u);
    }
    return vertices;
}

// A Draco primitive's TANGENT, if any, is inside the compressed data, which the decoder does
// not map; its frames are generated instead, as for a file without TANGENT.
LocalVertices readLocalVertices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                bool withTexcoords, Tangents tangents, const std::string& where) {
    const bool draco = isDracoPrimitive(primitive);
    LocalVertices vertices = draco ? readDracoVertices(model, primitive, withTexcoords, where)
                                   : readAccessorVertices(model, primitive, where);
    readRemainingAttributes(model, primitive, withTexcoords, where, vertices);
    const std::size_t vertexCount = vertices.positions.size();
    if (vertices.normals)
        checkAttributeCount(vertices.normals->size(), "NORMAL", vertexCount, where);
    if (const std::optional<int> tangent = attributeAccessor(primitive, "TANGENT");
        tangent && tangents == Tangents::Read && !draco) {
        vertices.tangents = readTangents(model, *tangent, where + ": TANGENT");
        checkAttributeCount(vertices.tangents->size(), "TANGENT", vertexCount, where);
    }
    return vertices;
}

// Morph targets and skins move the vertices in the file's order, which a Draco primitive's
// decoded vertices do not keep.
void deform(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
            const Deformation& deformation, LocalVertices& vertices, const std::string& where,
            GeometryRepairs& repairs) {
    const bool morphed = !deformation.morphWeights.empty() && !primitive.targets.empty();
    const bool skinned = deformation.joints != nullptr;
    if (!morphed && !skinned) return;
    if (isDracoPrimitive(primitive)) {
        const bool moves =
            skinned || std::any_of(deformation.morphWeights.begin(), deformation.morphWeights.end(),
                                   [](double w) { return w != 0.0; });
        if (!moves) return;
        throw GltfProblem(where + ": morph targets and skins of Draco primitives are not "
                                  "supported");
    }
    std::vector<glm::vec3>* normals = vertices.normals ? &*vertices.normals : nullptr;
    std::vector<glm::vec4>* tangents = vertices.tangents ? &*vertices.tangents : nullptr;
    if (morphed) {
        applyMorphTargets(model, primitive, deformation.morphWeights,
                          {vertices.positions, normals, tangents}, where);
    }
    if (skinned) {
        skinVertices(model, primitive, *deformation.joints, {vertices.positions, normals, tangents},
                     where, repairs);
    }
}

WorldGeometry readWorldGeometry(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                const glm::dmat4& world, Texcoords texcoords, Tangents tangents,
                                const Deformation& deformation, const std::string& where,
                                GeometryRepairs& repairs) {
    WorldGeometry geometry;
    geometry.withTexcoords = texcoords == Texcoords::Read;
    LocalVertices vertices =
        readLocalVertices(model, primitive, geometry.withTexcoords, tangents, where);
    const std::size_t vertexCount = vertices.positions.size();
    deform(model, primitive, deformation, vertices, where, repairs);
    transformPositions(vertices.positions, world, where);
    if (vertices.normals) transformNormals(*vertices.normals, world);
    if (vertices.texcoords) checkTexcoords(*vertices.texcoords, vertexCount, where);
    checkTriangleIndices(vertices, where);
    geometry.positions = std::move(vertices.positions);
    geometry.normals = std::move(vertices.normals);
    geometry.texcoords = std::move(vertices.texcoords);
    geometry.indices = std::move(vertices.indices);
    geometry.tangentMode = tangents;
    if (vertices.tangents) geometry.tangents = worldTangents(std::move(*vertices.tangents), world);
    geometry.mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    return geometry;
}

// v / |v| without overflow or underflow in |v|²: scaled by its largest component first, so a
// needle's face normal of length 1e-30 or a huge triangle's of 1e30 still comes out unit.
// Returns the zero vector when v is zero or not finite.
glm::vec3 unitVector(const glm::vec3& v) {
    const glm::vec3 a = glm::abs(v);
    const float largest = std::max(a.x, std::max(a.y, a.z));
    if (!(largest > 0.0f) || !std::isfinite(largest)) return glm::vec3(0.0f);
    const glm::vec3 scaled = v / largest;
    return scaled / glm::length(scaled);
}

// A zero or non-finite normal in the file must still give a unit vector: a NaN in the normals
// buffer would spread through every path that touches it. Counted once per vertex.
void repairNormals(std::vector<glm::vec3>& normals, GeometryRepairs& repairs) {
    for (glm::vec3& normal : normals) {
        const glm::vec3 unit = unitVector(normal);
        if (unit == glm::vec3(0.0f)) ++repairs.invalidNormals;
        normal = unit; // zero: replaced by the face normal per triangle
    }
}

void appendTriangle(const WorldGeometry& geometry, std::size_t first, std::uint32_t materialIndex,
                    TriangleSoup& soup, GeometryRepairs& repairs) {
    std::uint32_t corners[3] = {geometry.indices[first], geometry.indices[first + 1],
                                geometry.indices[first + 2]};
    if (geometry.mirrored) std::swap(corners[1], corners[2]);
    const glm::vec3& p0 = geometry.positions[corners[0]];
    const glm::vec3& p1 = geometry.positions[corners[1]];
    const glm::vec3& p2 = geometry.positions[corners[2]];
    // No area in float (repeated or collinear vertices): no watertight test can hit it and it
    // has no normal; leaving it out is exact. (A cross product beyond the float range, at
    // coordinates near 1e19, lands here too: such a triangle is past what floats can render.)
    const glm::vec3 flat = unitVector(glm::cross(p1 - p0, p2 - p0));
    if (flat == glm::vec3(0.0f)) {
        ++repairs.zeroAreaTriangles;
        return;
    }
    for (std::uint32_t corner : corners) {
        soup.positions.push_back(geometry.positions[corner]);
        const glm::vec3 normal = geometry.normals ? (*geometry.normals)[corner] : flat;
        soup.normals.push_back(normal == glm::vec3(0.0f) ? flat : normal);
        if (geometry.withTexcoords) {
            soup.texcoords.push_back(geometry.texcoords ? (*geometry.texcoords)[corner]
                                                        : glm::vec2(0.0f));
        }
        if (geometry.tangentMode == Tangents::Zero) soup.tangents.emplace_back(0.0f);
        if (geometry.tangentMode == Tangents::Read && geometry.tangents) {
            soup.tangents.push_back((*geometry.tangents)[corner]);
        }
    }
    soup.materialIndices.push_back(materialIndex);
}

// MikkTSpace frames for the corners from firstCorner on, as they were appended: world-space
// positions, the final shading normals and TEXCOORD_0.
void appendGeneratedTangents(std::size_t firstCorner, TriangleSoup& soup) {
    const std::size_t count = soup.positions.size() - firstCorner;
    const std::span<const glm::vec3> positions(soup.positions.data() + firstCorner, count);
    const std::span<const glm::vec3> normals(soup.normals.data() + firstCorner, count);
    const std::span<const glm::vec2> texcoords(soup.texcoords.data() + firstCorner, count);
    const std::vector<glm::vec4> generated = generateTangents(positions, normals, texcoords);
    soup.tangents.insert(soup.tangents.end(), generated.begin(), generated.end());
}

} // namespace

void appendPrimitiveTriangles(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                              const glm::dmat4& world, std::uint32_t materialIndex,
                              Texcoords texcoords, Tangents tangents, const std::string& where,
                              TriangleSoup& soup, GeometryRepairs& repairs,
                              const Deformation& deformation) {
    requireTriangles(primitive.mode, where);
    WorldGeometry geometry = readWorldGeometry(model, primitive, world, texcoords, tangents,
                                               deformation, where, repairs);
    if (geometry.normals) repairNormals(*geometry.normals, repairs);
    const std::size_t firstCorner = soup.positions.size();
    for (std::size_t first = 0; first < geometry.indices.size(); first += 3) {
        appendTriangle(geometry, first, materialIndex, soup, repairs);
    }
    if (tangents == Tangents::Read && !geometry.tangents)
        appendGeneratedTangents(firstCorner, soup);
}

} // namespace vkpt::gltf
