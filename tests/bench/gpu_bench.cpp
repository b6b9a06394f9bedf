// gpu_bench.cpp — prints vkpt's figures on the device (Mrays/s, seconds, samples/s, per-kernel
// GPU times) beside the CPU reference's on the same machine, for the Cornell box and the
// largest shared scene; medians of several runs. A benchmark: it prints, never asserts.
//
//   gpu_bench [--quick] [--spp N] [--res W H] [--runs N] [--device N|NAME] [scene ...]
//
// Defaults: 64 spp at 512 × 512, 3 runs. --quick (2 spp at 128 × 128) suits lavapipe in CI.
#include <cstdio>
#include <string>
#include <vector>

#include "bench_device_option.h"
#include "bench_options.h"
#include "bench_statistics.h"
#include "common/errors.h"
#include "gpu/context.h"
#include "gpu/vk_check.h"
#include "prepare/prepared_scene.h"
#include "reference/reference_renderer.h"
#include "render/wavefront.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

namespace {

using vkpt::bench::median;
using vkpt::bench::RenderBenchOptions;

using namespace vkpt;

struct BenchOptions {
    RenderBenchOptions render{64, 512, 512, 3, {}};
    GpuOptions gpu;
};

BenchOptions parse(int argc, char** argv) {
    BenchOptions o;
    RenderBenchOptions& r = o.render;
    CommandLine commandLine("gpu_bench");
    commandLine.add({"quick", {}, "", "2 spp at 128 x 128: seconds on lavapipe", [&r](auto) {
                         r.spp = 2;
                         r.width = r.height = 128;
                     }});
    bench::addRenderBenchOptions(commandLine, r);
    bench::addDeviceOption(commandLine, o.gpu);
    r.scenes = bench::parseBenchArguments(commandLine, argc, argv);
    if (r.scenes.empty()) r.scenes = bench::defaultBenchScenes();
    return o;
}

struct Figures {
    std::vector<double> seconds, mrays, samplesPerSecond;
    RenderStats last;

    void add(const RenderStats& stats) {
        seconds.push_back(stats.seconds);
        mrays.push_back(stats.megaRaysPerSecond());
        samplesPerSecond.push_back(double(stats.samplesTaken) / stats.seconds);
        last = stats;
    }
    void print(const char* who, int runs) const {
        std::printf("  %-8s %8.3f s  %8.3f Mrays/s  %10.0f samples/s  (medians of %d); "
                    "%.2f rays per sample, %.1f nodes per ray\n",
                    who, median(seconds), median(mrays), median(samplesPerSecond), runs,
                    double(last.rays.total()) / double(last.samplesTaken), last.nodesPerRay());
    }
};

void printKernelTimes(const WavefrontResult& result) {
    std::uint64_t total = 0;
    for (const KernelTimeTotal& t : result.kernelTimes)
        total += t.nanoseconds;
    for (const KernelTimeTotal& t : result.kernelTimes)
        std::printf("    %-20s %9.2f ms %5.1f %% in %llu dispatches\n", t.kernel.c_str(),
                    double(t.nanoseconds) * 1e-6, 100.0 * double(t.nanoseconds) / double(total),
                    (unsigned long long)t.dispatches);
}

void benchScene(GpuContext& context, const std::string& path, const RenderBenchOptions& o) {
    LoadOptions loadOptions;
    loadOptions.warnUnsupportedExtensions = false;
    Scene scene = loadGltfScene(path, loadOptions);
    PreparedScene prepared = prepareScene(scene);
    gpu::Camera camera = makeGpuCamera(
        selectCamera(scene, std::nullopt, float(o.width) / float(o.height)), o.width, o.height);
    RenderSettings settings = o.settings();
    std::printf("%s: %zu triangles, %ux%u at %u spp\n", path.c_str(), scene.triangleCount(),
                o.width, o.height, o.spp);
    Figures device, reference;
    for (int run = 0; run < o.runs; ++run) {
        WavefrontResult result = renderWavefront(context, prepared, camera, settings);
        device.add(result.stats);
        std::fprintf(stderr, "  vkpt run %d/%d: %.3f s\n", run + 1, o.runs, result.stats.seconds);
        RenderStats stats;
        renderReference(prepared, camera, settings, stats);
        reference.add(stats);
        std::fprintf(stderr, "  vkpt-ref run %d/%d: %.3f s\n", run + 1, o.runs, stats.seconds);
    }
    device.print("vkpt", o.runs);
    reference.print("vkpt-ref", o.runs);
    std::printf("  vkpt / vkpt-ref speed: %.2f\n",
                median(reference.seconds) / median(device.seconds));
    WavefrontOptions timed;
    timed.timeKernels = true;
    WavefrontResult result = renderWavefront(context, prepared, camera, settings, timed);
    std::printf("  per-kernel GPU time (one more run with timestamps, %.3f s, %u passes of %u "
                "slots):\n",
                result.stats.seconds, result.passes, result.slotCount);
    printKernelTimes(result);
}

} // namespace

int main(int argc, char** argv) {
    try {
        BenchOptions options = parse(argc, argv);
        GpuContext context(options.gpu);
        std::printf("device: %s%s\n", describeDevice(context.deviceInfo()).c_str(),
                    context.validationEnabled() ? " (validation on: figures are slower)" : "");
        for (const std::string& path : options.render.scenes)
            benchScene(context, path, options.render);
        return 0;
    } catch (const vkpt::VulkanError& error) {
        std::fprintf(stderr, "gpu_bench: error: %s\n", error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "gpu_bench: error: %s\n", error.what());
        return 1;
    }
}
