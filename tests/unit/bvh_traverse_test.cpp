// bvh_traverse_test.cpp — the stackless walk of the 8-wide compressed BVH (the kernels' code,
// shared/wide_bvh.h), the ordered stack walk (the reference's) and brute force agree on 10^5
// random rays per scene, synthetic and loaded from glTF files.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/ray_description.h"

#include "bvh/bvh_traverse.h"
#include "bvh/bvh_wide.h"
#include "bvh/synthetic_scenes.h"
#include "bvh/wide_traverse.h"
#include "common/errors.h"
#include "scene/gltf_loader.h"
#include "shared/intersect.h"

namespace vkpt::bvh_traverse_test {
namespace {

constexpr int kRaysPerScene = 100000;
constexpr int kBruteForceRays = 2000; // brute force costs a triangle test per triangle

const std::string kSharedScenes = VKPT_SCENES_DIR "/../../shared/scenes";

// One layout of the scene: the tree (its leaves renumbered by the flattening), the wide nodes
// and the primitives in the order both walks index.
struct Layout {
    BvhTree tree;
    std::vector<gpu::WideBvhNode> nodes;
    std::vector<gpu::Triangle> triangles;
};

struct BuiltScene {
    BvhTree tree;
    StackBvh stackBvh;                        // the tree laid out for the ordered stack walk
    std::vector<gpu::WideBvhNode> nodes;      // collapsed opening the largest child first
    std::vector<gpu::Triangle> triangles;     // in the order tree and nodes index
    Layout tall;                              // collapsed opening the tallest child first
    std::vector<std::uint32_t> indexOfSource; // input triangle → its index in `triangles`
    Aabb bounds;
};

// The triangles in BVH order: triangle i is the input triangle primitiveOrder[i].
std::vector<gpu::Triangle> bvhOrderedTriangles(const std::vector<glm::vec3>& positions,
                                               const BvhTree& tree) {
    std::vector<gpu::Triangle> triangles;
    triangles.reserve(tree.primitiveOrder.size());
    for (std::uint32_t source : tree.primitiveOrder) {
        const glm::vec3* p = &positions[3 * std::size_t(source)];
        triangles.push_back({p[0], 0u, p[1], NO_EMITTER, p[2], source});
    }
    return triangles;
}

BuiltScene buildScene(const std::vector<glm::vec3>& positions) {
    BuiltScene s;
    s.tree = buildBvh(triangleBounds(positions));
    s.tall.tree = s.tree;
    s.nodes = flattenWideBvh(s.tree);
    s.triangles = bvhOrderedTriangles(positions, s.tree);
    s.stackBvh = makeStackBvh(s.tree, s.triangles);
    s.tall.nodes = flattenWideBvh(s.tall.tree, CollapseOrder::Tallest);
    s.tall.triangles = bvhOrderedTriangles(positions, s.tall.tree);
    s.indexOfSource.resize(s.triangles.size());
    for (std::uint32_t i = 0; i < s.triangles.size(); ++i)
        s.indexOfSource[s.triangles[i].sourceIndex] = i;
    s.bounds = s.tree.nodes[0].bounds;
    return s;
}

// A hit of the tall layout under the main layout's numbering (both keep sourceIndex).
ClosestHit renumbered(const BuiltScene& s, ClosestHit hit) {
    if (hit.hit) hit.triangle = s.indexOfSource[s.tall.triangles[hit.triangle].sourceIndex];
    return hit;
}

// Random rays of several kinds: from inside the bounds, from outside towards a point inside,
// from anywhere in any direction, axis-parallel (zero direction components), and, for scenes
// on an integer lattice, axis-parallel rays through lattice points (exactly along edges and
// through vertices). Some directions are not unit length and some rays have a finite range.
class RayGenerator {
public:
    RayGenerator(const Aabb& bounds, bool lattice, std::uint32_t seed)
        : rng_(seed), lattice_(lattice), lo_(bounds.min), hi_(bounds.max), centre_(bounds.centre()),
          size_(glm::length(bounds.max - bounds.min) > 0.0f ? glm::length(bounds.max - bounds.min)
                                                            : 1.0f) {}

    RayQuery next() {
        RayQuery ray = pick(rng_.below(lattice_ ? 5 : 4));
        if (rng_.below(8) == 0) {
            ray.tMin = rng_.uniform(0.0f, 0.5f * size_);
            ray.tMax = ray.tMin + rng_.uniform(0.0f, 2.0f * size_);
        }
        return ray;
    }

private:
    RayQuery pick(std::uint32_t kind) {
        glm::vec3 margin = 0.25f * (hi_ - lo_) + glm::vec3(0.001f * size_);
        switch (kind) {
        case 0:
            return {rng_.inBox(lo_, hi_), rng_.unitVector()};
        case 1: {
            glm::vec3 origin = centre_ + rng_.unitVector() * size_ * rng_.uniform(0.6f, 2.0f);
            glm::vec3 target = rng_.inBox(lo_, hi_);
            return {origin, (target - origin) * rng_.uniform(0.1f, 3.0f)};
        }
        case 2:
            return {rng_.inBox(lo_ - margin, hi_ + margin), rng_.unitVector()};
        case 3:
            return {rng_.inBox(lo_ - margin, hi_ + margin), axisDirection()};
        default:
            return {latticePoint(), axisDirection()};
        }
    }

