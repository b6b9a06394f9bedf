// scene.h — the loaded scene as plain structs: world-space triangles, materials, cameras.
// No Vulkan and no BVH here; everything downstream starts from this.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt {

enum class AlphaMode : std::uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

struct SceneMaterial {
    std::string name;
    glm::vec4 baseColor{1.0f}; // linear RGBA
    glm::vec3 emission{0.0f};  // emissiveFactor × KHR_materials_emissive_strength
    float metallic = 1.0f;     // glTF defaults
    float roughness = 1.0f;
    bool doubleSided = false;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
};

// A perspective camera placed by the node tree. forward and up are unit and orthogonal.
struct SceneCamera {
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float yfov = 0.8f; // vertical field of view, radians
};

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};
};

// What the loader repaired or left out of the file's geometry, counted so that it can say so
// (docs/numerical-stability.md, "Degenerate geometry").
struct GeometryRepairs {
    std::size_t zeroAreaTriangles = 0; // skipped: no area in float, so no ray can hit them
    std::size_t invalidNormals = 0;    // zero-length or non-finite vertex normals: face normal used
};

// A triangle soup in world space: triangle i has vertices positions[3i .. 3i+2] (counter-
// clockwise seen from its front face), shading normals normals[3i .. 3i+2] and material
// materialIndices[i].
struct Scene {
    std::string sourcePath;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> materialIndices;
    std::vector<SceneMaterial> materials;
    std::vector<SceneCamera> cameras; // perspective ones, in depth-first node-walk order
    // The file's world-space point that positions and cameras are measured from. The loader
    // moves it to the centre of a scene that lies far from the origin (relative to its size),
    // so that floats keep their precision there; rendering does not depend on it.
    glm::dvec3 worldOrigin{0.0};
    GeometryRepairs repairs;

    std::size_t triangleCount() const { return materialIndices.size(); }
};

Bounds computeBounds(const Scene& scene);

} // namespace vkpt
