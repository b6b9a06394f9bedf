// reference_renderer.cpp — rounds of samples over the crop; in each, tiles handed to threads
// from an atomic counter, each pixel sampled up to the round's end unless its confidence
// interval says stop. A pixel's samples are the same and summed in the same order however the
// render is cut into rounds, so rounds change nothing in the image.
#include "reference/reference_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <thread>

#include <time.h>

#include "common/errors.h"
#include "common/progress.h"
#include "common/sampler_setup.h"
#include "driver/batch_policy.h"
#include "driver/render_driver.h"
#include "reference/integrators.h"
#include "reference/pixel_accumulator.h"
#include "reference/stack_intersector.h"
#include "shared/adaptive.h"
#include "shared/camera.h"
#include "shared/sample_guard.h"
#include "shared/sampling.h"
#include "state/pixel_features.h"

namespace vkpt {

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::uint32_t kTileSize = 16;
// A round's length when nothing else asks: short enough that Ctrl-C or SIGTERM is answered
// within about this long, long enough that starting the threads costs nothing.
constexpr double kRoundSeconds = 1.0;

struct TileGrid {
    std::uint32_t columns;
    std::uint32_t rows;
    std::uint32_t count() const { return columns * rows; }
};

// One pixel of the crop: its running estimate and where it stands.
struct PixelWork {
    PixelAccumulator accumulator;
    gpu::PixelFeatures features = gpu::noPixelFeatures(); // with AOVs
    std::uint32_t taken = 0; // samples traced, from the plan's first sample index on
    bool converged = false;
};

struct RenderJob {
    const PreparedScene& scene;
    const gpu::Camera& camera;
    const RenderSettings& settings;
    const IntersectorFactory& intersectors;
    const SamplePlan& plan;
    bool aovs;
    std::vector<PixelWork>& pixels; // plan.crop, row-major
    ProgressBar& progress;
    float darkFloor;
    TileGrid tiles;
    std::uint32_t roundEnd = 0; // every pixel samples until it has taken this many
    std::atomic<std::uint32_t> nextTile{0};
    std::mutex statsMutex;
    RenderStats& stats;
    float varianceScale = 1.0f; // of the adaptive stopping rule (shared/adaptive.h)
};

struct ThreadCounters {
    std::uint64_t samples = 0;
    std::uint64_t nonFinite = 0;
};

void renderPixel(RenderJob& job, IntegratorContext& context, std::uint32_t x, std::uint32_t y,
                 ThreadCounters& counters) {
    const RenderSettings& settings = job.settings;
    const AdaptiveSettings& adaptive = settings.adaptive;
    const std::uint32_t pixel = y * job.camera.width + x;
    const std::uint32_t setup = samplerSetupFor(settings, job.camera.width, job.camera.height);
    PixelWork& work = job.pixels[std::size_t(y - job.plan.crop.y0) * job.plan.crop.width() +
                                 (x - job.plan.crop.x0)];
    PixelAccumulator& accumulator = work.accumulator;
    while (work.taken < job.roundEnd && !work.converged) {
        const std::uint32_t s = job.plan.range.begin + work.taken;
        SampleKey key{setup, job.camera.width, settings.seed, pixel, s};
        glm::vec4 jitter = sampleFloats(key, 0, DIM_CAMERA);
        glm::vec2 film(float(x) + jitter.x, float(y) + jitter.y);
        CameraRay ray{gpu::cameraRayOrigin(job.camera, film),
                      gpu::cameraRayDirection(job.camera, film)};
        gpu::SampleFeatures features = gpu::missFeatures();
        glm::vec3 radiance = integrate(context, key, ray, job.aovs ? &features : nullptr);
        if (job.aovs) gpu::addSampleFeatures(work.features, features);
        if (gpu::isFiniteSample(radiance)) {
            radiance = gpu::clampSample(radiance, settings.clamp);
            accumulator.add(radiance, gpu::luminance(radiance), gpu::sampleHalf(s));
        } else {
            ++counters.nonFinite; // discarded: one NaN would poison the pixel for good
        }
        ++work.taken;
        ++counters.samples;
        bool batchDone = (s + 1) % adaptive.batchSize == 0;
        work.converged =
            adaptive.enabled && batchDone &&
            gpu::isPixelConverged(accumulator.count, float(accumulator.luminanceMean),
                                  float(accumulator.luminanceM2), adaptive.minSamples,
                                  adaptive.tolerance, job.darkFloor, job.varianceScale);
    }
}

void renderTile(RenderJob& job, IntegratorContext& context, std::uint32_t tile,
                ThreadCounters& counters) {
    const PixelRect& crop = job.plan.crop;
    std::uint32_t x0 = crop.x0 + (tile % job.tiles.columns) * kTileSize;
    std::uint32_t y0 = crop.y0 + (tile / job.tiles.columns) * kTileSize;
    std::uint32_t x1 = std::min(x0 + kTileSize, crop.x1);
    std::uint32_t y1 = std::min(y0 + kTileSize, crop.y1);
    const std::uint64_t before = counters.samples;
    for (std::uint32_t y = y0; y < y1; ++y)
        for (std::uint32_t x = x0; x < x1; ++x)
            renderPixel(job, context, x, y, counters);
    job.progress.advance(counters.samples - before);
}

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void renderWorker(RenderJob& job) {
    const double cpuStart = threadCpuSeconds();
    SceneTracer tracer(job.scene, job.intersectors);
    IntegratorContext context{job.settings, tracer, job.camera};
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

std::uint32_t threadCount(const RenderSettings& settings) {
    if (settings.threads > 0) return settings.threads;
    return std::max(1u, std::thread::hardware_concurrency());
}

void runRound(RenderJob& job) {
    job.nextTile = 0;
    std::vector<std::thread> workers;
    std::uint32_t count = std::min(threadCount(job.settings), job.tiles.count());
    for (std::uint32_t i = 0; i < count; ++i)
        workers.emplace_back(renderWorker, std::ref(job));
    for (std::thread& worker : workers)
        worker.join();
}

// --- records --------------------------------------------------------------------------------

PixelWork workFromRecord(const PixelRecord& r) {
    PixelWork w;
    w.accumulator.radianceSum = r.mean * double(r.count);
    w.accumulator.luminanceMean = r.luminanceMean;
    w.accumulator.luminanceM2 = r.luminanceM2;
    w.accumulator.count = r.count;
    for (int h = 0; h < 2; ++h) {
        w.accumulator.halfSums[h] = r.halves[h].mean * double(r.halves[h].count);
        w.accumulator.halfCounts[h] = r.halves[h].count;
    }
    w.taken = r.samplesTaken;
    w.converged = r.converged;
    return w;
}

PixelRecord recordFromWork(const PixelWork& w) {
    PixelRecord r;
    const PixelAccumulator& a = w.accumulator;
    r.mean = a.count ? a.radianceSum / double(a.count) : glm::dvec3(0.0);
    r.luminanceMean = a.luminanceMean;
    r.luminanceM2 = a.luminanceM2;
    r.count = a.count;
    for (int h = 0; h < 2; ++h) {
        r.halves[h].count = a.halfCounts[h];
        r.halves[h].mean =
            a.halfCounts[h] ? a.halfSums[h] / double(a.halfCounts[h]) : glm::dvec3(0.0);
    }
    r.samplesTaken = w.taken;
    r.converged = w.converged;
    return r;
}

std::vector<PixelRecord> recordsOf(const std::vector<PixelWork>& pixels) {
    std::vector<PixelRecord> records;
    records.reserve(pixels.size());
    for (const PixelWork& w : pixels)
        records.push_back(recordFromWork(w));
    return records;
}

// The crop's features, row-major; none without AOVs.
std::vector<FeatureRecord> featuresOf(const std::vector<PixelWork>& pixels, bool aovs) {
    std::vector<FeatureRecord> features;
    if (!aovs) return features;
    features.reserve(pixels.size());
    for (const PixelWork& w : pixels)
        features.push_back(featureRecordOf(w.features));
    return features;
}

std::vector<PixelWork> initialWork(const SamplePlan& plan, const ReferenceOptions& options) {
    std::vector<PixelWork> pixels(plan.crop.area());
    if (options.resume) {
        VKPT_ASSERT(options.resume->size() == plan.crop.area(), "resume records cover the crop");
        for (std::size_t i = 0; i < pixels.size(); ++i)
            pixels[i] = workFromRecord((*options.resume)[i]);
    }
    if (options.aovs && options.resumeFeatures) {
        VKPT_ASSERT(options.resumeFeatures->size() == plan.crop.area(),
                    "resumed features cover the crop");
        for (std::size_t i = 0; i < pixels.size(); ++i)
            pixels[i].features = pixelFeaturesOf((*options.resumeFeatures)[i]);
    }
    return pixels;
}

// --- rounds ----------------------------------------------------------------------------------

RenderOutput outputOf(const gpu::Camera& camera, const PixelRect& crop,
                      const std::vector<PixelRecord>& records) {
    RenderState state;
    state.identity.width = camera.width;
    state.identity.height = camera.height;
    state.window = crop;
    state.pixels = records;
    return renderOutputOf(state);
}

// The reference as the render driver's executor: a batch is a round, each pixel sampled up to
// the round's end unless it converges.
class ReferenceExecutor final : public RenderExecutor {
public:
    explicit ReferenceExecutor(RenderJob& job) : job_(job) {}

    std::uint32_t samplesDone() const override {
        std::uint32_t least = UINT32_MAX;
        for (const PixelWork& w : job_.pixels)
            if (!w.converged) least = std::min(least, w.taken);
        return least == UINT32_MAX ? budget() : std::min(least, budget());
    }

    std::uint32_t budget() const override { return job_.plan.range.size(); }

    std::uint64_t activePixels() const override {
        return std::uint64_t(
            std::count_if(job_.pixels.begin(), job_.pixels.end(),
                          [&](const PixelWork& w) { return !w.converged && w.taken < budget(); }));
    }

    // The first round takes one sample per pixel to measure the rate; later ones what fits in
    // kRoundSeconds.
    std::uint32_t batchWanted(std::uint32_t left, double secondsPerPixelSample) const override {
        if (!(secondsPerPixelSample > 0.0)) return 1;
        const double perSample = secondsPerPixelSample * double(activePixels());
        const double fit = std::floor(kRoundSeconds / perSample);
        return std::uint32_t(std::clamp(fit, 1.0, double(std::max(left, 1u))));
    }

    std::uint64_t runBatch(std::uint32_t k) override {
        const std::uint64_t before = job_.stats.samplesTaken;
        job_.roundEnd = samplesDone() + k;
        runRound(job_);
        return job_.stats.samplesTaken - before;
    }

    RenderSnapshot snapshot() override {
        RenderSnapshot pixels;
        pixels.records = recordsOf(job_.pixels);
        pixels.output = outputOf(job_.camera, job_.plan.crop, pixels.records);
        return pixels;
    }

    std::vector<FeatureRecord> features() override { return featuresOf(job_.pixels, job_.aovs); }

    void finish() override { job_.progress.finish(); }

    std::uint32_t firstCalibration() const override {
        const AdaptiveSettings& adaptive = job_.settings.adaptive;
        return adaptive.enabled && adaptive.calibrated ? firstCalibrationPoint(adaptive.minSamples)
                                                       : 0;
    }

    void setVarianceScale(float scale) override { job_.varianceScale = scale; }

private:
    RenderJob& job_;
};

} // namespace

float adaptiveDarkFloor(float exposure) {
    return ADAPTIVE_DARK_FLOOR * std::exp2(-exposure);
}

ReferenceResult renderReferenceParts(const PreparedScene& scene, const gpu::Camera& camera,
                                     const RenderSettings& settings, RenderStats& stats,
                                     const ReferenceOptions& options) {
    // Laying the tree out for the stack walk is set-up, not render time.
    std::optional<StackIntersectors> stackWalk;
    if (!options.intersectors) stackWalk.emplace(scene);
    const IntersectorFactory& intersectors =
        options.intersectors ? *options.intersectors : *stackWalk;
    auto start = Clock::now();
    const SamplePlan plan = options.plan.value_or(
        SamplePlan{fullFrame(camera.width, camera.height), {0, settings.samplesPerPixel}});
    std::vector<PixelWork> pixels = initialWork(plan, options);
    stats = RenderStats{};
    stats.uniformBudget = std::uint64_t(plan.crop.area()) * plan.range.size();
    std::unique_ptr<ProgressBar> progress =
        makeProgressBar("vkpt-ref", stats.uniformBudget, settings.quiet);
    TileGrid tiles{(plan.crop.width() + kTileSize - 1) / kTileSize,
                   (plan.crop.height() + kTileSize - 1) / kTileSize};
    RenderJob job{scene,        camera,    settings,
                  intersectors, plan,      options.aovs,
                  pixels,       *progress, adaptiveDarkFloor(settings.exposure),
                  tiles,        0,         {},
                  {},           stats};
    ReferenceExecutor executor(job);
    ReferenceResult result = runRender(executor, options);
    stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.stats = stats;
    return result;
}

RenderOutput renderReference(const PreparedScene& scene, const gpu::Camera& camera,
                             const RenderSettings& settings, RenderStats& stats) {
    return renderReferenceParts(scene, camera, settings, stats, {}).output;
}

RenderOutput renderReference(const PreparedScene& scene, const gpu::Camera& camera,
                             const RenderSettings& settings, RenderStats& stats,
                             const IntersectorFactory& intersectors) {
    ReferenceOptions options;
    options.intersectors = &intersectors;
    return renderReferenceParts(scene, camera, settings, stats, options).output;
}

} // namespace vkpt
