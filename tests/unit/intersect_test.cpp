// intersect_test.cpp — the shared ray/triangle and ray/box tests: edges, vertices, faces,
// axis-parallel rays, zero direction components and the exclusive t range.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "shared/intersect.h"

namespace vkpt::intersect_test {
namespace {

using glm::vec3;

// The unit right triangle in the z = 0 plane, counter-clockwise seen from +z.
const vec3 kV0{0.0f, 0.0f, 0.0f};
const vec3 kV1{1.0f, 0.0f, 0.0f};
const vec3 kV2{0.0f, 1.0f, 0.0f};

gpu::TriangleHit shootDown(vec3 v0, vec3 v1, vec3 v2, float x, float y, float tMin = 0.0f,
                           float tMax = VKPT_FAR) {
    return gpu::intersectTriangle(vec3(x, y, 1.0f), vec3(0.0f, 0.0f, -1.0f), v0, v1, v2, tMin,
                                  tMax);
}

gpu::TriangleHit shootDownUnit(float x, float y, float tMin = 0.0f, float tMax = VKPT_FAR) {
    return shootDown(kV0, kV1, kV2, x, y, tMin, tMax);
}

float enterUnitBox(vec3 origin, vec3 direction, float tMin = 0.0f, float tMax = VKPT_FAR) {
    return gpu::intersectBox(origin, gpu::safeInverseDirection(direction), vec3(0.0f), vec3(1.0f),
                             tMin, tMax);
}

TEST(TriangleIntersection, HitsInteriorWithDistanceAndBarycentrics) {
    gpu::TriangleHit h = shootDownUnit(0.25f, 0.5f);
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.t, 1.0f);
    EXPECT_EQ(h.u, 0.25f);
    EXPECT_EQ(h.v, 0.5f);
}

TEST(TriangleIntersection, DistanceIsInUnitsOfTheDirectionLength) {
    gpu::TriangleHit h = gpu::intersectTriangle(vec3(0.25f, 0.25f, 4.0f), vec3(0.0f, 0.0f, -2.0f),
                                                kV0, kV1, kV2, 0.0f, VKPT_FAR);
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.t, 2.0f);
}

TEST(TriangleIntersection, MissesPointsOutside) {
    EXPECT_FALSE(shootDownUnit(0.75f, 0.75f).hit); // beyond the hypotenuse
    EXPECT_FALSE(shootDownUnit(-0.25f, 0.5f).hit); // left of the y axis edge
    EXPECT_FALSE(shootDownUnit(0.5f, -0.25f).hit); // below the x axis edge
    EXPECT_FALSE(shootDownUnit(2.0f, 2.0f).hit);
}

TEST(TriangleIntersection, HitsExactlyOnEdgesCountAsHits) {
    EXPECT_TRUE(shootDownUnit(0.5f, 0.0f).hit);   // edge v0-v1
    EXPECT_TRUE(shootDownUnit(0.0f, 0.5f).hit);   // edge v0-v2
    EXPECT_TRUE(shootDownUnit(0.5f, 0.5f).hit);   // edge v1-v2
    EXPECT_TRUE(shootDownUnit(0.25f, 0.75f).hit); // edge v1-v2
    // A larger triangle whose determinant is not a power of two.
    vec3 a{0.0f, 0.0f, 0.0f}, b{3.0f, 0.0f, 0.0f}, c{0.0f, 3.0f, 0.0f};
    EXPECT_TRUE(shootDown(a, b, c, 1.0f, 2.0f).hit);
    EXPECT_TRUE(shootDown(a, b, c, 2.0f, 1.0f).hit);
    EXPECT_TRUE(shootDown(a, b, c, 1.5f, 0.0f).hit);
    EXPECT_TRUE(shootDown(a, b, c, 0.0f, 1.5f).hit);
}

TEST(TriangleIntersection, HitsExactlyOnVerticesCountAsHits) {
    for (vec3 v : {kV0, kV1, kV2})
        EXPECT_TRUE(shootDownUnit(v.x, v.y).hit) << v.x << "," << v.y;
    vec3 a{0.0f, 0.0f, 0.0f}, b{3.0f, 0.0f, 0.0f}, c{0.0f, 3.0f, 0.0f};
    for (vec3 v : {a, b, c})
        EXPECT_TRUE(shootDown(a, b, c, v.x, v.y).hit) << v.x << "," << v.y;
}

