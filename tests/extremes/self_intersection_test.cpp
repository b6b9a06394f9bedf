// self_intersection_test.cpp — a ray spawned from a surface with the shared offset
// (shared/ray_offset.h, Wächter and Binder) never re-hits the triangle it leaves: 10^6 random
// triangles of every size and position, each with a random point and a random outgoing
// direction down to grazing angles.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/intersect.h"
#include "shared/ray_offset.h"
#include "shared/rng.h"
#include "shared/sampling.h"

namespace vkpt {
namespace {

float logUniform(float u, float lo, float hi) { return lo * std::pow(hi / lo, u); }

glm::vec3 randomUnit(glm::vec2 u) {
    float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 2.0f * VKPT_PI * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

struct SpawnCase {
    glm::vec3 v0, v1, v2;
    glm::vec3 point;     // on the triangle, by barycentric interpolation as the renderers do
    glm::vec3 normal;    // unit geometric normal on the side the ray leaves towards
    glm::vec3 direction; // into that side, from grazing (cos 1e-4) to perpendicular
};

// Triangles centred up to 1e6 from the origin, from 1e-4 to 1e4 in size but never smaller than
// 1e-4 of their distance (about 800 float steps there): a smaller one collapses onto the float
// grid and is no longer a triangle.
SpawnCase makeCase(std::uint32_t i) {
    glm::vec4 a = gpu::randomFloats(23, i, 0, 0, 10), b = gpu::randomFloats(23, i, 0, 0, 11);
    glm::vec4 c = gpu::randomFloats(23, i, 0, 0, 12), d = gpu::randomFloats(23, i, 0, 0, 13);
    float distance = a.y < 0.2f ? 0.0f : logUniform(a.z, 1e-3f, 1e6f);
    float size = logUniform(a.x, std::max(1e-4f, 1e-4f * distance), 1e4f);
    glm::vec3 centre = distance * randomUnit({a.w, b.x});
    SpawnCase s;
    s.v0 = centre + size * randomUnit({b.y, b.z});
    s.v1 = centre + size * randomUnit({b.w, c.x});
    s.v2 = centre + size * randomUnit({c.y, c.z});
    glm::vec3 bary = gpu::sampleTriangleBarycentrics({c.w, d.x});
    s.point = bary.x * s.v0 + bary.y * s.v1 + bary.z * s.v2;
    glm::vec3 face = gpu::triangleFaceNormal(s.v0, s.v1, s.v2);
    s.normal = glm::normalize(d.y < 0.5f ? face : -face);
    float cosTheta = logUniform(d.z, 1e-4f, 1.0f);
    float phi = 2.0f * VKPT_PI * d.w;
    float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
    glm::vec3 local(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
    s.direction = gpu::basisToWorld(gpu::makeBasis(s.normal), local);
    return s;
}

TEST(SelfIntersection, SpawnedRaysNeverReHitTheirOwnTriangle) {
    std::uint64_t tested = 0, reHits = 0, degenerate = 0;
    for (std::uint32_t i = 0; i < 1000000; ++i) {
        SpawnCase s = makeCase(i);
        if (!std::isfinite(s.normal.x) || glm::dot(s.direction, s.normal) <= 0.0f) {
            ++degenerate; // a needle so thin that its normal is not representable
            continue;
        }
        glm::vec3 origin = gpu::offsetFromSurface(s.point, s.normal, gpu::triangleCoordinateScale(s.v0, s.v1, s.v2));
        ++tested;
        reHits += gpu::intersectTriangle(origin, s.direction, s.v0, s.v1, s.v2, 0.0f, VKPT_FAR).hit;
    }
    EXPECT_EQ(reHits, 0u) << "of " << tested << " spawned rays";
    EXPECT_LT(degenerate, 100u) << "random triangles should rarely be needles";
}

// The offset point must stay on the chosen side of the plane, however far from the origin.
TEST(SelfIntersection, OffsetOriginLiesOnTheNormalSide) {
    std::uint64_t wrongSide = 0;
    for (std::uint32_t i = 0; i < 1000000; ++i) {
        SpawnCase s = makeCase(i);
        if (!std::isfinite(s.normal.x)) continue;
        glm::vec3 origin = gpu::offsetFromSurface(s.point, s.normal, gpu::triangleCoordinateScale(s.v0, s.v1, s.v2));
        // Exact side test in double against the triangle's plane.
        glm::dvec3 n = glm::cross(glm::dvec3(s.v1) - glm::dvec3(s.v0), glm::dvec3(s.v2) - glm::dvec3(s.v0));
        if (glm::dot(n, glm::dvec3(s.normal)) < 0.0) n = -n;
        wrongSide += glm::dot(n, glm::dvec3(origin) - glm::dvec3(s.v0)) <= 0.0;
    }
    EXPECT_EQ(wrongSide, 0u);
}

} // namespace
} // namespace vkpt
