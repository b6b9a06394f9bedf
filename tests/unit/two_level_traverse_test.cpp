// two_level_traverse_test.cpp — walks of a two-level BVH (meshes placed by instances): the
// stackless wide walk (the kernels' code, shared/wide_bvh.h), the reference's two-level stack
// walk and brute force over every placed triangle agree on 10^4 random rays, with mirrored
// placements, placements that coincide exactly (ties go to the lower instance) and rays with
// −0 direction components (the walk's octant and its reciprocal must read the same sign).
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/ray_description.h"

#include "../support/instancing.h"
#include "bvh/bvh_traverse.h"
#include "bvh/wide_traverse.h"
#include "prepare/prepared_scene.h"
#include "reference/stack_intersector.h"
#include "shared/instance.h"

namespace vkpt::two_level_traverse_test {
namespace {

constexpr int kRays = 10000;
constexpr int kBruteForceRays = 2000;

struct TwoLevelScene {
    PreparedScene prepared;
    TwoLevelStackBvh stack;
    Aabb bounds;
};

TwoLevelScene buildScene(const Scene& scene) {
    TwoLevelScene s;
    s.prepared = prepareScene(scene);
    s.stack = makeTwoLevelStackBvh(s.prepared);
    s.bounds = s.prepared.instanceTree.nodes[0].bounds;
    return s;
}

// Brute force in the walks' own arithmetic: every instance's ray in its mesh's space against
// every triangle of the mesh, the best kept by instancedCrossingPrecedes.
ClosestHit bruteForce(const TwoLevelScene& s, const RayQuery& ray) {
    ClosestHit best;
    best.t = ray.tMax;
    for (std::uint32_t i = 0; i < s.prepared.instances.size(); ++i) {
        const gpu::Instance& x = s.prepared.instances[i];
        const PreparedMesh& mesh = s.prepared.meshes[x.mesh];
        const glm::vec3 origin = gpu::instanceRayOrigin(x, ray.origin);
        const glm::vec3 direction = gpu::instanceRayDirection(x, ray.direction);
        for (std::uint32_t p = mesh.firstPrimitive; p < mesh.firstPrimitive + mesh.primitiveCount;
             ++p) {
            const gpu::Triangle& tri = s.prepared.triangles[p];
            const float tMax = best.hit ? gpu::nextFloatUp(best.t) : best.t;
            gpu::TriangleHit h =
                gpu::intersectTriangle(origin, direction, tri.v0, tri.v1, tri.v2, ray.tMin, tMax);
            if (!h.hit || !gpu::instancedCrossingPrecedes(h.t, i, p, best.t, best.instance,
                                                          best.hit ? best.triangle : NO_PRIMITIVE))
                continue;
            best = {h.t, h.u, h.v, p, true, i};
        }
    }
    return best.hit ? best : ClosestHit{};
}

// The crossing of placed triangle (instance, primitive) at t, by the walks' arithmetic.
bool crossesAt(const TwoLevelScene& s, const RayQuery& ray, std::uint32_t instance,
               std::uint32_t primitive, float t) {
    const gpu::Instance& x = s.prepared.instances[instance];
    const gpu::Triangle& tri = s.prepared.triangles[primitive];
    gpu::TriangleHit h = gpu::intersectTriangle(gpu::instanceRayOrigin(x, ray.origin),
                                                gpu::instanceRayDirection(x, ray.direction), tri.v0,
                                                tri.v1, tri.v2, ray.tMin, gpu::nextFloatUp(t));
    return h.hit && h.t == t;
}

// Equal hits: both miss, or both at exactly the same t on the same placed triangle with the
// same barycentrics, or on two placed triangles that really tie there (a walk may pass over a
// box entered just beyond the best t that holds a tying crossing: bvh_traverse_test.cpp).
::testing::AssertionResult sameHit(const TwoLevelScene& s, const RayQuery& ray, const ClosestHit& a,
                                   const ClosestHit& b) {
    if (a.hit != b.hit) return ::testing::AssertionFailure() << "hit " << a.hit << " vs " << b.hit;
    if (!a.hit) return ::testing::AssertionSuccess();
    if (a.t != b.t)
        return ::testing::AssertionFailure()
               << std::setprecision(9) << "t " << a.t << " vs " << b.t;
    if (a.triangle == b.triangle && a.instance == b.instance) {
        if (a.u == b.u && a.v == b.v) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "same triangle, different barycentrics";
    }
    if (crossesAt(s, ray, a.instance, a.triangle, a.t) &&
        crossesAt(s, ray, b.instance, b.triangle, b.t))
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "instance " << a.instance << " triangle " << a.triangle << " vs instance "
           << b.instance << " triangle " << b.triangle << ": no tie";
}

// Random rays as bvh_traverse_test makes them, rays aimed at the placements (most of the scene's
// volume is empty), and axis-parallel ones whose zero components are −0 or +0 at random.
class RayMaker {
public:
    explicit RayMaker(const TwoLevelScene& s) : rng_(99), lo_(s.bounds.min), hi_(s.bounds.max) {
        for (const gpu::Instance& x : s.prepared.instances)
            targets_.push_back(
                glm::vec3(x.objectToWorld0.w, x.objectToWorld1.w, x.objectToWorld2.w));
    }