TEST(TriangleIntersection, VertexHitsHaveCornerBarycentrics) {
    gpu::TriangleHit h1 = shootDownUnit(1.0f, 0.0f);
    EXPECT_EQ(h1.u, 1.0f);
    EXPECT_EQ(h1.v, 0.0f);
    gpu::TriangleHit h2 = shootDownUnit(0.0f, 1.0f);
    EXPECT_EQ(h2.u, 0.0f);
    EXPECT_EQ(h2.v, 1.0f);
}

TEST(TriangleIntersection, HitsBackFaces) {
    gpu::TriangleHit h = gpu::intersectTriangle(vec3(0.25f, 0.25f, -1.0f), vec3(0.0f, 0.0f, 1.0f),
                                                kV0, kV1, kV2, 0.0f, VKPT_FAR);
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.t, 1.0f);
    EXPECT_EQ(h.u, 0.25f);
    EXPECT_EQ(h.v, 0.25f);
}

TEST(TriangleIntersection, MissesRaysParallelToThePlane) {
    // Above the plane, and inside it through the triangle: det = 0 either way.
    EXPECT_FALSE(gpu::intersectTriangle(vec3(-1.0f, 0.25f, 1.0f), vec3(1.0f, 0.0f, 0.0f), kV0, kV1,
                                        kV2, 0.0f, VKPT_FAR)
                     .hit);
    EXPECT_FALSE(gpu::intersectTriangle(vec3(-1.0f, 0.25f, 0.0f), vec3(1.0f, 0.0f, 0.0f), kV0, kV1,
                                        kV2, 0.0f, VKPT_FAR)
                     .hit);
    EXPECT_FALSE(gpu::intersectTriangle(vec3(-1.0f, -1.0f, 0.0f), vec3(1.0f, 1.0f, 0.0f), kV0, kV1,
                                        kV2, 0.0f, VKPT_FAR)
                     .hit);
}

// A triangle in each axis plane, hit by rays along that axis in both directions: two of the
// three direction components are zero.
TEST(TriangleIntersection, HitsAxisParallelRaysAlongEveryAxis) {
    for (int axis = 0; axis < 3; ++axis) {
        int a = (axis + 1) % 3, b = (axis + 2) % 3;
        vec3 v0(2.0f), v1(2.0f), v2(2.0f);
        v1[a] += 1.0f;
        v2[b] += 1.0f;
        for (float sign : {1.0f, -1.0f}) {
            vec3 origin(2.0f);
            origin[a] += 0.25f;
            origin[b] += 0.25f;
            origin[axis] -= 3.0f * sign;
            vec3 direction(0.0f);
            direction[axis] = sign;
            gpu::TriangleHit h =
                gpu::intersectTriangle(origin, direction, v0, v1, v2, 0.0f, VKPT_FAR);
            ASSERT_TRUE(h.hit) << "axis " << axis << " sign " << sign;
            EXPECT_EQ(h.t, 3.0f);
            EXPECT_EQ(h.u, 0.25f);
            EXPECT_EQ(h.v, 0.25f);
        }
    }
}

TEST(TriangleIntersection, DistanceRangeExcludesBothEnds) {
    // The hit is exactly at t = 1.
    float below = std::nextafter(1.0f, 0.0f);
    float above = std::nextafter(1.0f, 2.0f);
    EXPECT_FALSE(shootDownUnit(0.25f, 0.25f, 0.0f, 1.0f).hit);
    EXPECT_TRUE(shootDownUnit(0.25f, 0.25f, 0.0f, above).hit);
    EXPECT_FALSE(shootDownUnit(0.25f, 0.25f, 1.0f, VKPT_FAR).hit);
    EXPECT_TRUE(shootDownUnit(0.25f, 0.25f, below, VKPT_FAR).hit);
}

