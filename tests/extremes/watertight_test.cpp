// watertight_test.cpp — rays aimed exactly at the shared edges and vertices of closed meshes
// must never pass through: from outside they hit at or before the aimed-at point, from inside
// they cannot escape. 10^6 rays per mesh and side through vkpt-ref's traversal, 10^5 through
// vkpt's trace_closest kernel on the device; the target is zero leaks.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "../support/meshes.h"
#include "../support/ray_queries.h"
#include "bvh/bvh_traverse.h"
#include "extremes_support.h"
#include "shared/rng.h"

namespace vkpt::watertight_test {
namespace {

struct ClosedMesh {
    test::IndexedMesh mesh;
    glm::vec3 centre;
    float radius;
    PreparedScene prepared; // the BVH, its flattened nodes and the triangles in BVH order
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
};

ClosedMesh prepare(test::IndexedMesh mesh, glm::vec3 centre, float radius) {
    ClosedMesh m{std::move(mesh), centre, radius, {}, {}};
    Scene scene;
    std::uint32_t material = test::addMaterial(scene, glm::vec3(0.5f));
    for (const auto& t : m.mesh.triangles)
        test::addTriangle(scene, m.mesh.vertices[t[0]], m.mesh.vertices[t[1]],
                          m.mesh.vertices[t[2]], material);
    m.prepared = prepareScene(scene);
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : m.mesh.triangles)
        for (int k = 0; k < 3; ++k)
            edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
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

// Ray i from outside (side 0) or inside (side 1), aimed at target i: t = 1 there.
struct AimedRay {
    DeviceRay ray;
    glm::vec3 aim;
};

AimedRay aimedRay(const ClosedMesh& m, std::uint32_t i, int side) {
    glm::vec3 aim = target(m, i);
    glm::vec4 u = gpu::randomFloats(17, i, 0, 0, DIM_BSDF);
    // Both origins look through the aimed-at point towards a point well inside the convex
    // mesh, so every ray really crosses the surface there: a ray that only grazed an edge
    // of the solid could miss it legitimately after rounding, and would prove nothing.
    glm::vec3 inside = m.centre + 0.2f * m.radius * unitVector({u.z, u.w});
    glm::vec3 outside = aim + 2.0f * m.radius * glm::normalize(aim - inside);
    glm::vec3 origin = side == 0 ? outside : inside;
    return {{origin, aim - origin}, aim};
}

bool leaks(const AimedRay& r, bool hit, float t) {
    return !hit || t > 1.0f + allowance(r.aim, r.ray.origin);
}

LeakCount countLeaks(const ClosedMesh& m, std::uint32_t rays) {
    LeakCount leakCount;
    const StackBvh stackBvh = makeStackBvh(m.prepared.tree, m.prepared.triangles);
    for (std::uint32_t i = 0; i < rays; ++i)
        for (int side = 0; side < 2; ++side) {
            AimedRay r = aimedRay(m, i, side);
            ClosestHit hit = closestHitStack(stackBvh, {r.ray.origin, r.ray.direction});
            if (leaks(r, hit.hit, hit.t))
                ++(side == 0 ? leakCount.fromOutside : leakCount.fromInside);
        }
    return leakCount;
}

// The same rays through trace_closest on the device (its stackless walk of the flattened BVH).
LeakCount countDeviceLeaks(GpuContext& context, const ClosedMesh& m, std::uint32_t rays) {
    LeakCount leakCount;
    DeviceRayQueries queries(context, m.prepared);
    for (int side = 0; side < 2; ++side) {
        std::vector<AimedRay> aimed;
        std::vector<DeviceRay> list;
        for (std::uint32_t i = 0; i < rays; ++i) {
            aimed.push_back(aimedRay(m, i, side));
            list.push_back(aimed.back().ray);
        }
        std::vector<gpu::HitRecord> hits = queries.closest(list);
        for (std::uint32_t i = 0; i < rays; ++i)
            if (leaks(aimed[i], hits[i].triangle != NO_HIT, hits[i].t))
                ++(side == 0 ? leakCount.fromOutside : leakCount.fromInside);
    }
    EXPECT_EQ(queries.truncatedTraversals(), 0u);
    return leakCount;
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

constexpr std::uint32_t kDeviceRays = 100000;

class WatertightOnTheDevice : public test::GpuTest {};

TEST_F(WatertightOnTheDevice, NoMeshLeaksAtEdgesAndVertices) {
    const glm::vec3 far(1e5f, -1e5f, 1e5f);
    const ClosedMesh meshes[] = {
        prepare(test::icosphere(4, 1.0f, glm::vec3(0.0f)), glm::vec3(0.0f), 1.0f),
        prepare(test::splitCube(16, 2.0f, glm::vec3(0.0f)), glm::vec3(0.0f), 1.0f),
        prepare(test::icosphere(3, 1.0f, far), far, 1.0f)};
    const char* names[] = {"icosphere", "split cube", "icosphere at 1e5"};
    for (int i = 0; i < 3; ++i) {
        LeakCount leaks = countDeviceLeaks(context(), meshes[i], kDeviceRays);
        EXPECT_EQ(leaks.fromOutside, 0u) << names[i];
        EXPECT_EQ(leaks.fromInside, 0u) << names[i];
    }
}

} // namespace
} // namespace vkpt::watertight_test