    RayQuery next() {
        const glm::vec3 centre = 0.5f * (lo_ + hi_);
        const float size = glm::length(hi_ - lo_);
        switch (rng_.below(5)) {
        case 0:
            return {rng_.inBox(lo_, hi_), rng_.unitVector()};
        case 1: {
            const glm::vec3 origin = centre + rng_.unitVector() * size * rng_.uniform(0.6f, 2.0f);
            return {origin, (rng_.inBox(lo_, hi_) - origin) * rng_.uniform(0.1f, 3.0f)};
        }
        case 2: {
            RayQuery ray{rng_.inBox(lo_, hi_), rng_.unitVector()};
            ray.tMin = rng_.uniform(0.0f, 0.2f * size);
            ray.tMax = ray.tMin + rng_.uniform(0.0f, size);
            return ray;
        }
        case 3: {
            const glm::vec3 target = targets_[rng_.below(std::uint32_t(targets_.size()))] +
                                     rng_.inBox(glm::vec3(-1.0f), glm::vec3(1.0f));
            const glm::vec3 origin = target + rng_.unitVector() * size * rng_.uniform(0.1f, 1.0f);
            return {origin, target - origin};
        }
        default: {
            glm::vec3 d(rng_.below(2) ? 0.0f : -0.0f, rng_.below(2) ? 0.0f : -0.0f,
                        rng_.below(2) ? 0.0f : -0.0f);
            d[int(rng_.below(3))] = rng_.below(2) ? 1.0f : -1.0f;
            return {rng_.inBox(lo_, hi_), d};
        }
        }
    }

private:
    synthetic::Rng rng_;
    glm::vec3 lo_, hi_;
    std::vector<glm::vec3> targets_; // where the instances put their meshes' origins
};

void checkWalksAgree(const Scene& scene) {
    const TwoLevelScene s = buildScene(scene);
    ASSERT_FALSE(s.prepared.instances.empty());
    RayMaker rays(s);
    int hits = 0;
    for (int i = 0; i < kRays; ++i) {
        const RayQuery ray = rays.next();
        const ClosestHit stack = closestHitTwoLevel(s.stack, ray);
        const ClosestHit wide =
            closestHitWide(s.prepared.nodes, s.prepared.triangles, s.prepared.instances, ray);
        hits += stack.hit ? 1 : 0;
        EXPECT_TRUE(sameHit(s, ray, stack, wide)) << "stack vs wide, " << test::describeRay(ray);
        if (i < kBruteForceRays) {
            EXPECT_TRUE(sameHit(s, ray, bruteForce(s, ray), stack))
                << "brute force vs stack, " << test::describeRay(ray);
        }
        EXPECT_EQ(anyHitTwoLevel(s.stack, ray), stack.hit) << test::describeRay(ray);
        EXPECT_EQ(anyHitWide(s.prepared.nodes, s.prepared.triangles, s.prepared.instances, ray),
                  stack.hit)
            << test::describeRay(ray);
        if (stack.hit) {
            RayQuery nearer = ray;
            nearer.tMax = stack.t;
            EXPECT_FALSE(
                anyHitWide(s.prepared.nodes, s.prepared.triangles, s.prepared.instances, nearer))
                << test::describeRay(ray);
        }
        if (::testing::Test::HasFailure()) return;
    }
    EXPECT_GT(hits, kRays / 10); // the rays meet the scene
}

std::vector<std::vector<glm::vec3>> someMeshes() {
    return {synthetic::randomSoup(400, 5, 3.0f, 0.6f), synthetic::closedCube(3),
            synthetic::displacedSphere(8, 16), synthetic::grid(4)};
}

TEST(TwoLevelTraverse, AllWalksAgreeOnRandomPlacements) {
    checkWalksAgree(test::randomInstancedScene(someMeshes(), 6, 17));
}

TEST(TwoLevelTraverse, AllWalksAgreeOnManyPlacementsOfOneMesh) {
    checkWalksAgree(test::randomInstancedScene({synthetic::closedCube(2)}, 200, 23));
}

// One instance and no geometry of the scene's own: a top level of a single leaf.
TEST(TwoLevelTraverse, AllWalksAgreeOnASingleInstance) {
    Scene scene = test::randomInstancedScene({synthetic::displacedSphere(6, 12)}, 1, 7);
    static_cast<TriangleSoup&>(scene) = TriangleSoup{};
    scene.instances.resize(1);
    checkWalksAgree(scene);
}

// Two placements at the very same place cross every ray at the same t: the lower instance wins,
// whichever the walk meets first.
TEST(TwoLevelTraverse, CoincidentPlacementsTieToTheLowerInstance) {
    Scene scene = test::randomInstancedScene({synthetic::closedCube(1)}, 1, 3);
    ASSERT_EQ(scene.instances.size(), 2u); // the first placement is made twice
    const TwoLevelScene s = buildScene(scene);
    std::vector<std::uint32_t> placedTwice;
    for (std::uint32_t i = 0; i < s.prepared.instances.size(); ++i)
        if (s.prepared.instances[i].mesh != 0) placedTwice.push_back(i); // 0: the scene's own
    ASSERT_EQ(placedTwice.size(), 2u);
    const gpu::Instance& x = s.prepared.instances[placedTwice[0]];
    const glm::vec3 centre = gpu::instancePointToWorld(x, glm::vec3(0.5f)); // the cube's centre
    int hits = 0;
    RayMaker rays(s);
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 origin = centre + 30.0f * rays.next().direction;
        const RayQuery ray{origin, centre - origin};
        const ClosestHit wide =
            closestHitWide(s.prepared.nodes, s.prepared.triangles, s.prepared.instances, ray);
        const ClosestHit stack = closestHitTwoLevel(s.stack, ray);
        if (!stack.hit) continue;
        if (s.prepared.instances[stack.instance].mesh == 0) continue; // the scene's own
        ++hits;
        EXPECT_EQ(stack.instance, placedTwice[0]) << test::describeRay(ray);
        EXPECT_EQ(wide.instance, placedTwice[0]) << test::describeRay(ray);
    }
    EXPECT_GT(hits, 100);
}

} // namespace
} // namespace vkpt::two_level_traverse_test