    glm::vec3 axisDirection() {
        glm::vec3 d(0.0f);
        d[int(rng_.below(3))] = rng_.below(2) ? 1.0f : -1.0f;
        return d;
    }

    glm::vec3 latticePoint() {
        glm::vec3 p = rng_.inBox(lo_ - glm::vec3(1.0f), hi_ + glm::vec3(1.0f));
        return glm::floor(p);
    }

    synthetic::Rng rng_;
    bool lattice_;
    glm::vec3 lo_, hi_, centre_;
    float size_;
};

// Equal hits: both miss, or both hit at exactly the same t, on the same primitive with the same
// barycentrics or on two that really tie there. Walks prefer the lowest index among the
// crossings they find at one t (intersect.h), but each may pass over a box that holds another
// such crossing: box entries and the triangle test's t round differently (the latter's error
// grows with the triangle's size, not with t), so a box entered "just after" the best t can
// hold a crossing at that very t.
::testing::AssertionResult sameHit(const BuiltScene& s, const RayQuery& ray, const ClosestHit& a,
                                   const ClosestHit& b) {
    if (a.hit != b.hit) return ::testing::AssertionFailure() << "hit " << a.hit << " vs " << b.hit;
    if (!a.hit) return ::testing::AssertionSuccess();
    if (a.t != b.t)
        return ::testing::AssertionFailure()
               << std::setprecision(9) << "t " << a.t << " vs " << b.t << " (triangles "
               << a.triangle << ", " << b.triangle << ")";
    if (a.triangle == b.triangle) {
        if (a.u == b.u && a.v == b.v) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "same triangle, different barycentrics";
    }
    const float tMax = gpu::nextFloatUp(a.t);
    for (std::uint32_t index : {a.triangle, b.triangle}) {
        const gpu::Triangle& tri = s.triangles[index];
        gpu::TriangleHit h = gpu::intersectTriangle(ray.origin, ray.direction, tri.v0, tri.v1,
                                                    tri.v2, ray.tMin, tMax);
        if (!h.hit || h.t != a.t)
            return ::testing::AssertionFailure() << "triangle " << index << " does not tie";
    }
    return ::testing::AssertionSuccess();
}

struct WalkFigures {
    TraversalCounters stack;
    TraversalCounters wide;
    std::uint64_t maxStackNodes = 0;
    std::uint64_t maxWideNodes = 0;
    std::uint64_t maxWideIterations = 0; // nodes + triangle tests: the kernel's loops
    int hits = 0;
};

// Runs every query on one ray and checks that they agree; returns false after the first
// disagreement so that one bad scene does not print 10^5 failures.
bool checkRay(const BuiltScene& s, const RayQuery& ray, bool bruteForce, WalkFigures& f) {
    TraversalCounters stackCount, wideCount;
    ClosestHit stack = closestHitStack(s.stackBvh, ray, &stackCount);
    ClosestHit wide = closestHitWide(s.nodes, s.triangles, ray, &wideCount);
    f.stack.nodesVisited += stackCount.nodesVisited;
    f.stack.triangleTests += stackCount.triangleTests;
    f.wide.nodesVisited += wideCount.nodesVisited;
    f.wide.triangleTests += wideCount.triangleTests;
    f.maxStackNodes = std::max(f.maxStackNodes, stackCount.nodesVisited);
    f.maxWideNodes = std::max(f.maxWideNodes, wideCount.nodesVisited);
    f.maxWideIterations =
        std::max(f.maxWideIterations, wideCount.nodesVisited + wideCount.triangleTests);
    f.hits += stack.hit ? 1 : 0;
    EXPECT_TRUE(sameHit(s, ray, stack, wide)) << "stack vs wide, " << test::describeRay(ray);
    EXPECT_TRUE(
        sameHit(s, ray, stack, renumbered(s, closestHitWide(s.tall.nodes, s.tall.triangles, ray))))
        << "stack vs wide collapsed tallest first, " << test::describeRay(ray);
    if (bruteForce) {
        ClosestHit brute = closestHitBruteForce(s.triangles, ray);
        EXPECT_TRUE(sameHit(s, ray, brute, stack))
            << "brute force vs stack, " << test::describeRay(ray);
    }
    EXPECT_EQ(anyHitStack(s.stackBvh, ray), stack.hit) << test::describeRay(ray);
    EXPECT_EQ(anyHitWide(s.nodes, s.triangles, ray), stack.hit) << test::describeRay(ray);
    EXPECT_EQ(anyHitWide(s.tall.nodes, s.tall.triangles, ray), stack.hit) << test::describeRay(ray);
    if (stack.hit) {
        // Nothing lies strictly nearer than the closest hit (tMax is exclusive).
        RayQuery nearer = ray;
        nearer.tMax = stack.t;
        EXPECT_FALSE(anyHitStack(s.stackBvh, nearer)) << test::describeRay(ray);
        EXPECT_FALSE(anyHitWide(s.nodes, s.triangles, nearer)) << test::describeRay(ray);
    }
    return !::testing::Test::HasFailure();
}

void reportFigures(const std::string& name, const BuiltScene& s, const WalkFigures& f) {
    double rays = kRaysPerScene;
    std::ostringstream line;
    line << std::fixed << std::setprecision(1) << name << ": " << s.triangles.size()
         << " triangles, " << s.nodes.size() << " nodes, " << 100.0 * f.hits / rays
         << "% hit; nodes/ray stack " << double(f.stack.nodesVisited) / rays << " (max "
         << f.maxStackNodes << "), wide " << double(f.wide.nodesVisited) / rays << " (max "
         << f.maxWideNodes << ", max nodes + triangle tests " << f.maxWideIterations
         << "); triangle tests/ray stack " << double(f.stack.triangleTests) / rays << ", wide "
         << double(f.wide.triangleTests) / rays;
    std::cout << line.str() << "\n";
    ::testing::Test::RecordProperty("figures", line.str());
}

void checkAllWalksAgree(const std::string& name, const std::vector<glm::vec3>& positions,
                        bool lattice) {
    BuiltScene s = buildScene(positions);
    RayGenerator rays(s.bounds, lattice, 1234u);
    WalkFigures figures;
    for (int i = 0; i < kRaysPerScene; ++i)
        if (!checkRay(s, rays.next(), i < kBruteForceRays, figures)) return;
    reportFigures(name, s, figures);
}

// A scene file, or a skip when it is not there (the shared scenes live outside the repo).
void checkSceneFile(const std::string& path) {
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    Scene scene = loadGltfScene(path, options);
    ASSERT_GT(scene.triangleCount(), 0u) << path;
    checkAllWalksAgree(std::filesystem::path(path).filename().string(), scene.positions, false);
}

TEST(BvhTraverse, AllWalksAgreeOnARandomSoup) {
    checkAllWalksAgree("random soup", synthetic::randomSoup(20000, 31), false);
}

TEST(BvhTraverse, AllWalksAgreeOnACoplanarGrid) {
    checkAllWalksAgree("grid", synthetic::grid(100), true);
}

TEST(BvhTraverse, AllWalksAgreeOnAClosedCube) {
    checkAllWalksAgree("closed cube", synthetic::closedCube(40), true);
}

TEST(BvhTraverse, AllWalksAgreeOnADisplacedSphere) {
    checkAllWalksAgree("displaced sphere", synthetic::displacedSphere(100, 100), false);
}

TEST(BvhTraverse, AllWalksAgreeOnIdenticalTriangles) {
    std::vector<glm::vec3> positions;
    for (int i = 0; i < 200; ++i)
        positions.insert(positions.end(),
                         {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}});
    checkAllWalksAgree("identical triangles", positions, true);
}

TEST(BvhTraverse, AllWalksAgreeOnTheRepoCornellBox) {
    checkSceneFile(VKPT_SCENES_DIR "/cornell-box.gltf");
}

// The repo's Cornell box shrunk and blown up to the edges of the range where triangle tests
// hold (docs/numerical-stability.md; beyond 1e±18 products of coordinates leave the float
// range and the test reports crossings that lie outside the triangle, which walks with
// different boxes then find differently): the walks agree.
TEST(BvhTraverse, AllWalksAgreeOnTheCornellBoxAtExtremeScales) {
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    Scene scene = loadGltfScene(VKPT_SCENES_DIR "/cornell-box.gltf", options);
    for (float scale : {1e-18f, 1e-12f, 1e12f, 1e18f}) {
        std::vector<glm::vec3> positions = scene.positions;
        for (glm::vec3& p : positions)
            p *= scale;
        std::ostringstream name;
        name << "cornell box at scale " << scale;
        checkAllWalksAgree(name.str(), positions, false);
        if (::testing::Test::HasFailure()) return;
    }
}

TEST(BvhTraverse, AllWalksAgreeOnTheSharedBox) {
    checkSceneFile(kSharedScenes + "/Box/Box.glb");
}

TEST(BvhTraverse, AllWalksAgreeOnTheSharedCornellBox) {
    checkSceneFile(kSharedScenes + "/CornellBox/cornellBox.gltf");
}

TEST(BvhTraverse, AllWalksAgreeOnTheSharedDamagedHelmet) {
    checkSceneFile(kSharedScenes + "/DamagedHelmet/DamagedHelmet.glb");
}

// Two parallel unit squares at z = 1 and z = 2, shot from z = 0 along +z.
BuiltScene twoSquares() {
    std::vector<glm::vec3> positions = synthetic::grid(1);
    for (glm::vec3& p : positions)
        p.z = 1.0f;
    std::vector<glm::vec3> far = positions;
    for (glm::vec3& p : far)
        p.z = 2.0f;
    positions.insert(positions.end(), far.begin(), far.end());
    return buildScene(positions);
}

TEST(BvhTraverse, RespectsTheRayInterval) {
    BuiltScene s = twoSquares();
    RayQuery ray{glm::vec3(0.25f, 0.5f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)};
    EXPECT_EQ(closestHitStack(s.stackBvh, ray).t, 1.0f);
    EXPECT_EQ(closestHitWide(s.nodes, s.triangles, ray).t, 1.0f);
    ray.tMin = 1.0f; // exclusive: the near square is skipped
    EXPECT_EQ(closestHitStack(s.stackBvh, ray).t, 2.0f);
    EXPECT_EQ(closestHitWide(s.nodes, s.triangles, ray).t, 2.0f);
    ray.tMax = 2.0f; // exclusive: nothing left
    EXPECT_FALSE(closestHitStack(s.stackBvh, ray).hit);
    EXPECT_FALSE(closestHitWide(s.nodes, s.triangles, ray).hit);
    EXPECT_FALSE(anyHitStack(s.stackBvh, ray));
    EXPECT_FALSE(anyHitWide(s.nodes, s.triangles, ray));
}

TEST(BvhTraverse, ReturnsTheBvhOrderedIndexOfTheInputTriangle) {
    std::vector<glm::vec3> positions = synthetic::randomSoup(500, 32);
    BuiltScene s = buildScene(positions);
    synthetic::Rng rng(33);
    for (int i = 0; i < 200; ++i) {
        RayQuery ray{rng.inBox(s.bounds.min, s.bounds.max), rng.unitVector()};
        ClosestHit hit = closestHitWide(s.nodes, s.triangles, ray);
        if (!hit.hit) continue;
        std::uint32_t source = s.tree.primitiveOrder[hit.triangle];
        EXPECT_EQ(s.triangles[hit.triangle].sourceIndex, source);
        const glm::vec3* p = &positions[3 * std::size_t(source)];
        gpu::TriangleHit h =
            gpu::intersectTriangle(ray.origin, ray.direction, p[0], p[1], p[2], 0.0f, VKPT_FAR);
        EXPECT_TRUE(h.hit && h.t == hit.t);
    }
}

TEST(BvhTraverse, CountsBoxAndTriangleTests) {
    BuiltScene s = twoSquares();
    RayQuery ray{glm::vec3(0.25f, 0.5f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f)};
    TraversalCounters stack, wide;
    closestHitStack(s.stackBvh, ray, &stack);
    closestHitWide(s.nodes, s.triangles, ray, &wide);
    EXPECT_GT(stack.nodesVisited, 0u);
    EXPECT_GT(stack.triangleTests, 0u);
    EXPECT_EQ(wide.nodesVisited, 1u); // four triangles: one node, four leaves
    EXPECT_GT(wide.triangleTests, 0u);
    // A ray that misses every child box costs one node and no triangle test.
    TraversalCounters miss;
    RayQuery away{glm::vec3(5.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
    EXPECT_FALSE(closestHitWide(s.nodes, s.triangles, away, &miss).hit);
    EXPECT_EQ(miss.nodesVisited, 1u);
    EXPECT_EQ(miss.triangleTests, 0u);
}

// A ray running exactly along the cube's top front edge, from outside, first touches the
// cube at the corner vertex (0, n, n): the box test must let it through (intersect.h slabFar).
TEST(BvhTraverse, FindsAVertexHitAlongABoxEdge) {
    BuiltScene s = buildScene(synthetic::closedCube(4));
    RayQuery ray{glm::vec3(-1.0f, 4.0f, 4.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
    ClosestHit brute = closestHitBruteForce(s.triangles, ray);
    ASSERT_TRUE(brute.hit);
    EXPECT_EQ(brute.t, 1.0f);
    EXPECT_EQ(closestHitStack(s.stackBvh, ray).t, 1.0f);
    EXPECT_EQ(closestHitWide(s.nodes, s.triangles, ray).t, 1.0f);
}

} // namespace
} // namespace vkpt::bvh_traverse_test
