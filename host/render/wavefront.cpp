// wavefront.cpp — vkpt's executor: a pass gives k samples to the active pixels, each chunk's
// bounces from one command buffer, then reads the counters and compacts the active list; the
// render driver decides how many passes, of what k, and when to look at the pixels.
#include "render/wavefront.h"

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "common/errors.h"
#include "common/phase_log.h"
#include "common/progress.h"
#include "common/sampler_setup.h"
#include "driver/batch_policy.h"
#include "driver/render_driver.h"
#include "gpu/context.h"
#include "gpu/submit.h"
#include "gpu/upload.h"
#include "render/accumulation.h"
#include "render/device_scene.h"
#include "render/kernel_times.h"
#include "render/pass_recorder.h"
#include "render/pass_schedule.h"
#include "render/wavefront_kernels.h"
#include "render/work_buffers.h"
#include "shared/adaptive.h"
#include "state/pixel_features.h"

namespace vkpt {

namespace {

// Bounces recorded into one command buffer. Default depths (16) need one submission per
// chunk; deeper limits continue in further submissions while the queue holds rays, so
// recording stays bounded whatever --max-depth says.
constexpr std::uint32_t kBouncesPerSubmission = 32;

std::uint32_t integratorCode(const RenderSettings& settings) {
    switch (settings.integrator) {
    case Integrator::Path:
        return INTEGRATOR_PATH;
    case Integrator::Direct:
        return settings.lightSampling == LightSampling::Hemisphere ? INTEGRATOR_DIRECT_HEMISPHERE
                                                                   : INTEGRATOR_DIRECT_LIGHT;
    case Integrator::Normals:
        return INTEGRATOR_NORMALS;
    }
    return INTEGRATOR_PATH;
}

// Camera ray plus maxDepth scattering events for the path tracer; the direct and normals
// integrators trace their camera rays only (the direct one's light samples ride along).
std::uint64_t bouncesToTrace(const RenderSettings& settings) {
    if (settings.integrator != Integrator::Path) return 1;
    return std::uint64_t(settings.maxDepth) + 1;
}

// The same expression as the reference's adaptiveDarkFloor, so both stop at the same floor.
float darkFloor(float exposure) {
    return ADAPTIVE_DARK_FLOOR * std::exp2(-exposure);
}

gpu::FrameParams makeFrameParams(const RenderSettings& settings, const gpu::Camera& camera,
                                 const DeviceScene& scene, std::uint32_t slotCount) {
    gpu::FrameParams f{};
    f.camera = camera;
    f.seed = settings.seed;
    f.maxDepth = settings.maxDepth;
    f.rrStartDepth = settings.rrStartDepth;
    f.lightSamples = settings.integrator == Integrator::Normals ? 0u : settings.lightSamples;
    f.integrator = integratorCode(settings);
    f.pathFilter = static_cast<std::uint32_t>(settings.pathFilter);
    f.emitterCount = scene.emitterCount;
    f.adaptive = settings.adaptive.enabled ? 1u : 0u;
    f.adaptiveBatch = settings.adaptive.batchSize;
    f.adaptiveMinSamples = settings.adaptive.minSamples;
    f.adaptiveTolerance = settings.adaptive.tolerance;
    f.adaptiveDarkFloor = darkFloor(settings.exposure);
    f.slotCount = slotCount;
    f.pixelCount = camera.width * camera.height;
    f.samplerSetup = samplerSetupFor(settings, camera.width, camera.height);
    f.sampleClamp = settings.clamp;
    f.environment = scene.environment;
    return f;
}

BufferTable makeBufferTable(const DeviceScene& scene, const WorkBuffers& work) {
    BufferTable table;
    scene.bind(table);
    work.bind(table);
    return table;
}

SamplePlan samplePlanFor(const gpu::Camera& camera, const RenderSettings& settings,
                         const WavefrontOptions& options) {
    return options.plan.value_or(
        SamplePlan{fullFrame(camera.width, camera.height), {0, settings.samplesPerPixel}});
}

std::uint32_t slotCountFor(const GpuContext& context, const RenderSettings& settings,
                           const SamplePlan& plan, const WavefrontOptions& options) {
    SlotRequest request;
    request.lightSamples = settings.lightSamples;
    request.pathsWanted = std::uint64_t(plan.crop.area()) * plan.range.size();
    request.requestedSlots = options.slotCount;
    request.aovs = options.aovs;
    return chooseSlotCount(context, request);
}

// Pipelines built for fewer features than the scene uses would silently drop them (textures,
// spheres, lights): a programmer error, not a user's.
void checkFeaturesCover(const SceneFeatures& built, const SceneFeatures& used) {
    const std::array<bool, FEATURE_COUNT> have = built.kernelFeatures();
    const std::array<bool, FEATURE_COUNT> need = used.kernelFeatures();
    for (std::size_t i = 0; i < FEATURE_COUNT; ++i)
        VKPT_ASSERT(have[i] || !need[i], "the kernels are built without feature " +
                                             std::to_string(i) + ", which the scene uses");
}

SceneFeatures kernelFeaturesFor(const PreparedScene& scene, const WavefrontOptions& options) {
    SceneFeatures features = options.features.value_or(scene.features);
    checkFeaturesCover(features, scene.usedFeatures);
    return features;
}

std::unique_ptr<GpuTimer> makeTimer(const GpuContext& context, const WavefrontOptions& options) {
    if (!options.timeKernels) return nullptr;
    return std::make_unique<GpuTimer>(context, PassRecorder::timerCapacity(kBouncesPerSubmission),
                                      "kernelTimer");
}

DeviceScene timedUpload(const std::function<DeviceScene()>& upload) {
    ScopedPhase phase("upload");
    return upload();
}

// A member's construction as a phase of the process.
template <typename Make> auto timedPhase(const char* name, Make&& make) {
    ScopedPhase phase(name);
    return make();
}

class WavefrontRenderer final : public RenderExecutor {
public:
    // `upload` puts `scene` on the device (uploadScene); it runs after the working buffers exist,
    // so that a render too large for the device fails before the scene's upload (and before
    // renderWavefrontReleasing frees anything). The renderer reads only the scene's features.
    WavefrontRenderer(GpuContext& context, const std::function<DeviceScene()>& upload,
                      const PreparedScene& scene, const gpu::Camera& camera,
                      const RenderSettings& settings, const WavefrontOptions& options)
        : setupPhase_("device set-up"), context_(context), settings_(settings), camera_(camera),
          options_(options), plan_(samplePlanFor(camera, settings, options)),
          budget_(plan_.range.size()), pixelCount_(camera.width * camera.height),
          buffers_(timedPhase("work buffers",
                              [&] {
                                  return WorkBuffers(
                                      context, slotCountFor(context, settings, plan_, options),
                                      settings.lightSamples, pixelCount_,
                                      {scene.features.instances, options.aovs});
                              })),
          scene_(timedUpload(upload)), table_(makeBufferTable(scene_, buffers_)),
          pipelines_(timedPhase("pipelines",
                                [&] {
                                    return WavefrontPipelines(
                                        context, table_, kernelFeaturesFor(scene, options),
                                        options.kernelBuilds, options.earlyPipelines);
                                })),
          timer_(makeTimer(context, options)),
          recorder_(pipelines_, buffers_, timer_.get(),
                    settings.integrator != Integrator::Normals && settings.lightSamples > 0),
          bounces_(bouncesToTrace(settings)) {}

