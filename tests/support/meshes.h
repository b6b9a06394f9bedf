// meshes.h — closed meshes made in code for the numerical-extremes tests: an icosphere and a
// finely split cube, as triangle soups (three vertices per triangle, counter-clockwise outside).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt::test {

struct IndexedMesh {
    std::vector<glm::vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;

    std::vector<glm::vec3> soup() const {
        std::vector<glm::vec3> positions;
        for (const auto& t : triangles)
            for (std::uint32_t i : t)
                positions.push_back(vertices[i]);
        return positions;
    }
};

// Subdivided icosahedron on the unit sphere, scaled and moved; shared vertices are shared
// exactly (one float triple per vertex), as in a real closed mesh.
inline IndexedMesh icosphere(int subdivisions, float radius, glm::vec3 centre) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    IndexedMesh m;
    m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (glm::vec3& v : m.vertices)
        v = glm::normalize(v);
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            auto key = std::minmax(a, b);
            auto [it, inserted] = midpoints.try_emplace(key, std::uint32_t(m.vertices.size()));
            if (inserted) m.vertices.push_back(glm::normalize(m.vertices[a] + m.vertices[b]));
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& tri : m.triangles) {
            std::uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                          ca = midpoint(tri[2], tri[0]);
            finer.push_back({tri[0], ab, ca});
            finer.push_back({tri[1], bc, ab});
            finer.push_back({tri[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        m.triangles = std::move(finer);
    }
    for (glm::vec3& v : m.vertices)
        v = centre + radius * v;
    return m;
}

// A cube of side `size` whose faces are split into cells × cells quads of two triangles each.
inline IndexedMesh splitCube(int cells, float size, glm::vec3 centre) {
    IndexedMesh m;
    std::map<std::array<int, 3>, std::uint32_t> index;
    auto vertex = [&](std::array<int, 3> g) {
        auto [it, inserted] = index.try_emplace(g, std::uint32_t(m.vertices.size()));
        if (inserted)
            m.vertices.push_back(
                centre +
                size * (glm::vec3(float(g[0]), float(g[1]), float(g[2])) / float(cells) - 0.5f));
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            for (int i = 0; i < cells; ++i)
                for (int j = 0; j < cells; ++j) {
                    int u = (axis + 1) % 3, v = (axis + 2) % 3;
                    auto corner = [&](int di, int dj) {
                        std::array<int, 3> g{};
                        g[axis] = side * cells;
                        g[u] = i + di;
                        g[v] = j + dj;
                        return vertex(g);
                    };
                    std::uint32_t a = corner(0, 0), b = corner(1, 0), c = corner(1, 1),
                                  d = corner(0, 1);
                    // Counter-clockwise seen from outside: (u × v) points along +axis.
                    if (side == 1) {
                        m.triangles.push_back({a, b, c});
                        m.triangles.push_back({a, c, d});
                    } else {
                        m.triangles.push_back({a, c, b});
                        m.triangles.push_back({a, d, c});
                    }
                }
    return m;
}

} // namespace vkpt::test