TEST(TriangleIntersection, MissesTrianglesBehindTheOrigin) {
    EXPECT_FALSE(gpu::intersectTriangle(vec3(0.25f, 0.25f, 1.0f), vec3(0.0f, 0.0f, 1.0f), kV0, kV1,
                                        kV2, 0.0f, VKPT_FAR)
                     .hit);
}

// A ray starting on the surface (t = 0) does not hit it again with tMin = 0.
TEST(TriangleIntersection, MissesAtTheOriginWithTMinZero) {
    EXPECT_FALSE(gpu::intersectTriangle(vec3(0.25f, 0.25f, 0.0f), vec3(0.0f, 0.0f, -1.0f), kV0, kV1,
                                        kV2, 0.0f, VKPT_FAR)
                     .hit);
}

TEST(TriangleIntersection, DegenerateTrianglesNeverHit) {
    vec3 p{0.5f, 0.5f, 0.0f};
    EXPECT_FALSE(shootDown(p, p, p, 0.5f, 0.5f).hit); // a point
    // Collinear vertices: a segment, shot at a point on it and at an end.
    vec3 a{0.0f, 0.0f, 0.0f}, b{1.0f, 0.0f, 0.0f}, c{2.0f, 0.0f, 0.0f};
    EXPECT_FALSE(shootDown(a, b, c, 0.5f, 0.0f).hit);
    EXPECT_FALSE(shootDown(a, b, c, 0.0f, 0.0f).hit);
    EXPECT_FALSE(shootDown(a, a, c, 1.0f, 0.0f).hit); // two equal vertices
    // Seen edge-on the segment is also missed by a ray along its line.
    EXPECT_FALSE(gpu::intersectTriangle(vec3(-1.0f, 0.0f, 0.0f), vec3(1.0f, 0.0f, 0.0f), a, b, c,
                                        0.0f, VKPT_FAR)
                     .hit);
}

TEST(TriangleIntersection, FaceNormalPointsToTheCounterClockwiseSide) {
    vec3 n = gpu::triangleFaceNormal(kV0, kV1, kV2);
    EXPECT_EQ(n, vec3(0.0f, 0.0f, 1.0f));
}

TEST(SafeInverseDirection, ZeroComponentsBecomeLargeFiniteValuesWithTheirSign) {
    vec3 inv = gpu::safeInverseDirection(vec3(0.0f, -0.0f, 2.0f));
    EXPECT_TRUE(std::isfinite(inv.x) && std::isfinite(inv.y));
    EXPECT_GT(inv.x, 1e29f);
    EXPECT_LT(inv.y, -1e29f); // -0 by its sign bit, as the wide walk's octant reads it
    EXPECT_EQ(inv.z, 0.5f);
    EXPECT_LT(gpu::safeInverseDirection(vec3(-1e-31f)).x, -1e29f);
}

TEST(BoxIntersection, ReturnsTheEntryDistanceFromOutside) {
    EXPECT_EQ(enterUnitBox(vec3(-1.0f, 0.5f, 0.5f), vec3(1.0f, 0.0f, 0.0f)), 1.0f);
    EXPECT_EQ(enterUnitBox(vec3(0.5f, 3.0f, 0.5f), vec3(0.0f, -1.0f, 0.0f)), 2.0f);
    EXPECT_FLOAT_EQ(enterUnitBox(vec3(-1.0f, -1.0f, -1.0f), vec3(1.0f, 1.0f, 1.0f)), 1.0f);
}

TEST(BoxIntersection, MissesReturnFar) {
    EXPECT_EQ(enterUnitBox(vec3(-1.0f, 2.0f, 0.5f), vec3(1.0f, 0.0f, 0.0f)), VKPT_FAR);
    EXPECT_EQ(enterUnitBox(vec3(-1.0f, 0.5f, 0.5f), vec3(-1.0f, 0.0f, 0.0f)), VKPT_FAR); // behind
    EXPECT_EQ(enterUnitBox(vec3(-1.0f, -1.0f, 0.5f), vec3(1.0f, 3.0f, 0.0f)), VKPT_FAR);
}

TEST(BoxIntersection, OriginInsideEntersAtTMin) {
    EXPECT_EQ(enterUnitBox(vec3(0.5f), vec3(0.3f, -0.2f, 0.9f)), 0.0f);
    EXPECT_EQ(enterUnitBox(vec3(0.5f), vec3(0.0f, 0.0f, -1.0f), 0.25f), 0.25f);
}

