// bvh_build_bench.cpp — prints BVH build times and tree figures, and the cost of the ordered
// stack walk against the stackless skip-link walk, on a synthetic 1M-triangle surface and
// on glTF scenes. Prints figures; asserts nothing.
//
//     bvh_build_bench [scene.gltf ...]   (default: the repo's and the shared scenes)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "bench_statistics.h"
#include "bvh/bvh_flatten.h"
#include "bvh/bvh_traverse.h"
#include "bvh/synthetic_scenes.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "shared/intersect.h"

namespace vkpt {
namespace {

using vkpt::bench::median;

constexpr int kBuildRuns = 3;
constexpr int kTimedRuns = 3;
constexpr std::uint32_t kRays = 200000;

struct BenchScene {
    std::string name;
    std::vector<glm::vec3> positions;
    SceneCamera camera;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double medianSeconds(int runs, const std::function<void()>& work) {
    std::vector<double> seconds;
    for (int i = 0; i < runs; ++i) {
        auto start = std::chrono::steady_clock::now();
        work();
        seconds.push_back(secondsSince(start));
    }
    return median(seconds);
}

Bounds boundsOf(const std::vector<glm::vec3>& positions) {
    Bounds b;
    for (const glm::vec3& p : positions) {
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
    }
    return b;
}

// Camera rays through uniformly random image points of a square image.
std::vector<RayQuery> cameraRays(const SceneCamera& camera, std::uint32_t count) {
    synthetic::Rng rng(7);
    glm::vec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
    float tanHalf = std::tan(0.5f * camera.yfov);
    std::vector<RayQuery> rays;
    rays.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        float sx = rng.uniform(-1.0f, 1.0f) * tanHalf;
        float sy = rng.uniform(-1.0f, 1.0f) * tanHalf;
        glm::vec3 d = glm::normalize(camera.forward + sx * right + sy * camera.up);
        rays.push_back({camera.position, d});
    }
    return rays;
}

// Rays from inside the bounds in uniformly random directions, as after a diffuse bounce.
std::vector<RayQuery> scatteredRays(const Aabb& bounds, std::uint32_t count) {
    synthetic::Rng rng(8);
    std::vector<RayQuery> rays;
    rays.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i)
        rays.push_back({rng.inBox(bounds.min, bounds.max), rng.unitVector()});
    return rays;
}

struct WalkResult {
    double nodesPerRay = 0.0;
    double trianglesPerRay = 0.0;
    std::uint64_t maxNodes = 0;
    std::uint64_t maxIterations = 0; // nodes + triangle tests: a kernel's loop iterations
    double mraysPerSecond = -1.0;    // negative: not timed
};

using Walker = std::function<ClosestHit(const RayQuery&, TraversalCounters*)>;

// One counted pass for the work figures, then (if timed) passes without counters.
WalkResult measureWalk(const std::vector<RayQuery>& rays, const Walker& walk, bool timed = true) {
    WalkResult r;
    TraversalCounters total;
    for (const RayQuery& ray : rays) {
        TraversalCounters one;
        walk(ray, &one);
        total.nodesVisited += one.nodesVisited;
        total.triangleTests += one.triangleTests;
        r.maxNodes = std::max(r.maxNodes, one.nodesVisited);
        r.maxIterations = std::max(r.maxIterations, one.nodesVisited + one.triangleTests);
    }
    auto n = static_cast<double>(rays.size());
    r.nodesPerRay = static_cast<double>(total.nodesVisited) / n;
    r.trianglesPerRay = static_cast<double>(total.triangleTests) / n;
    if (!timed) return r;
    std::uint32_t hits = 0;
    double seconds = medianSeconds(kTimedRuns, [&] {
        for (const RayQuery& ray : rays)
            hits += walk(ray, nullptr).hit ? 1u : 0u;
    });
    r.mraysPerSecond = n / seconds * 1e-6;
    return r;
}

void printWalk(const char* label, const WalkResult& r) {
    std::printf("    %-26s %9.1f %9.2f %9llu %9llu ", label, r.nodesPerRay, r.trianglesPerRay,
                static_cast<unsigned long long>(r.maxNodes),
                static_cast<unsigned long long>(r.maxIterations));
    if (r.mraysPerSecond >= 0.0)
        std::printf("%9.2f\n", r.mraysPerSecond);
    else
        std::printf("%9s\n", "-");
}

struct BuiltScene {
    BvhTree tree;
    StackBvh stackBvh;               // the tree laid out for the ordered stack walk
    std::vector<gpu::BvhNode> nodes; // left child first
    std::vector<gpu::Triangle> triangles;
};

BuiltScene buildScene(const std::vector<glm::vec3>& positions) {
    BuiltScene s;
    s.tree = buildBvh(triangleBounds(positions));
    s.nodes = flattenBvh(s.tree);
    s.triangles.reserve(s.tree.primitiveOrder.size());
    for (std::uint32_t source : s.tree.primitiveOrder) {
        const glm::vec3* p = &positions[3 * std::size_t(source)];
        s.triangles.push_back({p[0], 0u, p[1], NO_EMITTER, p[2], source});
    }
    s.stackBvh = makeStackBvh(s.tree, s.triangles);
    return s;
}

void benchBuild(const BenchScene& scene) {
    std::vector<Aabb> bounds = triangleBounds(scene.positions);
    BvhBuildOptions oneThread;
    oneThread.threadCount = 1;
    double serial = medianSeconds(kBuildRuns, [&] { buildBvh(bounds, oneThread); });
    double parallel = medianSeconds(kBuildRuns, [&] { buildBvh(bounds); });
    BuiltScene built = buildScene(scene.positions);
    double flatten = medianSeconds(kBuildRuns, [&] { flattenBvh(built.tree); });
    BvhStats stats = computeBvhStats(built.tree);
    std::printf("  build: %.4f s on 1 thread, %.4f s on %u threads (median of %d); "
                "flatten %.4f s\n",
                serial, parallel, std::max(1u, std::thread::hardware_concurrency()), kBuildRuns,
                flatten);
    std::printf("  tree: %u nodes, %u leaves, depth %u, max leaf %u, SAH cost %.2f\n",
                stats.nodeCount, stats.leafCount, stats.maxDepth, stats.maxLeafSize,
                double(stats.sahCost));
}

// The walks of other stackless layouts, simulated by a recursive walk that tests each node's
// box on arrival (as a skip-link walk does) and picks the child order per node: a per-octant
// threaded BVH (8 orders, near child first along the split axis by the ray's direction sign)
// or a single fixed order that puts the larger box first.
using ChildOrder = std::function<bool(const BvhBuildNode& left, const BvhBuildNode& right,
                                      const RayQuery& ray)>; // true: right child first

struct SimulatedWalk {
    const BuiltScene& scene;
    const ChildOrder& rightFirst;
    const RayQuery& ray;
    glm::vec3 invDirection;
    ClosestHit best;
    TraversalCounters* counters;

