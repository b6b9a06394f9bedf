// synthetic_scenes.h — generated triangle soups of known shape (random soup, coplanar grid,
// closed cube, displaced sphere) for the BVH tests and benchmarks; not part of rendering.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

namespace vkpt::synthetic {

// A seeded generator whose floats are the same on every platform: std::mt19937's output is
// specified, the standard distributions are not.
class Rng {
public:
    explicit Rng(std::uint32_t seed) : engine_(seed) {}

    float uniform(); // in [0, 1)
    float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }
    std::uint32_t below(std::uint32_t n) { return static_cast<std::uint32_t>(engine_() % n); }
    glm::vec3 inBox(const glm::vec3& lo, const glm::vec3& hi);
    glm::vec3 unitVector(); // uniform on the sphere

private:
    std::mt19937 engine_;
};

// Each function returns three positions per triangle, counter-clockwise seen from the front.

// Triangles with centres uniform in [0, extent]^3 and vertices within ±size/2 of the centre.
std::vector<glm::vec3> randomSoup(std::uint32_t triangleCount, std::uint32_t seed,
                                  float extent = 10.0f, float size = 0.5f);

// cells × cells unit squares in the z = 0 plane, two triangles each, integer coordinates:
// every triangle coplanar, many sharing edges and vertices exactly.
std::vector<glm::vec3> grid(std::uint32_t cells);

// The surface of [0, cells]^3, each face cells × cells squares of two triangles, facing out.
std::vector<glm::vec3> closedCube(std::uint32_t cells);

// A unit sphere displaced by a few octaves of sines (a terrain-like, closed surface):
// 2 · rings · segments triangles.
std::vector<glm::vec3> displacedSphere(std::uint32_t rings, std::uint32_t segments);

} // namespace vkpt::synthetic
