// watertight_test.cpp — rays aimed exactly at the shared edges and vertices of closed meshes
// must never pass through: from outside they hit at or before the aimed-at point, from inside
// they cannot escape. 10^6 rays per mesh and side; the target is zero leaks.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "../support/meshes.h"
#include "bvh/bvh_build.h"
#include "bvh/bvh_traverse.h"
#include "shared/rng.h"

namespace vkpt {
namespace {

struct ClosedMesh {
    test::IndexedMesh mesh;
    glm::vec3 centre;
    float radius;
    BvhTree tree;
    std::vector<gpu::Triangle> triangles;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
};

ClosedMesh prepare(test::IndexedMesh mesh, glm::vec3 centre, float radius) {
    ClosedMesh m{std::move(mesh), centre, radius, {}, {}, {}};
    std::vector<glm::vec3> soup = m.mesh.soup();
    m.tree = buildBvh(triangleBounds(soup));
    for (std::uint32_t i : m.tree.primitiveOrder)
        m.triangles.push_back({soup[3 * i], 0, soup[3 * i + 1], NO_EMITTER, soup[3 * i + 2], i});
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : m.mesh.triangles)
        for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    m.edges.assign(edges.begin(), edges.end());
    return m;
}

glm::vec3 unitVector(glm::vec2 u) {
    float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    float phi = 6.2831853f * u.y;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// A point on a shared edge (a random fraction along it, rounded as any renderer would) or,
// for every fourth ray, a shared vertex exactly.
glm::vec3 target(const ClosedMesh& m, std::uint32_t ray) {
    glm::vec4 u = gpu::randomFloats(17, ray, 0, 0, DIM_LIGHT_FIRST);
    if (ray % 4 == 0) return m.mesh.vertices[std::uint32_t(u.x * float(m.mesh.vertices.size()))];
    const auto& e = m.edges[std::uint32_t(u.x * float(m.edges.size()))];
    return glm::mix(m.mesh.vertices[e.first], m.mesh.vertices[e.second], u.y);
}

struct LeakCount {
    std::uint64_t fromOutside = 0;
    std::uint64_t fromInside = 0;
};

// A leak: the closest hit lies beyond the aimed-at point, or there is none. The aimed-at
// point itself was rounded to float (by up to half an ulp of its largest coordinate per
// component, 0.008 at 1e5), so the true surface may lie that far behind it: the allowance is
// 4 ulps of the point's largest coordinate, in units of the ray's length, plus 1e-5.
float allowance(glm::vec3 aim, glm::vec3 origin) {
    float largest = std::max(std::max(std::abs(aim.x), std::abs(aim.y)), std::abs(aim.z));
    return 1e-5f + 4.0f * largest * 0x1p-23f / glm::length(aim - origin);
}

LeakCount countLeaks(const ClosedMesh& m, std::uint32_t rays) {
    LeakCount leaks;
    for (std::uint32_t i = 0; i < rays; ++i) {
        glm::vec3 aim = target(m, i);
        glm::vec4 u = gpu::randomFloats(17, i, 0, 0, DIM_BSDF);
        // Both origins look through the aimed-at point towards a point well inside the convex
        // mesh, so every ray really crosses the surface there: a ray that only grazed an edge
        // of the solid could miss it legitimately after rounding, and would prove nothing.
        glm::vec3 inside = m.centre + 0.2f * m.radius * unitVector({u.z, u.w});
        glm::vec3 outside = aim + 2.0f * m.radius * glm::normalize(aim - inside);
        for (int side = 0; side < 2; ++side) {
            glm::vec3 origin = side == 0 ? outside : inside;
            ClosestHit hit = closestHitStack(m.tree, m.triangles, {origin, aim - origin});
            if (!hit.hit || hit.t > 1.0f + allowance(aim, origin))
                ++(side == 0 ? leaks.fromOutside : leaks.fromInside);
        }
    }
    return leaks;
}

constexpr std::uint32_t kRays = 1000000;

TEST(Watertight, IcosphereHasNoLeaksAtEdgesAndVertices) {
    ClosedMesh m = prepare(test::icosphere(4, 1.0f, glm::vec3(0.0f)), glm::vec3(0.0f), 1.0f);
    LeakCount leaks = countLeaks(m, kRays);
    EXPECT_EQ(leaks.fromOutside, 0u);
    EXPECT_EQ(leaks.fromInside, 0u);
}

TEST(Watertight, FinelySplitCubeHasNoLeaksAtEdgesAndVertices) {
    ClosedMesh m = prepare(test::splitCube(16, 2.0f, glm::vec3(0.0f)), glm::vec3(0.0f), 1.0f);
    LeakCount leaks = countLeaks(m, kRays);
    EXPECT_EQ(leaks.fromOutside, 0u);
    EXPECT_EQ(leaks.fromInside, 0u);
}

TEST(Watertight, MeshFarFromTheOriginHasNoLeaks) {
    const glm::vec3 centre(1e5f, -1e5f, 1e5f);
    ClosedMesh m = prepare(test::icosphere(3, 1.0f, centre), centre, 1.0f);
    LeakCount leaks = countLeaks(m, kRays);
    EXPECT_EQ(leaks.fromOutside, 0u);
    EXPECT_EQ(leaks.fromInside, 0u);
}

} // namespace
} // namespace vkpt