    // The driver's loop, between the set-up and the result.
    WavefrontResult run();

    // The scene's device arrays, for the next frame of an animation to keep from (after run).
    DeviceScene takeScene() { return std::move(scene_); }

    std::uint32_t samplesDone() const override { return samplesDone_; }
    std::uint32_t budget() const override { return budget_; }
    std::uint64_t activePixels() const override { return activePixels_; }
    // As many samples as the path slots hold for the active pixels (pass_schedule.h).
    std::uint32_t batchWanted(std::uint32_t, double) const override {
        return samplesForPass(schedule());
    }
    std::uint64_t runBatch(std::uint32_t k) override;
    RenderSnapshot snapshot() override;
    std::vector<FeatureRecord> features() override;
    void finish() override { progress_->finish(); }
    std::uint32_t firstCalibration() const override {
        const AdaptiveSettings& adaptive = settings_.adaptive;
        return adaptive.enabled && adaptive.calibrated ? firstCalibrationPoint(adaptive.minSamples)
                                                       : 0;
    }
    void setVarianceScale(float scale) override { varianceScale_ = scale; }

private:
    void initialise();
    void uploadResumedStates();
    void uploadFeatures();
    void uploadActiveList();
    std::vector<gpu::PixelState> downloadPixelStates();
    ScheduleInputs schedule() const;
    gpu::PassParams chunkParams(std::uint32_t samplesPerPass, std::uint32_t start,
                                std::uint32_t pixels) const;
    void runChunk(const gpu::PassParams& params, bool firstChunk);
    void submit(const std::string& label, const std::function<void()>& record);
    WavefrontResult resultOf(RenderRunResult run);

