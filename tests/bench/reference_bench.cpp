// reference_bench.cpp — prints vkpt-ref's figures (BVH build time, Mrays/s, work per ray) for
// the Cornell box and the largest shared scene; a benchmark, never a pass/fail test.
//
//   reference_bench [--spp N] [--res W H] [--runs N] [scene ...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_options.h"
#include "bench_statistics.h"
#include "common/errors.h"
#include "prepare/prepared_scene.h"
#include "reference/reference_renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

namespace {

using vkpt::bench::median;
using vkpt::bench::RenderBenchOptions;

using namespace vkpt;

RenderBenchOptions parse(int argc, char** argv) {
    RenderBenchOptions o{4, 256, 256, 3, {}};
    CommandLine commandLine("reference_bench");
    bench::addRenderBenchOptions(commandLine, o);
    o.scenes = bench::parseBenchArguments(commandLine, argc, argv);
    if (o.scenes.empty()) o.scenes = bench::defaultBenchScenes();
    return o;
}

void benchScene(const std::string& path, const RenderBenchOptions& o) {
    LoadOptions loadOptions;
    loadOptions.warnUnsupportedExtensions = false;
    Scene scene = loadGltfScene(path, loadOptions);
    std::vector<double> buildSeconds, renderSeconds, mrays;
    RenderStats stats;
    PreparedScene prepared;
    SceneCamera sceneCamera = selectCamera(scene, std::nullopt, float(o.width) / float(o.height));
    for (int run = 0; run < o.runs; ++run) {
        prepared = prepareScene(scene);
        buildSeconds.push_back(prepared.bvhStats.buildSeconds);
    }
    RenderSettings settings = o.settings();
    gpu::Camera camera = makeGpuCamera(sceneCamera, o.width, o.height);
    for (int run = 0; run < o.runs; ++run) {
        renderReference(prepared, camera, settings, stats);
        renderSeconds.push_back(stats.seconds);
        mrays.push_back(stats.megaRaysPerSecond());
        std::fprintf(stderr, "  run %d/%d: %.3f s\n", run + 1, o.runs, stats.seconds);
    }
    std::printf(
        "%s\n  triangles %zu, BVH %u nodes, depth %u, SAH %.2f, build %.3f s (median of %d)\n",
        path.c_str(), scene.triangleCount(), prepared.bvhStats.nodeCount,
        prepared.bvhStats.maxDepth, double(prepared.bvhStats.sahCost), median(buildSeconds),
        o.runs);
    std::printf("  render %ux%u @ %u spp: %.3f s, %.2f Mrays/s (medians of %d), %.1f nodes and "
                "%.1f triangle tests per ray, %.2f rays per sample\n",
                o.width, o.height, o.spp, median(renderSeconds), median(mrays), o.runs,
                stats.nodesPerRay(), stats.trianglesPerRay(),
                double(stats.rays.total()) / double(stats.samplesTaken));
}

} // namespace

int main(int argc, char** argv) {
    try {
        RenderBenchOptions options = parse(argc, argv);
        for (const std::string& path : options.scenes)
            benchScene(path, options);
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "reference_bench: error: %s\n", error.what());
        return 1;
    }
}
