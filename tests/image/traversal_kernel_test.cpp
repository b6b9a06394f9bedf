// traversal_kernel_test.cpp — trace_closest and trace_shadow, run on uploaded ray lists, return
// what the reference's ordered stack walk returns (its StackIntersectors: one level or two) on
// 10^4 rays per scene: the Cornell box, the deep-BVH scene (whose long walks lavapipe's loop
// limit would cut short), scenes with spheres and alpha-masked cut-outs (the reference's
// AlphaMaskFilter), two-level scenes (meshes placed by instances) and a shared glTF scene. A last
// test builds a BVH whose walks must exceed that limit and checks that the kernels report it
// instead of answering wrongly in silence.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "../support/instancing.h"
#include "../support/ray_queries.h"
#include "bvh/bvh_traverse.h"
#include "bvh/synthetic_scenes.h"
#include "bvh/wide_traverse.h"
#include "feature_scenes.h"
#include "reference/stack_intersector.h"
#include "shared/camera.h"
#include "shared/intersect.h"
#include "shared/sphere.h"
#include "shared/wide_bvh.h"
#include "wavefront_test_support.h"

namespace vkpt::test::traversal_kernel_test {
namespace {

using feature_scenes::featureScenes;
using feature_scenes::NamedScene;
using feature_scenes::prepareTestScene;

constexpr int kRays = 10000;

// The root box of the scene's tree, or of its top level.
Aabb sceneBounds(const PreparedScene& scene) {
    return (scene.features.instances ? scene.instanceTree : scene.tree).nodes[0].bounds;
}

// Rays of three kinds: from the scene's camera through its field of view (the rays a render
// starts with; through the deep part of the deep-BVH scene), from inside the bounds in any
// direction, and from outside towards a point inside.
class RayMaker {
public:
    RayMaker(const LoadedTestScene& scene, std::uint32_t seed)
        : rng_(seed), bounds_(sceneBounds(scene.prepared)),
          camera_(makeGpuCamera(selectCamera(scene.scene, std::nullopt, 1.0f), 64, 64)) {}

    DeviceRay next() {
        glm::vec3 lo = bounds_.min, hi = bounds_.max;
        float size = std::max(glm::length(hi - lo), 1e-3f);
        switch (rng_.below(3)) {
        case 0: {
            glm::vec2 film(rng_.uniform(0.0f, 64.0f), rng_.uniform(0.0f, 64.0f));
            return {camera_.position, gpu::cameraRayDirection(camera_, film)};
        }
        case 1:
            return {rng_.inBox(lo, hi), rng_.unitVector()};
        default: {
            glm::vec3 origin =
                bounds_.centre() + rng_.unitVector() * size * rng_.uniform(0.6f, 2.0f);
            return {origin, rng_.inBox(lo, hi) - origin};
        }
        }
    }

