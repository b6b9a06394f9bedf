// reference_renderer.cpp — tiles handed to threads from an atomic counter; each pixel is
// sampled until its budget or its confidence interval says stop.
#include "reference/reference_renderer.h"

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <thread>

#include <time.h>

#include "common/progress.h"
#include "reference/integrators.h"
#include "reference/pixel_accumulator.h"
#include "reference/stack_intersector.h"
#include "shared/adaptive.h"
#include "shared/camera.h"
#include "shared/rng.h"
#include "shared/sample_guard.h"
#include "shared/sampling.h"

namespace vkpt {

namespace {

constexpr std::uint32_t kTileSize = 16;

struct TileGrid {
    std::uint32_t columns;
    std::uint32_t rows;
    std::uint32_t count() const { return columns * rows; }
};

struct RenderJob {
    const PreparedScene& scene;
    const gpu::Camera& camera;
    const RenderSettings& settings;
    const IntersectorFactory& intersectors;
    RenderOutput& output;
    ProgressBar& progress;
    float darkFloor;
    TileGrid tiles;
    std::atomic<std::uint32_t> nextTile{0};
    std::mutex statsMutex;
    RenderStats& stats;
};

// Outputs are float: a statistic beyond the float range saturates instead of becoming infinite
// (a double-to-float conversion out of range is undefined behaviour besides).
float saturatedFloat(double value) {
    return float(std::clamp(value, -double(FLT_MAX), double(FLT_MAX)));
}

struct ThreadCounters {
    std::uint64_t samples = 0;
    std::uint64_t nonFinite = 0;
};

void renderPixel(RenderJob& job, IntegratorContext& context, std::uint32_t x, std::uint32_t y,
                 ThreadCounters& counters) {
    const RenderSettings& settings = job.settings;
    const AdaptiveSettings& adaptive = settings.adaptive;
    const std::uint32_t pixel = y * job.camera.width + x;
    PixelAccumulator accumulator;
    std::uint32_t s = 0;
    for (; s < settings.samplesPerPixel; ++s) {
        SampleKey key{settings.seed, pixel, s};
        glm::vec4 jitter = gpu::randomFloats(key.seed, pixel, s, 0, DIM_CAMERA);
        glm::vec2 film(float(x) + jitter.x, float(y) + jitter.y);
        CameraRay ray{job.camera.position, gpu::cameraRayDirection(job.camera, film)};
        glm::vec3 radiance = integrate(context, key, ray);
        if (gpu::isFiniteSample(radiance)) {
            radiance = gpu::clampSample(radiance, settings.clamp);
            accumulator.add(radiance, gpu::luminance(radiance));
        } else {
            ++counters.nonFinite; // discarded: one NaN would poison the pixel for good
        }
        bool batchDone = (s + 1) % adaptive.batchSize == 0;
        if (adaptive.enabled && batchDone &&
            gpu::isPixelConverged(accumulator.count, float(accumulator.luminanceMean),
                                  float(accumulator.luminanceM2), adaptive.minSamples,
                                  adaptive.tolerance, job.darkFloor)) {
            ++s;
            break;
        }
    }
    counters.samples += s;
    job.output.image.pixels[pixel] = accumulator.mean();
    job.output.sampleCounts[pixel] = accumulator.count;
    job.output.luminanceMean[pixel] = saturatedFloat(accumulator.luminanceMean);
    job.output.luminanceM2[pixel] = saturatedFloat(accumulator.luminanceM2);
}

void renderTile(RenderJob& job, IntegratorContext& context, std::uint32_t tile,
                ThreadCounters& counters) {
    std::uint32_t x0 = (tile % job.tiles.columns) * kTileSize;
    std::uint32_t y0 = (tile / job.tiles.columns) * kTileSize;
    std::uint32_t x1 = std::min(x0 + kTileSize, job.camera.width);
    std::uint32_t y1 = std::min(y0 + kTileSize, job.camera.height);
    for (std::uint32_t y = y0; y < y1; ++y)
        for (std::uint32_t x = x0; x < x1; ++x) renderPixel(job, context, x, y, counters);
    job.progress.advance(std::uint64_t(x1 - x0) * (y1 - y0));
}

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void renderWorker(RenderJob& job) {
    const double cpuStart = threadCpuSeconds();
    SceneTracer tracer(job.scene, job.intersectors);
    IntegratorContext context{job.settings, tracer};
    ThreadCounters counters;
    for (std::uint32_t tile = job.nextTile++; tile < job.tiles.count(); tile = job.nextTile++)
        renderTile(job, context, tile, counters);
    std::lock_guard<std::mutex> lock(job.statsMutex);
    job.stats.rays += tracer.rays();
    job.stats.nodesVisited += tracer.traversal().nodesVisited;
    job.stats.triangleTests += tracer.traversal().triangleTests;
    job.stats.samplesTaken += counters.samples;
    job.stats.nonFiniteSamples += counters.nonFinite;
    job.stats.cpuSeconds += threadCpuSeconds() - cpuStart;
}

RenderOutput makeOutput(std::uint32_t width, std::uint32_t height) {
    RenderOutput output;
    output.image = Image(width, height);
    std::size_t pixels = std::size_t(width) * height;
    output.sampleCounts.assign(pixels, 0);
    output.luminanceMean.assign(pixels, 0.0f);
    output.luminanceM2.assign(pixels, 0.0f);
    return output;
}

std::uint32_t threadCount(const RenderSettings& settings) {
    if (settings.threads > 0) return settings.threads;
    return std::max(1u, std::thread::hardware_concurrency());
}

} // namespace

float adaptiveDarkFloor(float exposure) { return ADAPTIVE_DARK_FLOOR * std::exp2(-exposure); }

RenderOutput renderReference(const PreparedScene& scene, const gpu::Camera& camera,
                             const RenderSettings& settings, RenderStats& stats) {
    StackIntersectors intersectors(scene);
    return renderReference(scene, camera, settings, stats, intersectors);
}

RenderOutput renderReference(const PreparedScene& scene, const gpu::Camera& camera,
                             const RenderSettings& settings, RenderStats& stats,
                             const IntersectorFactory& intersectors) {
    auto start = std::chrono::steady_clock::now();
    RenderOutput output = makeOutput(camera.width, camera.height);
    stats = RenderStats{};
    stats.uniformBudget = std::uint64_t(camera.width) * camera.height * settings.samplesPerPixel;
    std::unique_ptr<ProgressBar> progress =
        makeProgressBar("vkpt-ref", std::uint64_t(camera.width) * camera.height, settings.quiet);
    TileGrid tiles{(camera.width + kTileSize - 1) / kTileSize,
                   (camera.height + kTileSize - 1) / kTileSize};
    RenderJob job{scene,
                  camera,
                  settings,
                  intersectors,
                  output,
                  *progress,
                  adaptiveDarkFloor(settings.exposure),
                  tiles,
                  {},
                  {},
                  stats};
    std::vector<std::thread> workers;
    std::uint32_t count = std::min(threadCount(settings), tiles.count());
    for (std::uint32_t i = 0; i < count; ++i) workers.emplace_back(renderWorker, std::ref(job));
    for (std::thread& worker : workers) worker.join();
    progress->finish();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return output;
}

} // namespace vkpt