TEST(BoxIntersection, OriginOnAFaceEntersAtZero) {
    EXPECT_EQ(enterUnitBox(vec3(0.0f, 0.5f, 0.5f), vec3(1.0f, 0.0f, 0.0f)), 0.0f);  // inward
    EXPECT_EQ(enterUnitBox(vec3(0.0f, 0.5f, 0.5f), vec3(-1.0f, 0.0f, 0.0f)), 0.0f); // outward
    EXPECT_EQ(enterUnitBox(vec3(0.0f, 0.5f, 0.5f), vec3(0.0f, 1.0f, 0.0f)), 0.0f);  // along it
}

// Zero components: the ray is parallel to a slab, inside it, outside it, or on its plane
// (where 0·(1/0) would be NaN without safeInverseDirection).
TEST(BoxIntersection, HandlesZeroDirectionComponents) {
    EXPECT_EQ(enterUnitBox(vec3(0.5f, 0.5f, -2.0f), vec3(0.0f, 0.0f, 1.0f)), 2.0f);
    EXPECT_EQ(enterUnitBox(vec3(1.5f, 0.5f, -2.0f), vec3(0.0f, 0.0f, 1.0f)), VKPT_FAR);
    EXPECT_EQ(enterUnitBox(vec3(0.0f, 0.0f, -2.0f), vec3(0.0f, 0.0f, 1.0f)), 2.0f);
    EXPECT_EQ(enterUnitBox(vec3(1.0f, 1.0f, -2.0f), vec3(-0.0f, -0.0f, 1.0f)), 2.0f);
    EXPECT_EQ(enterUnitBox(vec3(-1.0f, 0.0f, 0.5f), vec3(1.0f, 0.0f, 0.0f)), 1.0f);
}

TEST(BoxIntersection, TouchingAnEdgeOrACornerCountsAsHit) {
    // Along the edge y = 1, z = 1.
    EXPECT_EQ(enterUnitBox(vec3(-1.0f, 1.0f, 1.0f), vec3(1.0f, 0.0f, 0.0f)), 1.0f);
    // Diagonally through the edge x = 0, y = 1 only, at t = 1.
    EXPECT_EQ(enterUnitBox(vec3(-1.0f, 0.0f, 0.5f), vec3(1.0f, 1.0f, 0.0f)), 1.0f);
    EXPECT_EQ(enterUnitBox(vec3(-1.0f, 0.25f, 0.5f), vec3(1.0f, 1.0f, 0.0f)), VKPT_FAR);
    // Through the corner (1, 1, 1) only.
    EXPECT_EQ(enterUnitBox(vec3(2.0f, 2.0f, 0.0f), vec3(-1.0f, -1.0f, 1.0f)), 1.0f);
}

TEST(BoxIntersection, FlatBoxesAreHit) {
    vec3 inv = gpu::safeInverseDirection(vec3(0.0f, 0.0f, -1.0f));
    EXPECT_EQ(gpu::intersectBox(vec3(0.5f, 0.5f, 1.0f), inv, vec3(0.0f), vec3(1.0f, 1.0f, 0.0f),
                                0.0f, VKPT_FAR),
              1.0f);
}

TEST(BoxIntersection, RespectsTheDistanceRange) {
    vec3 origin(-1.0f, 0.5f, 0.5f), direction(1.0f, 0.0f, 0.0f);
    EXPECT_EQ(enterUnitBox(origin, direction, 0.0f, 0.5f), VKPT_FAR); // box beyond tMax
    EXPECT_EQ(enterUnitBox(origin, direction, 2.5f), VKPT_FAR);       // box before tMin
    EXPECT_EQ(enterUnitBox(origin, direction, 1.5f), 1.5f);           // tMin inside the box
    // An exit just short of tMax still counts: the widened exit admits rounding.
    EXPECT_EQ(enterUnitBox(origin, direction, 0.0f, 1.0f), 1.0f);
}

} // namespace
} // namespace vkpt::intersect_test
