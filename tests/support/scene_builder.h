// scene_builder.h — scenes built in memory for tests: diffuse materials, triangles, quads,
// grids and boxes with flat normals, counter-clockwise seen from their fronts.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkpt::test {

inline std::uint32_t addMaterial(Scene& scene, glm::vec3 albedo,
                                 glm::vec3 emission = glm::vec3(0.0f), bool doubleSided = false) {
    SceneMaterial material;
    material.name = "material " + std::to_string(scene.materials.size());
    material.baseColor = glm::vec4(albedo, 1.0f);
    material.emission = emission;
    material.metallic = 0.0f;
    material.specular = 0.0f; // the Lambertian "diffuse" kind
    material.doubleSided = doubleSided;
    scene.materials.push_back(material);
    return std::uint32_t(scene.materials.size() - 1);
}

// One triangle with flat shading normals; its front face is the counter-clockwise side.
inline void addTriangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c,
                        std::uint32_t material) {
    glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (glm::vec3 p : {a, b, c}) {
        scene.positions.push_back(p);
        scene.normals.push_back(n);
    }
    scene.materialIndices.push_back(material);
}

// A quad a b c d, counter-clockwise seen from its front.
inline void addQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
                    std::uint32_t material) {
    addTriangle(scene, a, b, c, material);
    addTriangle(scene, a, c, d, material);
}

// A horizontal rectangle at height y, facing up (+y) or down, split into cells × cells quads.
inline void addHorizontalGrid(Scene& scene, glm::vec2 lo, glm::vec2 hi, float y, bool facingUp,
                              int cells, std::uint32_t material) {
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            auto at = [&](int di, int dj) {
                float x = lo.x + (hi.x - lo.x) * float(i + di) / float(cells);
                float z = lo.y + (hi.y - lo.y) * float(j + dj) / float(cells);
                return glm::vec3(x, y, z);
            };
            if (facingUp) {
                addQuad(scene, at(0, 0), at(0, 1), at(1, 1), at(1, 0), material);
            } else {
                addQuad(scene, at(0, 0), at(1, 0), at(1, 1), at(0, 1), material);
            }
        }
}

// A closed axis-aligned box whose faces point outwards.
inline void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, std::uint32_t material) {
    glm::vec3 p[8];
    for (int i = 0; i < 8; ++i)
        p[i] = glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    addQuad(scene, p[0], p[4], p[6], p[2], material); // -x
    addQuad(scene, p[1], p[3], p[7], p[5], material); // +x
    addQuad(scene, p[0], p[1], p[5], p[4], material); // -y
    addQuad(scene, p[2], p[6], p[7], p[3], material); // +y
    addQuad(scene, p[0], p[2], p[3], p[1], material); // -z
    addQuad(scene, p[4], p[5], p[7], p[6], material); // +z
}

} // namespace vkpt::test
