// traversal_bench.cpp — the same rays traced by every traversal: Embree 3 (the baseline),
// vkpt-ref's ordered stack walk, the device's walk on the CPU and the device kernels (lavapipe
// without a GPU). Per ray set and variant: Mrays/s (median of --runs), nodes visited and
// primitive tests per ray, bytes fetched per ray, the ratio to Embree's Mrays/s, and how many
// answers disagree with the stack walk's. Beside wall-clock Mrays/s it prints Mrays per CPU
// second of the process (user + system time, lavapipe's threads included), which other tenants
// of a shared machine inflate far less. A benchmark: it prints, never asserts.
//
//   traversal_bench [--quick] [--runs N] [--res W H] [--threads N] [--triangles N]
//                   [--max-depth N] [--no-device] [--device N|NAME] [--batch N] [scene.gltf ...]
//
// Scenes by default: scenes/cornell-box.gltf, the shared TransmissionTest (skipped when
// absent) and the generated room with a displaced sphere (tests/support/room_scene.h).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "../support/room_scene.h"
#include "app/command_line.h"
#include "bench_device_option.h"
#include "bench_options.h"
#include "bench_statistics.h"
#include "common/errors.h"
#include "gpu/device_list.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"
#include "traversal_rays.h"
#include "traversal_variants.h"

namespace vkpt::bench {
namespace {

const char* const kProgram = "traversal_bench";
const std::string kGeneratedRoom = "generated room";

struct BenchOptions {
    RenderBenchOptions paths{1, 256, 256, 3, {}}; // one ray path per pixel; spp is unused
    std::uint32_t triangles = 1000000;
    std::uint32_t maxDepth = 8;
    VariantOptions variants;
};

BenchOptions parseOptions(int argc, char** argv) {
    BenchOptions o;
    CommandLine cl(kProgram);
    cl.add(
        {"quick", {}, "", "64x64 paths, 1 run, a 100k-triangle room: seconds, for CI", [&](auto) {
             o.paths.width = o.paths.height = 64;
             o.paths.runs = 1;
             o.triangles = 100000;
         }});
    addRunsOption(cl, o.paths, "timed runs per variant and ray set, median printed");
    addResolutionOption(cl, o.paths, "paths from W x H pixels, one sample each");
    cl.add({"threads", {}, "N", "threads of the CPU variants and Embree (default 2)", [&](auto v) {
                o.variants.threads = parseUnsigned("threads", v[0], 1);
            }});
    cl.add({"triangles", {}, "N", "size of the generated room (default 1000000)", [&](auto v) {
                o.triangles = parseUnsigned("triangles", v[0], 8);
            }});
    cl.add(
        {"max-depth", {}, "N", "scattering events of the recorded paths (default 8)", [&](auto v) {
             o.maxDepth = parseUnsigned("max-depth", v[0]);
         }});
    cl.add({"no-device", {}, "", "leave out the device kernels", [&](auto) {
                o.variants.device = false;
            }});
    addDeviceOption(cl, o.variants.gpu,
                    "Vulkan device of the device kernels (default: vkpt's choice)");
    cl.add({"batch",
            {},
            "N",
            "rays per dispatch of the device kernels (default: 16384 on a CPU "
            "device, 4194304 on a GPU)",
            [&](auto v) { o.variants.deviceBatch = parseUnsigned("batch", v[0], 64); }});
    o.paths.scenes = parseBenchArguments(cl, argc, argv, "[scene.gltf ...]");
    if (o.paths.scenes.empty()) {
        o.paths.scenes = defaultBenchScenes();
        o.paths.scenes.push_back(kGeneratedRoom);
    }
    return o;
}

Scene loadBenchScene(const std::string& path, const BenchOptions& o) {
    if (path == kGeneratedRoom) return test::toScene(test::makeRoomScene(o.triangles));
    LoadOptions loadOptions;
    loadOptions.warnUnsupportedExtensions = false;
    // The walks compared here, Embree's among them, are of one level: every placement
    // flattened.
    loadOptions.instancing = Instancing::Off;
    return loadGltfScene(path, loadOptions);
}

struct Timed {
    std::vector<double> seconds;
    std::vector<double> cpuSeconds;
    std::vector<TraceOutcome> outcomes; // of the last run
    TraceWork work;                     // of the last run
};

// User + system time of the whole process so far.
double processCpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

Timed timeVariant(TraversalVariant& variant, const RaySet& set, int runs) {
    Timed timed;
    for (int run = 0; run < runs; ++run) {
        const double cpuStart = processCpuSeconds();
        auto start = std::chrono::steady_clock::now();
        timed.work = variant.trace(set, timed.outcomes);
        timed.seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        timed.cpuSeconds.push_back(processCpuSeconds() - cpuStart);
    }
    return timed;
}

// Answers that differ from the reference's: a hit against a miss, or a closest t further
// apart than float noise of two different triangle tests (1e-4 relative).
struct Disagreement {
    std::size_t hitOrMiss = 0;
    std::size_t distance = 0;
};

Disagreement compare(const std::vector<TraceOutcome>& a, const std::vector<TraceOutcome>& b,
                     bool anyHit) {
    Disagreement d;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].hit != b[i].hit) {
            ++d.hitOrMiss;
        } else if (!anyHit && a[i].hit &&
                   std::abs(a[i].t - b[i].t) > 1e-4f * std::max(a[i].t, 1e-3f)) {
            ++d.distance;
        }
    }
    return d;
}

std::string perRay(std::optional<std::uint64_t> total, std::size_t rays) {
    if (!total) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", double(*total) / double(rays));
    return text;
}

