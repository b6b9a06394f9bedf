// study_plan.h — what the trade study (vkpt-study) renders: for one scene, the runs of each
// strategy whose error against time it measures, and the references they are measured against.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/render_settings.h"

namespace vkpt {

// Which reference a run is compared with: the full light transport, or direct lighting only
// (what the light- and hemisphere-sampling estimators of --integrator direct converge to).
enum class StudyReference { Full, Direct };
const char* referenceName(StudyReference reference); // "full", "direct"

// The sizes of a study. fullScale() is what docs/trade/ holds; quickScale() is the seconds-long
// version CI runs.
struct StudyScale {
    std::uint32_t width = 128;
    std::uint32_t height = 128;
    std::uint32_t maxSpp = 4096;  // uniform and adaptive budgets
    std::uint32_t sideSpp = 1024; // light/hemisphere, depth, roulette and pipeline budgets
    std::uint32_t referenceSpp = 16384;
    std::uint32_t referenceDepth = 64; // scattering events of the full reference
    std::vector<std::uint32_t> adaptiveBatches{16, 64};
    std::vector<float> tolerances{0.2f, 0.1f, 0.05f, 0.025f};
    std::uint32_t adaptiveMinSamples = 64;
    std::vector<std::uint32_t> depths{1, 2, 4, 8, 16, 32};
    std::vector<std::uint32_t> rouletteStarts{1, 3, 8, 0}; // 0: no roulette
};
StudyScale fullScale();
StudyScale quickScale();

// Seeds: every run renders with kStudySeed; the references with kReferenceSeed, so that no run
// shares a random number with its reference (shared numbers would hide the error).
inline constexpr std::uint32_t kStudySeed = 1;
inline constexpr std::uint32_t kReferenceSeed = 0x5eed0001u;

struct StudyRun {
    std::string family; // "uniform", "adaptive", "sampling", "depth", "roulette", "pipeline"
    std::string label;  // unique: "uniform", "adaptive b16 tol 0.05", "max depth 4", ...
    std::string flags;  // the vkpt options that select it: "--spp 4096 --adaptive 16 0.05"
    RenderSettings settings;
    StudyReference reference = StudyReference::Full;
    // false: rendered even when an earlier run took the same samples, and never lent to a
    // later one, so that its time is measured beside the run it is compared with.
    bool shareable = true;
};

// The families of planStudy, in its order, and a list of families as --only takes it
// ("uniform,adaptive").
const std::vector<std::string>& studyFamilies();
std::string familyList(const std::vector<std::string>& families);

// The runs, in the order they are rendered and reported. `base` supplies the scene, size and
// camera; every other setting comes from the plan.
std::vector<StudyRun> planStudy(const RenderSettings& base, const StudyScale& scale);

// The settings of a reference render (kReferenceSeed, scale.referenceSpp, no adaptive stop).
RenderSettings referenceSettings(const RenderSettings& base, const StudyScale& scale,
                                 StudyReference reference);

// Whether two settings trace the same samples with the same pipelines except for the budget,
// so that the render with the smaller --spp is a prefix of the other (its curve can be read
// off the larger run's).
bool sameSamplesExceptBudget(const RenderSettings& a, const RenderSettings& b);

} // namespace vkpt
