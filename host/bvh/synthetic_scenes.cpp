// synthetic_scenes.cpp — generated triangle soups for the BVH tests and benchmarks.
#include "bvh/synthetic_scenes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vkpt::synthetic {

// The top 24 bits of a 32-bit draw: every value is exact in a float and below 1.
float Rng::uniform() {
    return static_cast<float>(engine_() >> 8) * 0x1p-24f;
}

glm::vec3 Rng::inBox(const glm::vec3& lo, const glm::vec3& hi) {
    float x = uniform(lo.x, hi.x);
    float y = uniform(lo.y, hi.y);
    return {x, y, uniform(lo.z, hi.z)};
}

// Uniform z and azimuth give a uniform direction (Archimedes' hat-box theorem).
glm::vec3 Rng::unitVector() {
    float z = uniform(-1.0f, 1.0f);
    float phi = uniform(0.0f, 2.0f * std::numbers::pi_v<float>);
    float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

std::vector<glm::vec3> randomSoup(std::uint32_t triangleCount, std::uint32_t seed, float extent,
                                  float size) {
    Rng rng(seed);
    std::vector<glm::vec3> positions;
    positions.reserve(3 * std::size_t(triangleCount));
    glm::vec3 half(0.5f * size);
    for (std::uint32_t i = 0; i < triangleCount; ++i) {
        glm::vec3 centre = rng.inBox(glm::vec3(0.0f), glm::vec3(extent));
        for (int k = 0; k < 3; ++k)
            positions.push_back(centre + rng.inBox(-half, half));
    }
    return positions;
}

namespace {

// Two triangles for the quad a, b, c, d (counter-clockwise).
void appendQuad(std::vector<glm::vec3>& out, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    out.insert(out.end(), {a, b, c, a, c, d});
}

// One face of the cube: the cells × cells squares spanned from corner by du and dv, whose
// cross product points out of the cube.
void appendFace(std::vector<glm::vec3>& out, std::uint32_t cells, glm::vec3 corner, glm::vec3 du,
                glm::vec3 dv) {
    for (std::uint32_t i = 0; i < cells; ++i) {
        for (std::uint32_t j = 0; j < cells; ++j) {
            glm::vec3 p = corner + static_cast<float>(i) * du + static_cast<float>(j) * dv;
            appendQuad(out, p, p + du, p + du + dv, p + dv);
        }
    }
}

glm::vec3 spherePoint(float theta, float phi) {
    float r = 1.0f + 0.05f * std::sin(7.0f * theta) * std::cos(9.0f * phi) +
              0.02f * std::sin(31.0f * theta + 3.0f) * std::sin(27.0f * phi) +
              0.005f * std::cos(97.0f * theta) * std::sin(113.0f * phi + 1.0f);
    return r * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                         std::sin(theta) * std::sin(phi));
}

} // namespace

std::vector<glm::vec3> grid(std::uint32_t cells) {
    std::vector<glm::vec3> positions;
    positions.reserve(6 * std::size_t(cells) * cells);
    appendFace(positions, cells, glm::vec3(0.0f), {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    return positions;
}

std::vector<glm::vec3> closedCube(std::uint32_t cells) {
    std::vector<glm::vec3> positions;
    positions.reserve(36 * std::size_t(cells) * cells);
    float n = static_cast<float>(cells);
    glm::vec3 x(1.0f, 0.0f, 0.0f), y(0.0f, 1.0f, 0.0f), z(0.0f, 0.0f, 1.0f);
    appendFace(positions, cells, glm::vec3(0.0f), y, x); // z = 0, facing -z
    appendFace(positions, cells, n * z, x, y);           // z = n, facing +z
    appendFace(positions, cells, glm::vec3(0.0f), x, z); // y = 0, facing -y
    appendFace(positions, cells, n * y, z, x);           // y = n, facing +y
    appendFace(positions, cells, glm::vec3(0.0f), z, y); // x = 0, facing -x
    appendFace(positions, cells, n * x, y, z);           // x = n, facing +x
    return positions;
}

// Rings of constant theta from pole to pole; the poles' quads degenerate to triangles (and
// zero-area slivers), which the BVH must tolerate anyway.
std::vector<glm::vec3> displacedSphere(std::uint32_t rings, std::uint32_t segments) {
    std::vector<glm::vec3> positions;
    positions.reserve(6 * std::size_t(rings) * segments);
    float dTheta = std::numbers::pi_v<float> / static_cast<float>(rings);
    float dPhi = 2.0f * std::numbers::pi_v<float> / static_cast<float>(segments);
    for (std::uint32_t i = 0; i < rings; ++i) {
        float t0 = static_cast<float>(i) * dTheta, t1 = t0 + dTheta;
        for (std::uint32_t j = 0; j < segments; ++j) {
            float p0 = static_cast<float>(j) * dPhi, p1 = p0 + dPhi;
            appendQuad(positions, spherePoint(t0, p0), spherePoint(t0, p1), spherePoint(t1, p1),
                       spherePoint(t1, p0));
        }
    }
    return positions;
}

} // namespace vkpt::synthetic