    // A shadow-ray segment: the direction scaled to a random length, tested for t in (0, 1).
    DeviceRay nextSegment() {
        DeviceRay ray = next();
        float size = std::max(glm::length(bounds_.max - bounds_.min), 1e-3f);
        ray.direction = glm::normalize(ray.direction) * size * rng_.uniform(0.0f, 1.5f);
        ray.tMax = 1.0f;
        return ray;
    }

private:
    synthetic::Rng rng_;
    Aabb bounds_;
    gpu::Camera camera_;
};

std::string describe(const DeviceRay& ray) {
    std::ostringstream s;
    s << std::setprecision(9) << "o=(" << ray.origin.x << ", " << ray.origin.y << ", "
      << ray.origin.z << ") d=(" << ray.direction.x << ", " << ray.direction.y << ", "
      << ray.direction.z << ")";
    return s.str();
}

// Equal answers: both miss, or both hit at the same t (relative 1e-6: a device may fuse
// multiply-adds) on the same triangle with the same barycentrics, or on two triangles that
// really tie there (a shared edge, where the two walks' orders pick differently).
// The instance's ray (the world ray itself in a scene of one level) meets primitive `index` at
// about t.
bool crossesNear(const PreparedScene& scene, const DeviceRay& ray, std::uint32_t instance,
                 std::uint32_t index, float t, float tolerance) {
    glm::vec3 origin = ray.origin, direction = ray.direction;
    if (instance != NO_INSTANCE) {
        origin = gpu::instanceRayOrigin(scene.instances[instance], ray.origin);
        direction = gpu::instanceRayDirection(scene.instances[instance], ray.direction);
    }
    const gpu::Triangle& tri = scene.triangles[index];
    gpu::TriangleHit h =
        gpu::isSpherePrimitive(tri)
            ? gpu::intersectSphere(origin, direction, tri.v0, tri.v1.x, 0.0f, VKPT_FAR)
            : gpu::intersectTriangle(origin, direction, tri.v0, tri.v1, tri.v2, 0.0f, VKPT_FAR);
    return h.hit && std::abs(h.t - t) <= tolerance * std::max(1.0f, std::abs(t));
}

bool sameClosestHit(const PreparedScene& scene, const DeviceRay& ray, const gpu::HitRecord& g,
                    std::uint32_t gInstance, const ClosestHit& c) {
    bool gpuHit = g.triangle != NO_HIT;
    if (gpuHit != c.hit) return false;
    if (!c.hit) return true;
    auto close = [](float a, float b, float tolerance) {
        return std::abs(a - b) <= tolerance * std::max(1.0f, std::abs(b));
    };
    // An instance's ray starts at the world origin moved into the mesh's space, rounded (with
    // fused multiply-adds on the device) to a few 1e-7 of the origin's coordinates: for a small
    // placed triangle met at a glancing angle, far from the origin, that moves t and the
    // barycentrics by up to about 1e-5 and a few 1e-4 (the test prints the largest it meets).
    const bool instanced = gInstance != NO_INSTANCE;
    const float tTolerance = instanced ? 1e-4f : 1e-6f;
    const float barycentricTolerance = instanced ? 1e-3f : 1e-5f;
    if (!close(g.t, c.t, tTolerance)) return false;
    if (g.triangle == c.triangle && gInstance == c.instance)
        return close(g.u, c.u, barycentricTolerance) && close(g.v, c.v, barycentricTolerance);
    return crossesNear(scene, ray, gInstance, g.triangle, c.t, tTolerance);
}

// The largest differences between the device's and the stack walk's hits on one placed
// triangle, for the test's line.
struct HitDifferences {
    float t = 0.0f; // relative
    float barycentric = 0.0f;

    void add(const gpu::HitRecord& g, const ClosestHit& c) {
        if (!c.hit || g.triangle != c.triangle) return;
        t = std::max(t, std::abs(g.t - c.t) / std::max(1.0f, std::abs(c.t)));
        barycentric = std::max({barycentric, std::abs(g.u - c.u), std::abs(g.v - c.v)});
    }
};

struct WalkFigures {
    double meanNodes = 0.0;
    std::uint64_t maxNodes = 0; // of the wide walk (the device's code), on the CPU
};

WalkFigures wideWalkFigures(const PreparedScene& scene, const std::vector<DeviceRay>& rays) {
    WalkFigures f;
    std::uint64_t total = 0;
    for (const DeviceRay& ray : rays) {
        TraversalCounters counters;
        closestHitWide(scene.nodes, scene.triangles, scene.instances, {ray.origin, ray.direction},
                       &counters);
        total += counters.nodesVisited;
        f.maxNodes = std::max(f.maxNodes, counters.nodesVisited);
    }
    f.meanNodes = double(total) / double(rays.size());
    return f;
}

class DeviceTraversal : public GpuTest {
protected:
    void expectClosestMatchesStack(const LoadedTestScene& scene, const std::string& name) {
        RayMaker maker(scene, 7);
        std::vector<DeviceRay> rays;
        for (int i = 0; i < kRays; ++i)
            rays.push_back(maker.next());
        DeviceRayQueries queries(context(), scene.prepared);
        std::vector<std::uint32_t> instances;
        std::vector<gpu::HitRecord> hits = queries.closest(rays, &instances);
        StackIntersectors intersectors(scene.prepared); // with the alpha filter, one or two levels
        std::unique_ptr<SceneIntersector> stack = intersectors.makeIntersector();
        int disagreements = 0, hitCount = 0;
        HitDifferences differences;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            ClosestHit cpu = stack->closestHit(rays[i].origin, rays[i].direction, 0.0f);
            hitCount += cpu.hit ? 1 : 0;
            if (instances[i] == cpu.instance) differences.add(hits[i], cpu);
            if (sameClosestHit(scene.prepared, rays[i], hits[i], instances[i], cpu)) continue;
            if (++disagreements <= 5)
                ADD_FAILURE() << name << ": ray " << i << " " << describe(rays[i]) << ": device "
                              << hits[i].triangle << " (instance " << instances[i] << ") at t "
                              << hits[i].t << ", stack " << (cpu.hit ? int(cpu.triangle) : -1)
                              << " (instance " << cpu.instance << ") at t " << cpu.t;
        }
        WalkFigures figures = wideWalkFigures(scene.prepared, rays);
        std::printf("%s: %zu triangles, %d of %d rays hit, %d disagreements (largest relative t "
                    "difference %.2g, barycentric %.2g); wide walk on the CPU %.1f nodes per ray "
                    "(max %llu); device %.1f nodes per ray\n",
                    name.c_str(), scene.prepared.triangles.size(), hitCount, kRays, disagreements,
                    double(differences.t), double(differences.barycentric), figures.meanNodes,
                    (unsigned long long)figures.maxNodes, double(queries.nodesVisited()) / kRays);
        EXPECT_EQ(disagreements, 0);
        EXPECT_GT(hitCount, kRays / 10) << "too few hits to test anything";
        EXPECT_EQ(queries.truncatedTraversals(), 0u);
    }

