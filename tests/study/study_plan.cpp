// study_plan.cpp — the runs of the trade study, strategy by strategy.
#include "study/study_plan.h"

#include <cstdio>

namespace vkpt {

namespace {

std::string formatTolerance(float tolerance) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", double(tolerance));
    return text;
}

RenderSettings studySettings(const RenderSettings& base, std::uint32_t spp) {
    RenderSettings s;
    s.scenePath = base.scenePath;
    s.width = base.width;
    s.height = base.height;
    s.cameraIndex = base.cameraIndex;
    s.samplesPerPixel = spp;
    s.seed = kStudySeed;
    s.quiet = true;
    return s;
}

std::string sppFlag(std::uint32_t spp) {
    return "--spp " + std::to_string(spp);
}

void addUniform(std::vector<StudyRun>& runs, const RenderSettings& base, const StudyScale& scale) {
    runs.push_back({"uniform", "uniform", sppFlag(scale.maxSpp), studySettings(base, scale.maxSpp),
                    StudyReference::Full});
}

void addAdaptive(std::vector<StudyRun>& runs, const RenderSettings& base, const StudyScale& scale) {
    for (std::uint32_t batch : scale.adaptiveBatches)
        for (float tolerance : scale.tolerances) {
            RenderSettings s = studySettings(base, scale.maxSpp);
            s.adaptive.enabled = true;
            s.adaptive.batchSize = batch;
            s.adaptive.tolerance = tolerance;
            s.adaptive.minSamples = scale.adaptiveMinSamples;
            s.adaptive.calibrated = base.adaptive.calibrated;
            const std::string tol = formatTolerance(tolerance);
            runs.push_back({"adaptive", "adaptive b" + std::to_string(batch) + " tol " + tol,
                            sppFlag(scale.maxSpp) + " --adaptive " + std::to_string(batch) + " " +
                                tol + " --adaptive-min " +
                                std::to_string(scale.adaptiveMinSamples) +
                                (s.adaptive.calibrated ? "" : " --adaptive-error variance"),
                            s, StudyReference::Full});
        }
}

// The direct-lighting integrator's two estimators, both converging to the direct reference.
void addSampling(std::vector<StudyRun>& runs, const RenderSettings& base, const StudyScale& scale) {
    for (LightSampling sampling : {LightSampling::Light, LightSampling::Hemisphere}) {
        RenderSettings s = studySettings(base, scale.sideSpp);
        s.integrator = Integrator::Direct;
        s.lightSampling = sampling;
        const bool light = sampling == LightSampling::Light;
        runs.push_back({"sampling", light ? "light sampling" : "hemisphere sampling",
                        sppFlag(scale.sideSpp) + " --integrator direct --light-sampling " +
                            (light ? "light" : "hemisphere"),
                        s, StudyReference::Direct});
    }
}

void addDepths(std::vector<StudyRun>& runs, const RenderSettings& base, const StudyScale& scale) {
    for (std::uint32_t depth : scale.depths) {
        RenderSettings s = studySettings(base, scale.sideSpp);
        s.maxDepth = depth;
        runs.push_back({"depth", "max depth " + std::to_string(depth),
                        sppFlag(scale.sideSpp) + " --max-depth " + std::to_string(depth), s,
                        StudyReference::Full});
    }
}

void addRoulette(std::vector<StudyRun>& runs, const RenderSettings& base, const StudyScale& scale) {
    for (std::uint32_t start : scale.rouletteStarts) {
        RenderSettings s = studySettings(base, scale.sideSpp);
        // A start beyond the depth limit never plays roulette.
        s.rrStartDepth = start == 0 ? s.maxDepth + 1 : start;
        const std::string value = std::to_string(s.rrStartDepth);
        runs.push_back({"roulette",
                        start == 0 ? "no roulette" : "roulette from " + std::to_string(start),
                        sppFlag(scale.sideSpp) + " --rr-depth " + value, s, StudyReference::Full});
    }
}

// Uniform sampling with the pipelines and buffers specialised to the scene's features (vkpt's
// default) and with the all-features ones (--general), rendered one after the other so that
// the machine's load changes as little as possible between the two.
void addPipelines(std::vector<StudyRun>& runs, const RenderSettings& base,
                  const StudyScale& scale) {
    for (bool general : {false, true}) {
        RenderSettings s = studySettings(base, scale.sideSpp);
        s.general = general;
        runs.push_back({"pipeline", general ? "general pipelines" : "specialised pipelines",
                        sppFlag(scale.sideSpp) + (general ? " --general" : ""), s,
                        StudyReference::Full, false});
    }
}

} // namespace

const std::vector<std::string>& studyFamilies() {
    static const std::vector<std::string> families{"uniform", "adaptive", "sampling",
                                                   "depth",   "roulette", "pipeline"};
    return families;
}

std::string familyList(const std::vector<std::string>& families) {
    std::string list;
    for (const std::string& f : families)
        list += (list.empty() ? "" : ",") + f;
    return list;
}

const char* referenceName(StudyReference reference) {
    return reference == StudyReference::Full ? "full" : "direct";
}

StudyScale fullScale() {
    return StudyScale{};
}

StudyScale quickScale() {
    StudyScale s;
    s.width = s.height = 32;
    s.maxSpp = 64;
    s.sideSpp = 16;
    s.referenceSpp = 1024;
    s.adaptiveBatches = {8};
    s.tolerances = {0.2f, 0.1f};
    s.adaptiveMinSamples = 16;
    s.depths = {1, 16};
    s.rouletteStarts = {3, 0};
    return s;
}

std::vector<StudyRun> planStudy(const RenderSettings& base, const StudyScale& scale) {
    std::vector<StudyRun> runs;
    addUniform(runs, base, scale);
    addAdaptive(runs, base, scale);
    addSampling(runs, base, scale);
    addDepths(runs, base, scale);
    addRoulette(runs, base, scale);
    addPipelines(runs, base, scale);
    return runs;
}

RenderSettings referenceSettings(const RenderSettings& base, const StudyScale& scale,
                                 StudyReference reference) {
    RenderSettings s = studySettings(base, scale.referenceSpp);
    s.seed = kReferenceSeed;
    if (reference == StudyReference::Direct) {
        s.integrator = Integrator::Direct; // light sampling, the lower-variance estimator
    } else {
        s.maxDepth = scale.referenceDepth;
    }
    return s;
}

bool sameSamplesExceptBudget(const RenderSettings& a, const RenderSettings& b) {
    return a.scenePath == b.scenePath && a.width == b.width && a.height == b.height &&
           a.cameraIndex == b.cameraIndex && a.seed == b.seed && a.maxDepth == b.maxDepth &&
           a.rrStartDepth == b.rrStartDepth && a.integrator == b.integrator &&
           a.lightSampling == b.lightSampling && a.lightSamples == b.lightSamples &&
           a.pathFilter == b.pathFilter && a.clamp == b.clamp && a.general == b.general &&
           !a.adaptive.enabled && !b.adaptive.enabled;
}

} // namespace vkpt
