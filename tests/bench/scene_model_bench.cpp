// scene_model_bench.cpp — what specialising to a scene's feature set buys: for each scene,
// vkpt with pipelines and buffers built for the scene's features and with --general (every
// feature), side by side: Mrays/s, seconds, pipeline-creation time, the scene's device
// buffers and peak device memory; medians of several runs, and how far the two images are
// apart at the same seed. A benchmark: it prints, never asserts (tests/image asserts the
// images' agreement).
//
//   scene_model_bench [--spp N] [--res W H] [--runs N] [--device N|NAME]
//                     [--env-color R G B] [scene ...]
//
// Defaults: 16 spp at 256 × 256, 5 runs; the Cornell box and DamagedHelmet (lit by a constant
// environment of 1 when no --env-color is given). --env-color lights every scene given. "first run"
// includes what a driver compiles at the first dispatch (lavapipe compiles its LLVM code then, not
// at pipeline creation); the other times are medians.
#include <algorithm>
#include <cmath>
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
#include "render/wavefront.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

namespace {

using vkpt::bench::median;
using vkpt::bench::RenderBenchOptions;

using namespace vkpt;

struct BenchScene {
    std::string path;
    glm::vec3 environment{0.0f};
};

// The scenes go with the environment that lights each (render.scenes stays empty).
struct BenchOptions {
    RenderBenchOptions render{16, 256, 256, 5, {}};
    GpuOptions gpu;
    std::vector<BenchScene> scenes;
    std::optional<glm::vec3> environment;
};

BenchOptions parse(int argc, char** argv) {
    BenchOptions o;
    CommandLine commandLine("scene_model_bench");
    bench::addRenderBenchOptions(commandLine, o.render);
    bench::addDeviceOption(commandLine, o.gpu);
    commandLine.add(
        {"env-color", {}, "R G B", "constant environment of the scenes given", [&o](auto v) {
             o.environment = glm::vec3(parseFloat("env-color", v[0]), parseFloat("env-color", v[1]),
                                       parseFloat("env-color", v[2]));
         }});
    for (const std::string& path : bench::parseBenchArguments(commandLine, argc, argv))
        o.scenes.push_back({path, o.environment.value_or(glm::vec3(0.0f))});
    if (o.scenes.empty()) {
        const std::string shared = std::string(VKPT_SCENES_DIR) + "/../../shared/scenes/";
        o.scenes = {
            {std::string(VKPT_SCENES_DIR) + "/cornell-box.gltf",
             o.environment.value_or(glm::vec3(0.0f))},
            {shared + "DamagedHelmet/DamagedHelmet.glb", o.environment.value_or(glm::vec3(1.0f))}};
    }
    return o;
}

struct ModeFigures {
    std::vector<double> seconds, mrays, pipelineSeconds;
    double firstRunSeconds = 0.0; // with the driver's deferred compile (lavapipe: at dispatch)
    std::uint64_t sceneBytes = 0;
    std::uint64_t peakBytes = 0;
    std::vector<SceneBufferBytes> buffers;
    RenderOutput image; // of the last run, for the same-seed comparison
};

// A fresh device per mode, so that its peak memory is this mode's alone.
ModeFigures runMode(const Scene& scene, const BenchOptions& o, bool general,
                    const gpu::Camera& camera) {
    GpuContext context(o.gpu);
    PreparedScene prepared = prepareScene(scene, {{}, general});
    ModeFigures figures;
    for (int run = 0; run < o.render.runs; ++run) {
        WavefrontResult result = renderWavefront(context, prepared, camera, o.render.settings());
        if (run == 0) figures.firstRunSeconds = result.stats.seconds;
        figures.seconds.push_back(result.stats.seconds);
        figures.mrays.push_back(result.stats.megaRaysPerSecond());
        figures.pipelineSeconds.push_back(result.pipelineCreationSeconds);
        figures.sceneBytes = result.sceneBufferBytes;
        figures.buffers = result.sceneBuffers;
        figures.image = std::move(result.output);
        std::fprintf(stderr, "  %s run %d/%d: %.3f s\n", general ? "general" : "scene", run + 1,
                     o.render.runs, result.stats.seconds);
    }
    figures.peakBytes = context.memoryStats().peakBytes;
    return figures;
}

double largestRelativeDifference(const RenderOutput& a, const RenderOutput& b) {
    double largest = 0.0;
    for (std::size_t i = 0; i < a.image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            double x = a.image.pixels[i][c], y = b.image.pixels[i][c];
            largest = std::max(largest, std::abs(x - y) / std::max(std::abs(y), 1e-6));
        }
    return largest;
}

std::string buffersText(const std::vector<SceneBufferBytes>& buffers) {
    std::string text;
    for (const SceneBufferBytes& b : buffers)
        text += (text.empty() ? "" : ", ") + b.name + " " + std::to_string(b.bytes / 1024) + " KiB";
    return text;
}

void benchScene(const BenchScene& bench, const BenchOptions& o) {
    LoadOptions loadOptions;
    loadOptions.warnUnsupportedExtensions = false;
    Scene scene = loadGltfScene(bench.path, loadOptions);
    scene.environment.radiance = bench.environment;
    SceneCamera sceneCamera =
        selectCamera(scene, std::nullopt, float(o.render.width) / float(o.render.height));
    gpu::Camera camera = makeGpuCamera(sceneCamera, o.render.width, o.render.height);
    std::printf("%s: %zu triangles, %zu spheres, %ux%u at %u spp; features: %s\n",
                bench.path.c_str(), scene.triangleCount(), scene.spheres.size(), o.render.width,
                o.render.height, o.render.spp, describeFeatures(analyseScene(scene)).c_str());
    ModeFigures specialised = runMode(scene, o, false, camera);
    ModeFigures general = runMode(scene, o, true, camera);
    std::printf("| build | Mrays/s | seconds | first run | pipeline creation | scene buffers | "
                "peak device memory |\n| --- | --- | --- | --- | --- | --- | --- |\n");
    for (const auto& [name, f] : {std::pair<const char*, const ModeFigures*>{"scene", &specialised},
                                  {"--general", &general}}) {
        std::printf("| %s | %.3f | %.3f | %.3f | %.1f ms | %.2f MiB | %.2f MiB |\n", name,
                    median(f->mrays), median(f->seconds), f->firstRunSeconds,
                    1e3 * median(f->pipelineSeconds), double(f->sceneBytes) / 1048576.0,
                    double(f->peakBytes) / 1048576.0);
    }
    std::printf("  (medians of %d runs)\n  scene buffers, scene:     %s\n"
                "  scene buffers, --general: %s\n",
                o.render.runs, buffersText(specialised.buffers).c_str(),
                buffersText(general.buffers).c_str());
    std::printf("  same seed, largest relative difference between the two images: %.3g\n\n",
                largestRelativeDifference(specialised.image, general.image));
}

} // namespace

int main(int argc, char** argv) {
    try {
        BenchOptions options = parse(argc, argv);
        {
            GpuContext context(options.gpu);
            std::printf("device: %s%s\n\n", describeDevice(context.deviceInfo()).c_str(),
                        context.validationEnabled() ? " (validation on: figures are slower)" : "");
        }
        for (const BenchScene& scene : options.scenes)
            benchScene(scene, options);
        return 0;
    } catch (const vkpt::VulkanError& error) {
        std::fprintf(stderr, "scene_model_bench: error: %s\n", error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "scene_model_bench: error: %s\n", error.what());
        return 1;
    }
}