    void expectAnyHitMatchesStack(const LoadedTestScene& scene, const std::string& name) {
        RayMaker maker(scene, 11);
        std::vector<DeviceRay> rays;
        for (int i = 0; i < kRays; ++i)
            rays.push_back(maker.nextSegment());
        DeviceRayQueries queries(context(), scene.prepared);
        std::vector<bool> occluded = queries.occluded(rays);
        StackIntersectors intersectors(scene.prepared);
        std::unique_ptr<SceneIntersector> stack = intersectors.makeIntersector();
        int disagreements = 0, blocked = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            bool cpu = stack->occluded(rays[i].origin, rays[i].direction, rays[i].tMax);
            blocked += cpu ? 1 : 0;
            if (occluded[i] == cpu) continue;
            if (++disagreements <= 5)
                ADD_FAILURE() << name << ": segment " << i << " " << describe(rays[i])
                              << ": device " << occluded[i] << ", stack " << cpu;
        }
        std::printf("%s: %d of %d segments blocked, %d disagreements\n", name.c_str(), blocked,
                    kRays, disagreements);
        EXPECT_EQ(disagreements, 0);
        EXPECT_GT(blocked, kRays / 20);
        EXPECT_LT(blocked, kRays - kRays / 20);
        EXPECT_EQ(queries.truncatedTraversals(), 0u);
    }
};

TEST_F(DeviceTraversal, ClosestHitsMatchTheStackWalkInTheCornellBox) {
    expectClosestMatchesStack(loadTestScene("cornell-box.gltf"), "cornell-box");
}

TEST_F(DeviceTraversal, AnyHitsMatchTheStackWalkInTheCornellBox) {
    expectAnyHitMatchesStack(loadTestScene("cornell-box.gltf"), "cornell-box");
}

TEST_F(DeviceTraversal, ClosestHitsMatchTheStackWalkInTheDeepBvh) {
    expectClosestMatchesStack(loadTestScene("test/deep-bvh.gltf"), "deep-bvh");
}

TEST_F(DeviceTraversal, AnyHitsMatchTheStackWalkInTheDeepBvh) {
    expectAnyHitMatchesStack(loadTestScene("test/deep-bvh.gltf"), "deep-bvh");
}

// Spheres among the triangles, and alpha cut-outs (textured, on triangles and on a sphere).
TEST_F(DeviceTraversal, SpheresAndAlphaCutOutsMatchTheStackWalk) {
    for (const NamedScene& named : featureScenes()) {
        if (named.name != "spheres" && named.name != "alpha_mask") continue;
        LoadedTestScene scene = prepareTestScene(named.make());
        expectClosestMatchesStack(scene, named.name);
        expectAnyHitMatchesStack(scene, named.name);
    }
}