    void visit(std::uint32_t index) {
        const BvhBuildNode& n = scene.tree.nodes[index];
        if (counters) ++counters->nodesVisited;
        if (gpu::intersectBox(ray.origin, invDirection, n.bounds.min, n.bounds.max, ray.tMin,
                              best.t) == VKPT_FAR)
            return;
        if (n.isLeaf()) return testLeaf(n);
        bool swap = rightFirst(scene.tree.nodes[n.leftChild], scene.tree.nodes[n.rightChild], ray);
        visit(swap ? n.rightChild : n.leftChild);
        visit(swap ? n.leftChild : n.rightChild);
    }

    void testLeaf(const BvhBuildNode& n) {
        for (std::uint32_t i = n.firstPrimitive; i < n.firstPrimitive + n.primitiveCount; ++i) {
            if (counters) ++counters->triangleTests;
            const gpu::Triangle& t = scene.triangles[i];
            gpu::TriangleHit h = gpu::intersectTriangle(ray.origin, ray.direction, t.v0, t.v1, t.v2,
                                                        ray.tMin, best.t);
            if (h.hit) best = {h.t, h.u, h.v, i, true};
        }
    }
};

ClosestHit closestHitSimulated(const BuiltScene& s, const ChildOrder& order, const RayQuery& ray,
                               TraversalCounters* counters) {
    SimulatedWalk walk{s, order, ray, gpu::safeInverseDirection(ray.direction), {}, counters};
    walk.best.t = ray.tMax;
    walk.visit(0);
    return walk.best;
}

// The builder does not keep split axes; the axis along which the children's centres lie
// furthest apart stands in for it.
bool octantRightFirst(const BvhBuildNode& left, const BvhBuildNode& right, const RayQuery& ray) {
    glm::vec3 gap = right.bounds.centre() - left.bounds.centre();
    glm::vec3 a = glm::abs(gap);
    int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    return (gap[axis] >= 0.0f) != (ray.direction[axis] >= 0.0f);
}

bool largerRightFirst(const BvhBuildNode& left, const BvhBuildNode& right, const RayQuery&) {
    return right.bounds.surfaceArea() > left.bounds.surfaceArea();
}

// cameraNodes: the tree flattened near child first along the camera's forward direction.
void benchTraversal(const BuiltScene& s, const char* label, const std::vector<RayQuery>& rays,
                    const std::vector<gpu::BvhNode>& cameraNodes) {
    std::printf("  %s, %zu rays, closest hit, 1 thread:\n", label, rays.size());
    std::printf("    %-26s %9s %9s %9s %9s %9s\n", "walk", "nodes/ray", "tris/ray", "max nodes",
                "max iter.", "Mrays/s");
    printWalk("stack (ordered)", measureWalk(rays, [&](const RayQuery& r, TraversalCounters* c) {
                  return closestHitStack(s.stackBvh, r, c);
              }));
    printWalk("stackless, left first",
              measureWalk(rays, [&](const RayQuery& r, TraversalCounters* c) {
                  return closestHitStackless(s.nodes, s.triangles, r, c);
              }));
    printWalk("stackless, camera order",
              measureWalk(rays, [&](const RayQuery& r, TraversalCounters* c) {
                  return closestHitStackless(cameraNodes, s.triangles, r, c);
              }));
    // Simulated walks print no speed: their recursion is not what the renderer would run.
    ChildOrder octant = octantRightFirst, larger = largerRightFirst;
    printWalk("octant-threaded (sim.)", measureWalk(
                                            rays,
                                            [&](const RayQuery& r, TraversalCounters* c) {
                                                return closestHitSimulated(s, octant, r, c);
                                            },
                                            false));
    printWalk("larger box first (sim.)", measureWalk(
                                             rays,
                                             [&](const RayQuery& r, TraversalCounters* c) {
                                                 return closestHitSimulated(s, larger, r, c);
                                             },
                                             false));
}

// The camera reflected through the centre of the bounds, looking the other way: a fixed child
// order that is far-first for one is near-first for the other.
SceneCamera mirrored(const SceneCamera& camera, const BuiltScene& s) {
    SceneCamera m = camera;
    m.position = 2.0f * s.tree.nodes[0].bounds.centre() - camera.position;
    m.forward = -camera.forward;
    return m;
}

void benchScene(const BenchScene& scene) {
    std::printf("\n%s: %zu triangles\n", scene.name.c_str(), scene.positions.size() / 3);
    benchBuild(scene);
    BuiltScene built = buildScene(scene.positions);
    SceneCamera back = mirrored(scene.camera, built);
    std::vector<gpu::BvhNode> cameraNodes = flattenBvh(built.tree, {scene.camera.forward});
    benchTraversal(built, "camera rays", cameraRays(scene.camera, kRays), cameraNodes);
    benchTraversal(built, "mirrored camera rays", cameraRays(back, kRays),
                   flattenBvh(built.tree, {back.forward}));
    // Secondary rays walk the nodes flattened for the camera, as in a render.
    benchTraversal(built, "scattered rays", scatteredRays(built.tree.nodes[0].bounds, kRays),
                   cameraNodes);
}

BenchScene syntheticSphere() {
    BenchScene scene{"displaced sphere (synthetic)", synthetic::displacedSphere(500, 1000), {}};
    scene.camera = makeFramingCamera(boundsOf(scene.positions), 1.0f);
    return scene;
}

// The file's first camera, or one that frames its bounds.
bool loadBenchScene(const std::string& path, BenchScene& scene) {
    try {
        LoadOptions options;
        options.warnUnsupportedExtensions = false;
        Scene loaded = loadGltfScene(path, options);
        scene.name = std::filesystem::path(path).filename().string();
        scene.camera = loaded.cameras.empty() ? makeFramingCamera(computeBounds(loaded), 1.0f)
                                              : loaded.cameras.front();
        scene.positions = std::move(loaded.positions);
        return !scene.positions.empty();
    } catch (const std::exception& e) {
        std::printf("\n%s: skipped: %s\n", path.c_str(), e.what());
        return false;
    }
}

std::vector<std::string> defaultScenePaths() {
    std::string shared = VKPT_SCENES_DIR "/../../shared/scenes";
    std::vector<std::string> paths{
        VKPT_SCENES_DIR "/cornell-box.gltf",    shared + "/Box/Box.glb",
        shared + "/CornellBox/cornellBox.gltf", shared + "/DamagedHelmet/DamagedHelmet.glb",
        shared + "/ToyCar/ToyCar.gltf",         shared + "/TransmissionTest/TransmissionTest.glb"};
    std::erase_if(paths, [](const std::string& p) { return !std::filesystem::exists(p); });
    return paths;
}

} // namespace
} // namespace vkpt

int main(int argc, char** argv) {
    using namespace vkpt;
    std::vector<std::string> paths(argv + 1, argv + argc);
    if (paths.empty()) {
        benchScene(syntheticSphere());
        paths = defaultScenePaths();
    }
    for (const std::string& path : paths) {
        BenchScene scene;
        if (loadBenchScene(path, scene)) benchScene(scene);
    }
    return 0;
}
