// bvh_build_bench.cpp — prints BVH build and collapse times, tree figures, and the cost of the
// reference's ordered stack walk against the device's stackless wide walk run on the CPU, on
// a synthetic 1M-triangle surface and on glTF scenes; where Embree 3 is installed, its own
// builder on the same triangles and threads. Prints figures; asserts nothing.
//
//     bvh_build_bench [--build-only] [scene.gltf ...]   (default: the repo's and the shared scenes)
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

#include "app/run_program.h"
#include "bench_options.h"
#include "bench_statistics.h"
#include "bvh/bvh_traverse.h"
#include "bvh/bvh_wide.h"
#include "bvh/synthetic_scenes.h"
#include "bvh/wide_traverse.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "shared/intersect.h"

#ifdef VKPT_HAVE_EMBREE
#include "embree/embree_build.h"
#endif

namespace vkpt {
namespace {

using vkpt::bench::median;

// Odd, for a median; enough that one run slowed by the shared machine does not move it.
constexpr int kBuildRuns = 7;
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
    double mraysPerSecond = 0.0;
};

using Walker = std::function<ClosestHit(const RayQuery&, TraversalCounters*)>;

// One counted pass for the work figures, then timed passes without counters.
WalkResult measureWalk(const std::vector<RayQuery>& rays, const Walker& walk) {
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
    std::uint32_t hits = 0;
    double seconds = medianSeconds(kTimedRuns, [&] {
        for (const RayQuery& ray : rays)
            hits += walk(ray, nullptr).hit ? 1u : 0u;
    });
    r.mraysPerSecond = n / seconds * 1e-6;
    return r;
}

void printWalk(const char* label, const WalkResult& r) {
    std::printf("    %-26s %9.1f %9.2f %9llu %9llu %9.2f\n", label, r.nodesPerRay,
                r.trianglesPerRay, static_cast<unsigned long long>(r.maxNodes),
                static_cast<unsigned long long>(r.maxIterations), r.mraysPerSecond);
}

struct BuiltScene {
    BvhTree tree;      // leaves renumbered by flattenWideBvh
    StackBvh stackBvh; // the tree laid out for the ordered stack walk
    std::vector<gpu::WideBvhNode> nodes;
    std::vector<gpu::Triangle> triangles;
};

BuiltScene buildScene(const std::vector<glm::vec3>& positions) {
    BuiltScene s;
    s.tree = buildBvh(triangleBounds(positions));
    s.nodes = flattenWideBvh(s.tree);
    s.triangles.reserve(s.tree.primitiveOrder.size());
    for (std::uint32_t source : s.tree.primitiveOrder) {
        const glm::vec3* p = &positions[3 * std::size_t(source)];
        s.triangles.push_back({p[0], 0u, p[1], NO_EMITTER, p[2], source});
    }
    s.stackBvh = makeStackBvh(s.tree, s.triangles);
    return s;
}

// One round of the parallel build and collapse, and Embree's builder at its default quality on
// the same triangles and threads right after, so that a ratio compares runs that saw the same
// load.
struct BuildRound {
    double build = 0.0;
    double collapse = 0.0;
    double embree = 0.0; // 0 without Embree
};

BuildRound timeBuildRound(const BenchScene& scene, [[maybe_unused]] std::uint32_t threads) {
    BuildRound round;
    auto start = std::chrono::steady_clock::now();
    BvhTree tree = buildBvh(triangleBounds(scene.positions));
    round.build = secondsSince(start);
    start = std::chrono::steady_clock::now();
    flattenWideBvh(tree);
    round.collapse = secondsSince(start);
#ifdef VKPT_HAVE_EMBREE
    round.embree =
        bench::embreeBuildSeconds(scene.positions, bench::EmbreeBuildQuality::Medium, threads);
#endif
    return round;
}

// From triangle positions to the device's nodes, as prepareScene does: bounds, binary build,
// collapse to 8-wide; beside Embree's builder at its default quality and at embree-ref's.
void benchBuild(const BenchScene& scene) {
    const std::uint32_t threads = std::max(1u, std::thread::hardware_concurrency());
    BvhBuildOptions oneThread;
    oneThread.threadCount = 1;
    double serial =
        medianSeconds(kBuildRuns, [&] { buildBvh(triangleBounds(scene.positions), oneThread); });
    std::vector<double> builds, collapses, totals, embrees, ratios;
    for (int i = 0; i < kBuildRuns; ++i) {
        const BuildRound round = timeBuildRound(scene, threads);
        builds.push_back(round.build);
        collapses.push_back(round.collapse);
        totals.push_back(round.build + round.collapse);
        embrees.push_back(round.embree);
        ratios.push_back(round.embree > 0.0 ? (round.build + round.collapse) / round.embree : 0.0);
    }
    std::printf("  build from positions: %.4f s on 1 thread, %.4f s on %u threads; collapse to "
                "8-wide %.4f s; build + collapse %.4f s (medians of %d)\n",
                serial, median(builds), threads, median(collapses), median(totals), kBuildRuns);
#ifdef VKPT_HAVE_EMBREE
    std::vector<double> high;
    for (int i = 0; i < kBuildRuns; ++i)
        high.push_back(
            bench::embreeBuildSeconds(scene.positions, bench::EmbreeBuildQuality::High, threads));
    std::printf("  Embree 3 build on %u threads: %.4f s (medium quality, its default), %.4f s "
                "(high, as embree-ref); build + collapse / Embree medium: %.2f (median of the "
                "runs' ratios, each run beside the other)\n",
                threads, median(embrees), median(high), median(ratios));
#endif
    const BuiltScene built = buildScene(scene.positions);
    BvhStats stats = computeBvhStats(built.tree);
    WideBvhStats wide = computeWideBvhStats(built.nodes);
    std::printf("  binary tree: %u nodes, %u leaves, depth %u, max leaf %u, SAH cost %.2f\n",
                stats.nodeCount, stats.leafCount, stats.maxDepth, stats.maxLeafSize,
                double(stats.sahCost));
    std::printf("  8-wide tree: %u nodes (%.1f MiB), %u leaf children, depth %u, %.2f children "
                "per node\n",
                wide.nodeCount, double(wide.nodeCount) * sizeof(gpu::WideBvhNode) / 1048576.0,
                wide.leafCount, wide.depth, wide.childrenPerNode);
}

void benchTraversal(const BuiltScene& s, const char* label, const std::vector<RayQuery>& rays) {
    std::printf("  %s, %zu rays, closest hit, 1 thread:\n", label, rays.size());
    std::printf("    %-26s %9s %9s %9s %9s %9s\n", "walk", "nodes/ray", "tris/ray", "max nodes",
                "max iter.", "Mrays/s");
    printWalk("stack (ordered, binary)",
              measureWalk(rays, [&](const RayQuery& r, TraversalCounters* c) {
                  return closestHitStack(s.stackBvh, r, c);
              }));
    printWalk("stackless 8-wide (device)",
              measureWalk(rays, [&](const RayQuery& r, TraversalCounters* c) {
                  return closestHitWide(s.nodes, s.triangles, r, c);
              }));
}

// The camera reflected through the centre of the bounds, looking the other way: the octant
// order must serve both.
SceneCamera mirrored(const SceneCamera& camera, const BuiltScene& s) {
    SceneCamera m = camera;
    m.position = 2.0f * s.tree.nodes[0].bounds.centre() - camera.position;
    m.forward = -camera.forward;
    return m;
}

void benchScene(const BenchScene& scene, bool buildOnly) {
    std::printf("\n%s: %zu triangles\n", scene.name.c_str(), scene.positions.size() / 3);
    benchBuild(scene);
    if (buildOnly) return;
    BuiltScene built = buildScene(scene.positions);
    benchTraversal(built, "camera rays", cameraRays(scene.camera, kRays));
    benchTraversal(built, "mirrored camera rays", cameraRays(mirrored(scene.camera, built), kRays));
    benchTraversal(built, "scattered rays", scatteredRays(built.tree.nodes[0].bounds, kRays));
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
        options.instancing = Instancing::Off; // one tree over every placed triangle
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
    return runProgram("bvh_build_bench", [argc, argv] {
        CommandLine commandLine("bvh_build_bench");
        bool buildOnly = false;
        commandLine.add(
            {"build-only", {}, "", "time the builds alone, not the walks", [&buildOnly](auto) {
                 buildOnly = true;
             }});
        std::vector<std::string> paths = bench::parseBenchArguments(commandLine, argc, argv);
        if (paths.empty()) {
            benchScene(syntheticSphere(), buildOnly);
            paths = defaultScenePaths();
        }
        for (const std::string& path : paths) {
            BenchScene scene;
            if (loadBenchScene(path, scene)) benchScene(scene, buildOnly);
        }
        return 0;
    });
}