// Ten alpha-masked screens stacked 2 cm apart in front of the wall, each with its own pattern
// of holes: a ray crosses several cut-outs before it stops, and the BVH puts screens side by
// side in one leaf, so the walk must pause for the alpha test in the middle of a leaf and
// resume there (lib/traverse.glsl), for the closest hit and for any hit.
Scene stackedCutOutScene() {
    using namespace feature_scenes;
    Scene scene = cornerWithMaterials();
    int holes = addTexture(
        scene, 8, 8,
        [](std::uint32_t x, std::uint32_t y) {
            return glm::uvec4(200, 200, 200, (x / 2 + y / 2) % 2 ? 255 : 0);
        },
        true);
    for (int k = 0; k < 10; ++k) {
        std::uint32_t screen = addMaterial(scene, {{0.9f, 0.9f, 0.9f}, {}, 0.0f, 1.0f, 0.0f, true});
        scene.materials[screen].alphaMode = AlphaMode::Mask;
        scene.materials[screen].baseColorTexture.texture = holes;
        const float z = 1.0f - 0.02f * float(k);
        addQuad(scene, {-1.5f, 0.0f, z}, {1.5f, 0.0f, z}, {1.5f, 3.0f, z}, {-1.5f, 3.0f, z}, screen,
                1.3f + 0.37f * float(k));
    }
    return scene;
}

// The most alpha-masked primitives any leaf of the wide tree holds.
std::uint32_t mostMaskedPrimitivesInALeaf(const PreparedScene& scene) {
    std::uint32_t most = 0;
    for (const gpu::WideBvhNode& node : scene.nodes) {
        for (std::uint32_t slot = 0; slot < WIDE_BVH_WIDTH; ++slot) {
            const std::uint32_t count = gpu::wideLeafCount(node.leafCounts, slot);
            const std::uint32_t first =
                node.primitiveBase + gpu::wideLeafOffset(node.leafCounts, slot);
            std::uint32_t masked = 0;
            for (std::uint32_t i = first; i < first + count; ++i)
                masked +=
                    scene.materials[scene.triangles[i].materialIndex].alphaMode == ALPHA_MODE_MASK
                        ? 1
                        : 0;
            most = std::max(most, masked);
        }
    }
    return most;
}

TEST_F(DeviceTraversal, WalksResumeAfterCutOutsInsideALeaf) {
    LoadedTestScene scene = prepareTestScene(stackedCutOutScene());
    // Three masked triangles in a leaf are two screens' at least: a ray can cross both.
    ASSERT_GE(mostMaskedPrimitivesInALeaf(scene.prepared), 3u)
        << "the BVH no longer puts screens together; the test would not resume inside a leaf";
    expectClosestMatchesStack(scene, "stacked cut-outs");
    expectAnyHitMatchesStack(scene, "stacked cut-outs");
}

// Two levels: meshes placed by turned, scaled and mirrored instances (some placed twice at one
// place: ties go to the lower instance on both sides), beside the scene's own triangles.
TEST_F(DeviceTraversal, TwoLevelWalksMatchTheStackWalk) {
    LoadedTestScene scene{
        test::randomInstancedScene({synthetic::closedCube(3), synthetic::displacedSphere(8, 16),
                                    synthetic::randomSoup(300, 9, 3.0f, 0.6f)},
                                   40, 41),
        {}};
    scene.prepared = prepareScene(scene.scene);
    ASSERT_TRUE(scene.prepared.features.instances);
    expectClosestMatchesStack(scene, "instances");
    expectAnyHitMatchesStack(scene, "instances");
}

// The feature scenes with spheres and alpha cut-outs as one mesh placed by an instance (the
// spheres stay in the scene's own level).
TEST_F(DeviceTraversal, TwoLevelSpheresAndAlphaCutOutsMatchTheStackWalk) {
    for (const NamedScene& named : featureScenes()) {
        if (named.name != "spheres" && named.name != "alpha_mask") continue;
        glm::dmat4 placement = glm::rotate(glm::dmat4(1.0), 0.4, glm::dvec3(0.0, 1.0, 0.0));
        placement = glm::scale(placement, glm::dvec3(-1.0, 1.0, 1.0));
        LoadedTestScene scene = prepareTestScene(test::instanceWholeScene(named.make(), placement));
        ASSERT_TRUE(scene.prepared.features.instances);
        expectClosestMatchesStack(scene, named.name + " instanced");
        expectAnyHitMatchesStack(scene, named.name + " instanced");
    }
}

