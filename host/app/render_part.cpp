// render_part.cpp — identity, resume checks, the state of a part, checkpoints and the rescue.
#include "app/render_part.h"

#include <algorithm>
#include <cstdio>

#include "app/live_preview.h"
#include "app/output_checks.h"
#include "common/errors.h"
#include "common/phase_log.h"
#include "driver/denoised_output.h"
#include "image/image_file.h"
#include "image/image_io.h"
#include "prepare/scene_hash.h"
#include "state/atomic_write.h"
#include "state/state_file.h"
#include "state/state_merge.h"

namespace vkpt {

namespace {

// The samples the records hold, as the ranges of their region: uniform sampling takes the same
// samples in every pixel, [begin, begin + taken); adaptive sampling the prefix [0, B) that the
// pixels still going have reached (converged ones stopped within it).
std::vector<SampleRange> rangesTaken(const std::vector<PixelRecord>& records,
                                     const SamplePlan& plan, bool adaptive) {
    std::uint32_t most = 0, least = UINT32_MAX;
    for (const PixelRecord& p : records) {
        most = std::max(most, p.samplesTaken);
        least = std::min(least, p.samplesTaken);
    }
    if (records.empty() || most == 0) return {};
    if (adaptive) return {{0, most}};
    VKPT_ASSERT(least == most, "uniform sampling gives every pixel the same samples");
    return {{plan.range.begin, plan.range.begin + most}};
}

} // namespace

RenderPart::RenderPart(std::string program, const RenderSettings& settings,
                       const FarmSettings& farm)
    : program_(std::move(program)), settings_(settings), farm_(farm),
      plan_(samplePlanFor(farm, settings)) {
    if (!farm.resumePath.empty()) resumed_ = readStateFile(farm.resumePath);
}

void RenderPart::attachScene(const SceneSetup& setup) {
    setup_ = &setup;
    ScopedPhase hashPhase("scene hash");
    identity_ = {sceneContentHash(setup.prepared, setup.camera), settingsKey(settings_),
                 settings_.seed, settings_.width, settings_.height};
    hashPhase.end();
    if (!resumed_) return;
    checkResumable(*resumed_);
    const std::vector<SampleRange>& ranges = resumed_->regions.front().ranges;
    std::fprintf(stderr, "%s: resuming %s: samples %s of %s done\n", program_.c_str(),
                 farm_.resumePath.c_str(), describeRanges(ranges).c_str(),
                 describeRanges({plan_.range}).c_str());
}

void RenderPart::checkResumable(const RenderState& resumed) {
    const std::string& path = farm_.resumePath;
    RenderState self;
    self.identity = identity_;
    checkSameRender({"this render", self}, {path, resumed});
    if (farm_.crop && !(*farm_.crop == resumed.window))
        throw InputError(path + ": holds pixels " + describeRect(resumed.window) +
                         ", but --crop asks for " + describeRect(*farm_.crop));
    plan_.crop = resumed.window;
    if (resumed.regions.size() != 1 || !(resumed.regions[0].rect == resumed.window))
        throw InputError(path + ": a merge of several regions; resume each part from its own "
                                "state, or render the rest with --crop");
    const std::vector<SampleRange> ranges = normalizedRanges(resumed.regions[0].ranges);
    const std::uint32_t start = settings_.adaptive.enabled ? 0 : plan_.range.begin;
    const bool prefix = ranges.empty() || (ranges.size() == 1 && ranges[0].begin == start);
    if (!prefix)
        throw InputError(path + ": holds samples " + describeRanges(ranges) +
                         ", which do not start this render's share " +
                         describeRanges({plan_.range}) +
                         " (resume with the --task and --spp the part was started with)");
}

bool RenderPart::needsAovs() const {
    return outputHoldsState(settings_.outputPath) || farm_.checkpointSeconds > 0.0 ||
           settings_.denoise || resumeFeatures() != nullptr;
}

const std::vector<FeatureRecord>* RenderPart::resumeFeatures() const {
    return resumed_ && !resumed_->features.empty() ? &resumed_->features : nullptr;
}

RenderState RenderPart::stateOf(const std::vector<PixelRecord>& records,
                                const std::vector<FeatureRecord>& features) const {
    VKPT_ASSERT(features.empty() || features.size() == records.size(),
                "features cover the records' pixels");
    RenderState state;
    state.identity = identity_;
    state.origin.program = program_;
    state.origin.scene = settings_.scenePath;
    if (farm_.task)
        state.origin.task =
            std::to_string(farm_.task->index) + "/" + std::to_string(farm_.task->count);
    state.window = plan_.crop;
    state.regions = {{plan_.crop, rangesTaken(records, plan_, settings_.adaptive.enabled)}};
    state.pixels = records;
    state.features = features;
    return state;
}

void RenderPart::writeState(const RenderState& state, const std::string& path, const char* what) {
    writeStateFile(state, path);
    const std::vector<SampleRange>& ranges = state.regions.front().ranges;
    std::fprintf(stderr, "%s: %s: wrote %s (samples %s)\n", program_.c_str(), what, path.c_str(),
                 describeRanges(ranges).c_str());
}

std::function<void(const std::vector<PixelRecord>&, const std::vector<FeatureRecord>&)>
RenderPart::checkpointWriter(Denoiser* denoiser) {
    return [this, denoiser](const std::vector<PixelRecord>& records,
                            const std::vector<FeatureRecord>& features) {
        RenderState state = stateOf(records, features);
        if (denoiser && !features.empty() && features.size() == records.size())
            state.denoised = denoiseWindow(*denoiser, plan_.crop, records, features);
        writeState(state, statePathFor(settings_.outputPath), "checkpoint");
    };
}

void RenderPart::writeResults(const RenderOutput& output, const std::vector<PixelRecord>& records,
                              const std::vector<FeatureRecord>& features,
                              const std::vector<glm::vec3>& denoised, bool stopped) {
    const std::string& path = settings_.outputPath;
    const RenderState state = stateOf(records, features);
    try {
        if (outputHoldsState(path)) {
            RenderState shown = state;
            shown.denoised = denoised;
            writeStateFile(shown, path);
        } else {
            writeDisplayImage(denoised.empty() ? output.image
                                               : denoisedFrame(output.image, plan_.crop, denoised),
                              settings_);
        }
        writeSampleCountHeatMap(output.sampleCounts, output.image.width, output.image.height,
                                heatMapPathFor(path));
        if (!outputHoldsState(path) && (stopped || farm_.checkpointSeconds > 0.0))
            writeState(state, statePathFor(path), "state");
    } catch (const InputError& error) {
        const std::string rescue = rescuePathFor(statePathFor(path));
        try {
            writeStateFile(state, rescue);
        } catch (const std::exception& second) {
            throw InputError(std::string(error.what()) +
                             "; saving the state failed too: " + second.what());
        }
        throw InputError(std::string(error.what()) + "; the render's state is saved in " + rescue +
                         " (resume or merge it from there)");
    }
}

} // namespace vkpt
