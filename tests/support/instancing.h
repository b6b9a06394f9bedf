// instancing.h — two-level scenes built in memory for tests: meshes placed by random transforms
// (turned, scaled unevenly, mirrored, some placed twice at the very same place), and any scene
// turned into a two-level one whose single mesh, placed by a given transform, holds all of its
// non-emitting triangles (the same scene: instanced = flattened at the same seed).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "bvh/synthetic_scenes.h"
#include "scene/scene.h"

namespace vkpt::test {

// A soup with flat normals from three positions per triangle, all of one material.
inline SceneMesh meshOfSoup(const std::vector<glm::vec3>& positions, std::uint32_t material) {
    SceneMesh mesh;
    for (std::size_t i = 0; i + 2 < positions.size(); i += 3) {
        const glm::vec3 n =
            glm::cross(positions[i + 1] - positions[i], positions[i + 2] - positions[i]);
        const float length = glm::length(n);
        if (!(length > 0.0f)) continue; // the loader leaves zero-area triangles out
        for (std::size_t k = 0; k < 3; ++k) {
            mesh.positions.push_back(positions[i + k]);
            mesh.normals.push_back(n / length);
        }
        mesh.materialIndices.push_back(material);
    }
    return mesh;
}

// A random affine placement: turned about a random axis, scaled by 0.5–2 per axis (mirrored in x
// when asked), moved within [-extent, extent]^3.
inline glm::dmat4 randomPlacement(synthetic::Rng& rng, float extent, bool mirrored) {
    const glm::vec3 axis = rng.unitVector();
    const double angle = rng.uniform(0.0f, 6.2831853f);
    glm::dvec3 scale(rng.uniform(0.5f, 2.0f), rng.uniform(0.5f, 2.0f), rng.uniform(0.5f, 2.0f));
    if (mirrored) scale.x = -scale.x;
    const glm::dvec3 at(rng.inBox(glm::vec3(-extent), glm::vec3(extent)));
    return glm::scale(glm::rotate(glm::translate(glm::dmat4(1.0), at), angle, glm::dvec3(axis)),
                      scale);
}

// `meshes` placed `placementsPerMesh` times each by randomPlacement (every third mirrored), the
// first placement of every mesh twice at the same place (crossings that tie exactly, decided by
// the lower instance), with a few triangles of the scene's own beside them.
inline Scene randomInstancedScene(const std::vector<std::vector<glm::vec3>>& meshes,
                                  std::uint32_t placementsPerMesh, std::uint32_t seed) {
    Scene scene;
    SceneMaterial material;
    material.metallic = 0.0f;
    material.specular = 0.0f;
    scene.materials.push_back(material);
    synthetic::Rng rng(seed);
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        scene.meshes.push_back(meshOfSoup(meshes[m], 0));
        for (std::uint32_t p = 0; p < placementsPerMesh; ++p) {
            const glm::dmat4 placement = randomPlacement(rng, 20.0f, p % 3 == 2);
            scene.instances.push_back({std::uint32_t(m), placement});
            if (p == 0) scene.instances.push_back({std::uint32_t(m), placement});
        }
    }
    const SceneMesh own = meshOfSoup(synthetic::randomSoup(64, seed + 1, 40.0f, 3.0f), 0);
    static_cast<TriangleSoup&>(scene) = own;
    return scene;
}

// The scene with its non-emitting triangles moved into one mesh placed by `transform`: their
// positions mapped by its inverse (in double), normals and tangents as the loader would read a
// file whose node carries `transform` (tangent w flipped by a mirror), and a mirrored
// transform's corners stored in swapped order, as a file's would be, so that the placed front
// face is the original one. Emitting triangles stay where they are.
inline Scene instanceWholeScene(const Scene& flat, const glm::dmat4& transform) {
    Scene scene = flat;
    static_cast<TriangleSoup&>(scene) = TriangleSoup{};
    const glm::dmat4 inverse = glm::inverse(transform);
    const glm::dmat3 linear(transform);
    const bool mirrored = glm::determinant(linear) < 0.0;
    const bool texcoords = flat.texcoords.size() == flat.positions.size();
    const bool tangents = flat.tangents.size() == flat.positions.size();
    SceneMesh mesh;
    mesh.name = "the scene's triangles";
    for (std::size_t t = 0; t < flat.triangleCount(); ++t) {
        const bool emits = flat.materials[flat.materialIndices[t]].emits();
        TriangleSoup& to = emits ? static_cast<TriangleSoup&>(scene) : mesh;
        const bool swap = mirrored && !emits; // emitters stay as they were, in world space
        const std::size_t order[3] = {0, std::size_t(swap ? 2 : 1), std::size_t(swap ? 1 : 2)};
        for (std::size_t k : order) {
            const std::size_t i = 3 * t + k;
            if (emits) {
                to.positions.push_back(flat.positions[i]);
                to.normals.push_back(flat.normals[i]);
                if (tangents) to.tangents.push_back(flat.tangents[i]);
            } else {
                to.positions.push_back(
                    glm::vec3(inverse * glm::dvec4(glm::dvec3(flat.positions[i]), 1.0)));
                // Normals map by the transpose of the transform (the inverse of the inverse
                // transpose the shading applies).
                to.normals.push_back(glm::vec3(
                    glm::normalize(glm::transpose(linear) * glm::dvec3(flat.normals[i]))));
                if (tangents) {
                    const glm::vec4 w = flat.tangents[i];
                    const glm::dvec3 local = glm::inverse(linear) * glm::dvec3(glm::vec3(w));
                    const double length = glm::length(local);
                    to.tangents.push_back(
                        w.w == 0.0f || !(length > 0.0)
                            ? glm::vec4(0.0f)
                            : glm::vec4(glm::vec3(local / length), mirrored ? -w.w : w.w));
                }
            }
            if (texcoords) to.texcoords.push_back(flat.texcoords[i]);
        }
        to.materialIndices.push_back(flat.materialIndices[t]);
    }
    if (mesh.triangleCount() > 0) {
        scene.meshes.push_back(std::move(mesh));
        scene.instances.push_back({std::uint32_t(scene.meshes.size() - 1), transform});
    }
    return scene;
}

} // namespace vkpt::test