TEST_F(DeviceTraversal, ClosestAndAnyHitsMatchTheStackWalkInASharedScene) {
    const std::string path = sharedScenePath("Box/Box.glb");
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is not there";
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    LoadedTestScene box{loadGltfScene(path, options), {}};
    box.prepared = prepareScene(box.scene);
    expectClosestMatchesStack(box, "Box.glb");
    expectAnyHitMatchesStack(box, "Box.glb");
}

// Triangles in the planes x = i·h, each with a bounding box that contains the x axis while the
// triangle itself leaves it out, and beyond them one triangle across the axis: a ray along the
// axis enters every box of the tree, so its walk visits every node and tests every triangle,
// and only a walk that reaches the end finds the hit.
Scene wallOfNearMisses(std::uint32_t triangles) {
    Scene scene;
    scene.materials.push_back(SceneMaterial{});
    auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        glm::vec3 n(-1.0f, 0.0f, 0.0f);
        scene.positions.insert(scene.positions.end(), {a, b, c});
        scene.normals.insert(scene.normals.end(), {n, n, n});
        scene.materialIndices.push_back(0);
    };
    for (std::uint32_t i = 0; i < triangles; ++i) {
        float x = float(i) * 1e-3f;
        // In (y, z): (-1, -1), (1, -1), (1, 0.9); the axis point (0, 0) lies above the long edge.
        add({x, -1.0f, -1.0f}, {x, 1.0f, -1.0f}, {x, 1.0f, 0.9f});
    }
    float end = float(triangles) * 1e-3f + 1.0f;
    add({end, -1.0f, -1.0f}, {end, 1.0f, -1.0f}, {end, 0.0f, 1.0f});
    return scene;
}

struct LongWalk {
    // Loop condition tests of one walk, as lavapipe's budget counts them (docs/gpu.md), from
    // above: a test per triangle, and per node one of the node loop and the final tests of the
    // leaf and climb loops, plus a climb each.
    std::uint64_t iterations = 0;
    std::uint32_t truncated = 0; // of 64 device walks
    std::uint32_t found = 0;     // device walks that found the far triangle
};

LongWalk walkTheWall(GpuContext& context, std::uint32_t triangles) {
    PreparedScene prepared = prepareScene(wallOfNearMisses(triangles));
    DeviceRay ray{glm::vec3(-1.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
    TraversalCounters counters;
    ClosestHit cpu =
        closestHitWide(prepared.nodes, prepared.triangles, {ray.origin, ray.direction}, &counters);
    EXPECT_TRUE(cpu.hit);
    DeviceRayQueries queries(context, prepared, 64);
    LongWalk walk;
    walk.iterations = 4 * counters.nodesVisited + counters.triangleTests;
    for (const gpu::HitRecord& hit : queries.closest(std::vector<DeviceRay>(64, ray)))
        walk.found += hit.triangle == cpu.triangle ? 1 : 0;
    walk.truncated = queries.truncatedTraversals();
    std::printf("a walk of %llu nodes and %llu triangle tests: %u of 64 device walks cut short, "
                "%u found the far triangle\n",
                (unsigned long long)counters.nodesVisited,
                (unsigned long long)counters.triangleTests, walk.truncated, walk.found);
    return walk;
}

// Tens of thousands of iterations, under lavapipe's budget of 65,535: every walk completes.
TEST_F(DeviceTraversal, LongWalksWithinTheLoopBudgetComplete) {
    LongWalk walk = walkTheWall(context(), 40000);
    ASSERT_GT(walk.iterations, 30000u);
    ASSERT_LT(walk.iterations, 60000u);
    EXPECT_EQ(walk.truncated, 0u);
    EXPECT_EQ(walk.found, 64u);
}

// On lavapipe (Mesa 22.3) a walk past the budget stops early; the kernels must count it (the
// renderer then warns) rather than answer wrongly in silence. A conforming device completes it.
TEST_F(DeviceTraversal, WalksCutShortByALoopLimitAreReported) {
    LongWalk walk = walkTheWall(context(), 400000);
    ASSERT_GT(walk.iterations, 65535u);
    if (context().deviceInfo().driverId == VK_DRIVER_ID_MESA_LLVMPIPE) {
        EXPECT_EQ(walk.truncated, 64u) << "lavapipe's loop limit did not show: see docs/gpu.md";
    } else {
        EXPECT_EQ(walk.truncated, 0u);
        EXPECT_EQ(walk.found, 64u);
    }
}

} // namespace
} // namespace vkpt::test::traversal_kernel_test