    ScopedPhase setupPhase_; // from the first member to the first pass
    GpuContext& context_;
    const RenderSettings& settings_;
    gpu::Camera camera_;
    const WavefrontOptions& options_;
    SamplePlan plan_;
    std::uint32_t budget_; // samples per pixel of the plan's range
    std::uint32_t pixelCount_;
    WorkBuffers buffers_;
    DeviceScene scene_;
    BufferTable table_;
    WavefrontPipelines pipelines_;
    std::unique_ptr<GpuTimer> timer_;
    PassRecorder recorder_;
    std::uint64_t bounces_;
    KernelTimeTotals times_;
    std::unique_ptr<ProgressBar> progress_;

    // Where the render stands between passes.
    std::uint32_t activePixels_ = 0;
    std::uint32_t samplesDone_ = 0;
    std::uint32_t activeParity_ = 0;
    bool useActiveList_ = false;
    float varianceScale_ = 1.0f; // of the adaptive stopping rule (shared/adaptive.h)
    std::uint32_t passes_ = 0;
    std::uint64_t resumedSamples_ = 0; // Σ samples the resumed records had taken
};

void WavefrontRenderer::initialise() {
    gpu::FrameParams frame = makeFrameParams(settings_, camera_, scene_, buffers_.slotCount);
    upload(context_, buffers_.frameParams, std::span<const gpu::FrameParams>(&frame, 1));
    fillBuffer(context_, buffers_.pixelStates, 0);
    fillBuffer(context_, buffers_.queueCounters, 0);
    activePixels_ = pixelCount_;
    if (options_.resume) uploadResumedStates();
    if (options_.aovs) uploadFeatures();
    if (options_.resume || !(plan_.crop == fullFrame(camera_.width, camera_.height)))
        uploadActiveList();
}

void WavefrontRenderer::uploadResumedStates() {
    const std::vector<PixelRecord>& records = *options_.resume;
    VKPT_ASSERT(records.size() == plan_.crop.area(), "resume records cover the crop");
    std::vector<gpu::PixelState> pixels(pixelCount_, gpu::PixelState{});
    std::size_t i = 0;
    for (std::uint32_t y = plan_.crop.y0; y < plan_.crop.y1; ++y)
        for (std::uint32_t x = plan_.crop.x0; x < plan_.crop.x1; ++x, ++i) {
            pixels[std::size_t(y) * camera_.width + x] = pixelStateFromRecord(records[i]);
            resumedSamples_ += records[i].samplesTaken;
        }
    upload(context_, buffers_.pixelStates, std::span<const gpu::PixelState>(pixels));
}

// Every pixel starts with no feature samples (its depth +inf, which a fill of zeros is not), a
// resumed one with its features so far.
void WavefrontRenderer::uploadFeatures() {
    std::vector<gpu::PixelFeatures> pixels(pixelCount_, gpu::noPixelFeatures());
    if (const std::vector<FeatureRecord>* resumed = options_.resumeFeatures) {
        VKPT_ASSERT(resumed->size() == plan_.crop.area(), "resumed features cover the crop");
        std::size_t i = 0;
        for (std::uint32_t y = plan_.crop.y0; y < plan_.crop.y1; ++y)
            for (std::uint32_t x = plan_.crop.x0; x < plan_.crop.x1; ++x, ++i)
                pixels[std::size_t(y) * camera_.width + x] = pixelFeaturesOf((*resumed)[i]);
    }
    upload(context_, *buffers_.pixelFeatures, std::span<const gpu::PixelFeatures>(pixels));
}

// A crop or a resumed render starts from a list of the pixels that go on, instead of "every
// pixel" (useActiveList 0); all of them have taken the same number of samples, which is where
// the passes start.
void WavefrontRenderer::uploadActiveList() {
    const std::vector<PixelRecord>* resume = options_.resume;
    std::vector<std::uint32_t> active;
    std::optional<std::uint32_t> taken;
    std::size_t i = 0;
    for (std::uint32_t y = plan_.crop.y0; y < plan_.crop.y1; ++y)
        for (std::uint32_t x = plan_.crop.x0; x < plan_.crop.x1; ++x, ++i) {
            const PixelRecord record = resume ? (*resume)[i] : PixelRecord{};
            if (record.converged || record.samplesTaken >= budget_) continue;
            if (taken && *taken != record.samplesTaken)
                throw InputError("the state to resume has pixels at " + std::to_string(*taken) +
                                 " and at " + std::to_string(record.samplesTaken) +
                                 " samples; vkpt resumes only a state whose unfinished pixels "
                                 "all have the same count (vkpt-ref resumes any)");
            taken = record.samplesTaken;
            active.push_back(y * camera_.width + x);
        }
    samplesDone_ = taken.value_or(budget_);
    activePixels_ = std::uint32_t(active.size());
    if (!active.empty())
        upload(context_, buffers_.activePixels, std::span<const std::uint32_t>(active));
    activeParity_ = 0;
    useActiveList_ = true;
}

void WavefrontRenderer::submit(const std::string& label, const std::function<void()>& record) {
    submitAndWait(context_, label, [&](VkCommandBuffer commands) {
        recorder_.begin(commands);
        record();
        recorder_.readBackCounters();
    });
    if (timer_) times_.add(timer_->results());
}

// Bounces in submissions of kBouncesPerSubmission; between two, the host looks at the queue
// and stops early when every path of the chunk has ended.
void WavefrontRenderer::runChunk(const gpu::PassParams& params, bool firstChunk) {
    const std::string label =
        "pass " + std::to_string(passes_) + " chunk " + std::to_string(params.chunkStart);
    std::uint64_t bounce = 0;
    while (true) {
        const std::uint64_t end = std::min(bounces_, bounce + kBouncesPerSubmission);
        const bool last = end == bounces_;
        submit(label, [&] {
            if (bounce == 0 && firstChunk) recorder_.resetActiveList();
            if (bounce == 0) recorder_.generateCameraRays(params);
            for (std::uint64_t b = bounce; b < end; ++b) {
                gpu::PassParams bounceParams = params;
                bounceParams.bounce = static_cast<std::uint32_t>(b);
                recorder_.traceBounce(bounceParams);
            }
            if (last) recorder_.accumulate(params);
        });
        bounce = end;
        if (last) return;
        if (readCounters(buffers_.countersReadback).raysInQueue(bounce & 1) == 0) {
            submit(label + " accumulate", [&] { recorder_.accumulate(params); });
            return;
        }
    }
}

ScheduleInputs WavefrontRenderer::schedule() const {
    const AdaptiveSettings& adaptive = settings_.adaptive;
    return {budget_,          samplesDone_,       activePixels_,      buffers_.slotCount,
            adaptive.enabled, adaptive.batchSize, adaptive.minSamples};
}

gpu::PassParams WavefrontRenderer::chunkParams(std::uint32_t samplesPerPass, std::uint32_t start,
                                               std::uint32_t pixels) const {
    gpu::PassParams params{};
    params.sampleBase = plan_.range.begin + samplesDone_;
    params.samplesPerPass = samplesPerPass;
    params.chunkStart = start;
    params.chunkPixels = pixels;
    params.activeParity = activeParity_;
    params.useActiveList = useActiveList_ ? 1u : 0u;
    params.adaptiveVarianceScale = varianceScale_;
    params.recordAovs = options_.aovs ? 1u : 0u;
    return params;
}

std::uint64_t WavefrontRenderer::runBatch(std::uint32_t k) {
    const std::uint32_t chunk = pixelsPerChunk(activePixels_, k, buffers_.slotCount);
    const std::uint64_t samples = std::uint64_t(activePixels_) * k;
    for (std::uint32_t start = 0; start < activePixels_; start += chunk)
        runChunk(chunkParams(k, start, std::min(chunk, activePixels_ - start)), start == 0);
    activePixels_ = readCounters(buffers_.countersReadback).nextActivePixels();
    activeParity_ ^= 1u;
    useActiveList_ = true;
    samplesDone_ += k;
    ++passes_;
    progress_->setStatus("active pixels " + std::to_string(activePixels_));
    progress_->advance(k);
    return samples;
}

std::vector<gpu::PixelState> WavefrontRenderer::downloadPixelStates() {
    return download<gpu::PixelState>(context_, buffers_.pixelStates, pixelCount_);
}

// The crop's features, row-major; none without AOVs.
std::vector<FeatureRecord> WavefrontRenderer::features() {
    if (!options_.aovs) return {};
    const std::vector<gpu::PixelFeatures> pixels =
        download<gpu::PixelFeatures>(context_, *buffers_.pixelFeatures, pixelCount_);
    std::vector<FeatureRecord> features;
    features.reserve(plan_.crop.area());
    for (std::uint32_t y = plan_.crop.y0; y < plan_.crop.y1; ++y)
        for (std::uint32_t x = plan_.crop.x0; x < plan_.crop.x1; ++x)
            features.push_back(featureRecordOf(pixels[std::size_t(y) * camera_.width + x]));
    return features;
}

// One readback of the pixel states (consistent at a pass end).
RenderSnapshot WavefrontRenderer::snapshot() {
    const std::vector<gpu::PixelState> pixels = downloadPixelStates();
    return {cropRecords(pixels, camera_.width, plan_.crop),
            makeRenderOutput(pixels, camera_.width, camera_.height)};
}

WavefrontResult WavefrontRenderer::resultOf(RenderRunResult run) {
    WavefrontResult result;
    static_cast<RenderRunResult&>(result) = std::move(run);
    DeviceCounters counters = readCounters(buffers_.countersReadback);
    addCounterStats(counters, result.stats);
    std::uint64_t taken = 0;
    for (const PixelRecord& record : result.records)
        taken += record.samplesTaken;
    result.stats.samplesTaken = taken - resumedSamples_;
    result.stats.uniformBudget = std::uint64_t(plan_.crop.area()) * budget_;
    result.kernelTimes = times_.totals();
    result.truncatedTraversals = counters.words[COUNTER_TRUNCATED];
    result.passes = passes_;
    result.slotCount = buffers_.slotCount;
    result.pipelineCreationSeconds = pipelines_.creationSeconds();
    result.pipelineCreations = pipelines_.creations();
    result.pipelinesCreatedEarly = pipelines_.createdEarly();
    result.sceneBuffers = scene_.bufferBytes();
    result.sceneBufferBytes = scene_.totalBytes();
    return result;
}

WavefrontResult WavefrontRenderer::run() {
    initialise();
    setupPhase_.end();
    ScopedPhase renderPhase("render");
    progress_ = makeProgressBar("vkpt", budget_, settings_.quiet);
    progress_->advance(samplesDone_);
    return resultOf(runRender(*this, options_));
}

} // namespace

WavefrontResult renderWavefront(GpuContext& context, const PreparedScene& scene,
                                const gpu::Camera& camera, const RenderSettings& settings,
                                const WavefrontOptions& options) {
    WavefrontRenderer renderer(
        context, [&] { return uploadScene(context, scene); }, scene, camera, settings, options);
    return renderer.run();
}

WavefrontResult renderWavefrontReleasing(GpuContext& context, PreparedScene& scene,
                                         const gpu::Camera& camera, const RenderSettings& settings,
                                         const WavefrontOptions& options) {
    // The tree (the device walks the wide nodes) and the host's meshes are freed first, once the
    // working buffers exist: a render too large for the device has failed by then.
    auto release = [&] {
        scene.tree = {};
        scene.meshes = {};
        scene.instanceTree = {};
        return uploadSceneAndRelease(context, scene);
    };
    WavefrontRenderer renderer(context, release, scene, camera, settings, options);
    return renderer.run();
}

WavefrontResult renderWavefrontKeeping(GpuContext& context, PreparedScene& scene,
                                       const gpu::Camera& camera, const RenderSettings& settings,
                                       const WavefrontOptions& options, KeptDeviceScene& kept) {
    auto upload = [&] {
        scene.tree = {};
        scene.meshes = {};
        scene.instanceTree = {};
        return kept.upload(context, scene);
    };
    // The upload takes what `kept` held: a frame that fails leaves nothing for the next to keep.
    WavefrontRenderer renderer(context, upload, scene, camera, settings, options);
    WavefrontResult result = renderer.run();
    kept.keep(renderer.takeScene());
    return result;
}

} // namespace vkpt