// nodes × node bytes + tests × primitive bytes; ">=" when only the nodes are counted.
std::string bytesPerRay(const TraceWork& work, const WalkLayout& layout, std::size_t rays) {
    if (!work.nodes || layout.nodeBytes == 0) return "-";
    double bytes = double(*work.nodes) * double(layout.nodeBytes);
    if (work.primitiveTests) bytes += double(*work.primitiveTests) * double(layout.primitiveBytes);
    char text[32];
    std::snprintf(text, sizeof text, "%s%.0f",
                  work.primitiveTests ? "" : ">=", bytes / double(rays));
    return text;
}

// Mrays per second of wall-clock time and per CPU second.
struct Speed {
    double wall = 0.0;
    double cpu = 0.0;
};

Speed speedOf(const Timed& timed, std::size_t rays) {
    return {double(rays) / median(timed.seconds) * 1e-6,
            double(rays) / median(timed.cpuSeconds) * 1e-6};
}

std::string ratio(double value, double base) {
    if (base <= 0.0) return "-";
    char text[16];
    std::snprintf(text, sizeof text, "%.2f", value / base);
    return text;
}

void printRow(const VariantInfo& info, const Timed& timed, std::size_t rays, Speed base,
              const std::string& disagreement) {
    Speed speed = speedOf(timed, rays);
    std::printf("    %-50s %7.2f %5s %8.2f %5s %6s %6s %7s  %s\n", info.name.c_str(), speed.wall,
                ratio(speed.wall, base.wall).c_str(), speed.cpu, ratio(speed.cpu, base.cpu).c_str(),
                perRay(timed.work.nodes, rays).c_str(),
                perRay(timed.work.primitiveTests, rays).c_str(),
                bytesPerRay(timed.work, info.layout, rays).c_str(), disagreement.c_str());
}

void benchRaySet(const RaySet& set, std::vector<std::unique_ptr<TraversalVariant>>& variants,
                 int runs) {
    std::printf("  %s: %zu rays\n    %-50s %7s %5s %8s %5s %6s %6s %7s  %s\n", set.name.c_str(),
                set.rays.size(), "variant", "Mrays/s", "ratio", "Mr/cpu-s", "ratio", "nodes",
                "tests", "bytes", "disagree (hit/miss, t)");
    if (set.rays.empty()) return;
    std::vector<Timed> timed;
    for (auto& variant : variants)
        timed.push_back(timeVariant(*variant, set, runs));
    const Timed* reference = nullptr;
    Speed base;
    for (std::size_t v = 0; v < variants.size(); ++v) {
        if (variants[v]->info().checkReference) reference = &timed[v];
        if (variants[v]->info().ratioBase) base = speedOf(timed[v], set.rays.size());
    }
    for (std::size_t v = 0; v < variants.size(); ++v) {
        std::string disagreement = "(reference)";
        if (!variants[v]->info().checkReference && reference) {
            Disagreement d = compare(reference->outcomes, timed[v].outcomes, set.anyHit);
            disagreement = std::to_string(d.hitOrMiss) + ", " + std::to_string(d.distance);
        }
        printRow(variants[v]->info(), timed[v], set.rays.size(), base, disagreement);
        if (timed[v].work.kernelSeconds && *timed[v].work.kernelSeconds > 0.0)
            std::printf("    %-50s %7.2f  (GPU time of the kernels alone, last run)\n",
                        "  kernels alone",
                        double(set.rays.size()) / *timed[v].work.kernelSeconds * 1e-6);
    }
}

void benchScene(const std::string& path, const BenchOptions& o) {
    if (path != kGeneratedRoom && !std::filesystem::exists(path)) {
        std::printf("%s: not found, skipped\n\n", path.c_str());
        return;
    }
    Scene scene = loadBenchScene(path, o);
    float aspect = float(o.paths.width) / float(o.paths.height);
    SceneCamera sceneCamera = selectCamera(scene, std::nullopt, aspect);
    PreparedScene prepared = prepareScene(scene);
    gpu::Camera camera = makeGpuCamera(sceneCamera, o.paths.width, o.paths.height);
    RenderSettings settings;
    settings.maxDepth = o.maxDepth;
    std::vector<RaySet> sets = recordRenderRays(prepared, camera, settings);
    std::printf(
        "%s: %zu triangles; vkpt BVH %u nodes, depth %u, built in %.3f s; rays of "
        "%ux%u paths (1 spp, depth %u); medians of %d runs\n",
        path == kGeneratedRoom
            ? ("generated room, " + std::to_string(o.triangles) + " triangles asked").c_str()
            : path.c_str(),
        prepared.triangles.size(), prepared.bvhStats.nodeCount, prepared.bvhStats.maxDepth,
        prepared.bvhStats.buildSeconds, o.paths.width, o.paths.height, o.maxDepth, o.paths.runs);
    std::vector<std::unique_ptr<TraversalVariant>> variants =
        makeTraversalVariants(prepared, o.variants);
    for (const RaySet& set : sets)
        benchRaySet(set, variants, o.paths.runs);
    std::printf("\n");
}

} // namespace
} // namespace vkpt::bench

int main(int argc, char** argv) {
    try {
        vkpt::bench::BenchOptions options = vkpt::bench::parseOptions(argc, argv);
        for (const std::string& scene : options.paths.scenes)
            vkpt::bench::benchScene(scene, options);
        return 0;
    } catch (const vkpt::InputError& error) {
        std::fprintf(stderr, "%s: error: %s\n", vkpt::bench::kProgram, error.what());
        return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "%s: error: %s\n", vkpt::bench::kProgram, error.what());
        return 3;
    }
}
