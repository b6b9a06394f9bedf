// trade_study_test.cpp — the parts of vkpt-study that need no device: the plan of runs, the
// time at which a curve reaches an error, adaptive's speedup, the CSV written and read back,
// the table (with the pipeline comparison) and plot script, and the reference cache.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "common/errors.h"
#include "study/reference_cache.h"
#include "study/study_curves.h"
#include "study/study_data.h"
#include "study/study_output.h"
#include "study/study_plan.h"

namespace vkpt::trade_study_test {
namespace {

ConvergencePoint point(double seconds, double relMse, std::uint32_t spp = 1) {
    ConvergencePoint p;
    p.figures.seconds = p.figures.renderSeconds = seconds;
    p.figures.samplesPerPixel = spp;
    p.figures.samplesTaken = std::uint64_t(spp) * 16;
    p.relMse = relMse;
    return p;
}

RunResult result(const std::string& family, const std::string& label,
                 std::vector<ConvergencePoint> curve) {
    RunResult r;
    r.run.family = family;
    r.run.label = label;
    r.run.flags = "--spp 64";
    r.curve = std::move(curve);
    return r;
}

RenderSettings base() {
    RenderSettings s;
    s.scenePath = VKPT_SCENES_DIR "/cornell-box.gltf";
    s.width = s.height = 32;
    return s;
}

TEST(TradeStudyPlan, CoversEveryStrategyWithUniqueLabels) {
    for (const StudyScale& scale : {fullScale(), quickScale()}) {
        const std::vector<StudyRun> runs = planStudy(base(), scale);
        std::set<std::string> labels, families;
        for (const StudyRun& run : runs) {
            EXPECT_TRUE(labels.insert(run.label).second) << run.label;
            families.insert(run.family);
            EXPECT_EQ(run.settings.seed, kStudySeed);
            EXPECT_NE(run.settings.seed, kReferenceSeed);
        }
        EXPECT_EQ(families, (std::set<std::string>{"uniform", "adaptive", "sampling", "depth",
                                                   "roulette", "pipeline"}));
        EXPECT_EQ(families, std::set<std::string>(studyFamilies().begin(), studyFamilies().end()));
    }
}

TEST(TradeStudyPlan, SpecialisedAndGeneralPipelinesAreTimedOneAfterTheOther) {
    for (const StudyScale& scale : {fullScale(), quickScale()}) {
        std::vector<StudyRun> pipelines;
        for (const StudyRun& run : planStudy(base(), scale))
            if (run.family == "pipeline") pipelines.push_back(run);
        ASSERT_EQ(pipelines.size(), 2u);
        EXPECT_EQ(pipelines[0].label, "specialised pipelines");
        EXPECT_FALSE(pipelines[0].settings.general);
        EXPECT_EQ(pipelines[1].label, "general pipelines");
        EXPECT_TRUE(pipelines[1].settings.general);
        EXPECT_EQ(pipelines[1].flags, "--spp " + std::to_string(scale.sideSpp) + " --general");
        for (const StudyRun& run : pipelines) {
            // Rendered, not read off the uniform run, so that both are timed side by side.
            EXPECT_FALSE(run.shareable);
            EXPECT_EQ(run.settings.samplesPerPixel, scale.sideSpp);
            EXPECT_FALSE(run.settings.adaptive.enabled);
            EXPECT_EQ(run.reference, StudyReference::Full);
        }
    }
}

TEST(TradeStudyPlan, LightAndHemisphereSamplingAreMeasuredAgainstDirectLighting) {
    for (const StudyRun& run : planStudy(base(), fullScale()))
        if (run.family == "sampling") {
            EXPECT_EQ(run.reference, StudyReference::Direct);
            EXPECT_EQ(run.settings.integrator, Integrator::Direct);
        } else {
            EXPECT_EQ(run.reference, StudyReference::Full);
        }
}

TEST(TradeStudyPlan, NoRouletteMeansAStartBeyondTheDepth) {
    bool found = false;
    for (const StudyRun& run : planStudy(base(), fullScale()))
        if (run.label == "no roulette") {
            found = true;
            EXPECT_GT(run.settings.rrStartDepth, run.settings.maxDepth);
        }
    EXPECT_TRUE(found);
}

TEST(TradeStudyPlan, ReferencesUseTheirOwnSeedAndDepth) {
    const RenderSettings full = referenceSettings(base(), fullScale(), StudyReference::Full);
    EXPECT_EQ(full.seed, kReferenceSeed);
    EXPECT_EQ(full.samplesPerPixel, fullScale().referenceSpp);
    EXPECT_EQ(full.maxDepth, fullScale().referenceDepth);
    EXPECT_FALSE(full.adaptive.enabled);
    EXPECT_EQ(referenceSettings(base(), fullScale(), StudyReference::Direct).integrator,
              Integrator::Direct);
}

TEST(TradeStudyPlan, OnlyTheBudgetMayDifferForARunToBeShared) {
    RenderSettings a = base(), b = base();
    b.samplesPerPixel = 4 * a.samplesPerPixel;
    EXPECT_TRUE(sameSamplesExceptBudget(a, b));
    b.maxDepth = 3;
    EXPECT_FALSE(sameSamplesExceptBudget(a, b));
    b = a;
    b.adaptive.enabled = true;
    EXPECT_FALSE(sameSamplesExceptBudget(a, b));
    b = a;
    b.general = true; // the same samples, but not the same time
    EXPECT_FALSE(sameSamplesExceptBudget(a, b));
}

TEST(TradeStudyCurves, InterpolatesTheCrossingOnLogLogAxes) {
    // From (1 s, 1e-1) to (10 s, 1e-3): 1e-2 is halfway on both log axes.
    const std::vector<ConvergencePoint> curve{point(1.0, 1e-1), point(10.0, 1e-3)};
    EXPECT_NEAR(timeToReach(curve, 1e-2, StudyClock::Wall), std::sqrt(10.0), 1e-9);
    EXPECT_NEAR(timeToReach(curve, 1e-3, StudyClock::Wall), 10.0, 1e-9);
    EXPECT_TRUE(std::isnan(timeToReach(curve, 1e-4, StudyClock::Wall)));
}

TEST(TradeStudyCurves, ACurveThatStartsBelowReachesAtItsFirstPoint) {
    EXPECT_EQ(timeToReach({point(0.5, 1e-3), point(1.0, 1e-4)}, 1e-2, StudyClock::Wall), 0.5);
}

TEST(TradeStudyCurves, TheFirstCrossingCountsAndUnknownPointsAreSkipped) {
    const std::vector<ConvergencePoint> curve{point(1.0, std::nan("")), point(2.0, 2e-2),
                                              point(4.0, 5e-3), point(8.0, 2e-2),
                                              point(16.0, 1e-3)};
    const double t = timeToReach(curve, 1e-2, StudyClock::Wall);
    EXPECT_GT(t, 2.0);
    EXPECT_LT(t, 4.0);
}

TEST(TradeStudyCurves, APrefixKeepsThePointsWithinTheBudget) {
    const std::vector<ConvergencePoint> curve{point(1, 1, 4), point(2, 1, 8), point(3, 1, 12)};
    EXPECT_EQ(curvePrefix(curve, 8).size(), 2u);
}

TEST(TradeStudyCurves, AdaptiveSpeedupComparesTheBestAdaptiveRunInTimeAndInSamples) {
    const std::vector<RunResult> results{
        result("uniform", "uniform", {point(1.0, 1e-1, 1), point(10.0, 1e-3, 100)}),
        result("adaptive", "fewer samples", {point(1.0, 1e-1, 1), point(20.0, 1e-3, 50)}),
        result("adaptive", "faster", {point(1.0, 1e-1, 1), point(5.0, 1e-3, 80)})};
    const AdaptiveSpeedup s = adaptiveSpeedup(results, 1e-3, StudyClock::Wall);
    EXPECT_EQ(s.fastestLabel, "faster");
    EXPECT_NEAR(s.inTime(), 2.0, 1e-12);
    EXPECT_EQ(s.fewestSamplesLabel, "fewer samples");
    EXPECT_NEAR(s.inSamples(), 2.0, 1e-12);
    EXPECT_TRUE(std::isnan(adaptiveSpeedup(results, 1e-4, StudyClock::Wall).inTime()));
}

TEST(TradeStudyCurves, TheCpuClockReadsTheCpuTime) {
    ConvergencePoint p = point(2.0, 1e-2);
    p.figures.cpuSeconds = 3.5;
    EXPECT_EQ(curveSeconds(p, StudyClock::Wall), 2.0);
    EXPECT_EQ(curveSeconds(p, StudyClock::Cpu), 3.5);
}

StudySummary sampleSummary() {
    StudySummary summary;
    summary.name = "box";
    summary.scene = "scenes/box.gltf";
    summary.width = summary.height = 4;
    summary.machine = "a test machine";
    summary.note = "A note.";
    summary.studySeconds = 12.5;
    ReferenceInfo reference;
    reference.renderer = "vkpt-ref (CPU, 2 threads)";
    reference.spp = 1024;
    reference.maxDepth = 64;
    reference.seconds = 3.25;
    reference.estimatedRelMse = 1.5e-5;
    summary.references.push_back(reference);
    summary.results.push_back(
        result("uniform", "uniform", {point(0.1, 0.5, 1), point(1, 4e-3, 9)}));
    RunResult adaptive = result("adaptive", "adaptive b16 tol 0.1", {point(0.5, 2e-3, 7)});
    adaptive.run.settings.adaptive = {true, 16, 0.1f, 64, true};
    adaptive.run.flags = "--spp 64 --adaptive 16 0.1";
    summary.results.push_back(adaptive);
    RunResult shared = result("depth", "max depth 16", {point(0.1, 0.5, 1)});
    shared.sharedWith = "uniform";
    summary.results.push_back(shared);
    // The general run is the specialised one 1.1 times slower throughout.
    RunResult specialised =
        result("pipeline", "specialised pipelines", {point(0.1, 0.5, 1), point(1, 4e-3, 9)});
    specialised.setupSeconds = 0.02;
    summary.results.push_back(specialised);
    RunResult general =
        result("pipeline", "general pipelines", {point(0.11, 0.5, 1), point(1.1, 4e-3, 9)});
    general.run.flags = "--spp 64 --general";
    general.setupSeconds = 0.05;
    summary.results.push_back(general);
    return summary;
}

TEST(TradeStudyData, TheCsvAndDescriptionReadBackToTheSameReport) {
    const StudySummary summary = sampleSummary();
    std::ostringstream csv, meta;
    writeStudyCsv(csv, summary);
    writeStudyMeta(meta, summary);
    std::istringstream csvIn(csv.str()), metaIn(meta.str());
    const StudySummary back = readStudySummary(csvIn, metaIn);
    std::ostringstream table, tableBack, script, scriptBack;
    writeStudyTable(table, summary, "box.svg", "box-headline.svg");
    writeStudyTable(tableBack, back, "box.svg", "box-headline.svg");
    EXPECT_EQ(table.str(), tableBack.str());
    writeGnuplotScript(script, summary, "h.svg", "o.svg");
    writeGnuplotScript(scriptBack, back, "h.svg", "o.svg");
    EXPECT_EQ(script.str(), scriptBack.str());
}

TEST(TradeStudyData, AForeignCsvIsRefused) {
    std::istringstream csv("a,b,c\n1,2,3\n"), meta("size 4 4\n");
    EXPECT_THROW(readStudySummary(csv, meta), InputError);
}

TEST(TradeStudyOutput, TheTableHasTheHeadline) {
    std::ostringstream table;
    writeStudyTable(table, sampleSummary(), "box.svg", "box-headline.svg");
    const std::string text = table.str();
    for (const char* expected :
         {"time to relMSE 1e-2", "time to relMSE 1e-3", "| uniform (defaults) |", "(6 spp)",
          "**1.29×** in wall time", "max depth 16 (= uniform)", "1024", "A note.",
          "![box: uniform against adaptive"})
        EXPECT_NE(text.find(expected), std::string::npos) << expected << " in\n" << text;
}

TEST(TradeStudyOutput, TheTableComparesGeneralWithSpecialisedPipelines) {
    std::ostringstream table;
    writeStudyTable(table, sampleSummary(), "box.svg", "box-headline.svg");
    const std::string text = table.str();
    for (const char* expected :
         {"| specialised pipelines (defaults, timed beside general) | `--spp 64` |",
          "| general pipelines | `--spp 64 --general` |", "General over specialised pipelines",
          "- to relMSE 1e-02: **1.10×** (", "- to relMSE 1e-03: not measured",
          "- the whole budget, 9 samples/pixel: **1.10×** (1.1 s against 1 s)",
          "wall time): 0.05 s against 0.02 s"})
        EXPECT_NE(text.find(expected), std::string::npos) << expected << " in\n" << text;
}

TEST(TradeStudyOutput, TheScriptWritesBothPlotsWithLogAxes) {
    std::ostringstream script;
    writeGnuplotScript(script, sampleSummary(), "h.svg", "o.svg");
    const std::string text = script.str();
    for (const char* expected : {"set output 'h.svg'", "set output 'o.svg'", "set logscale xy",
                                 "$run0 << EOD", "$adaptive16 << EOD", "set multiplot",
                                 "$run4 using 1:2 with lines lw 2 title 'general pipelines'"})
        EXPECT_NE(text.find(expected), std::string::npos) << expected;
}

TEST(ReferenceCache, NamesTheSceneAndSettingsAndChangesWithThem) {
    RenderSettings s = base();
    s.samplesPerPixel = 256;
    const std::string path = referenceCachePath("/cache", s, StudyReference::Full);
    EXPECT_EQ(path.rfind("/cache/references/cornell-box-32x32-full-256spp-", 0), 0u) << path;
    EXPECT_EQ(referenceCachePath("/cache", s, StudyReference::Full), path);
    s.seed += 1;
    EXPECT_NE(referenceCachePath("/cache", s, StudyReference::Full), path);
}

TEST(ReferenceCache, WritesAndReadsAnImageWithItsDescription) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "vkpt_trade_study_test_cache";
    std::filesystem::remove_all(dir);
    const std::string path = (dir / "references" / "r.pfm").string();
    EXPECT_FALSE(readCachedReference(path).has_value());
    Image image(3, 2);
    image.pixels[4] = glm::vec3(0.25f, 0.5f, 4.0f);
    ReferenceInfo info;
    info.renderer = "vkpt-ref (CPU, 2 threads)";
    info.spp = 4096;
    info.maxDepth = 64;
    info.seconds = 12.5;
    info.estimatedRelMse = 2.5e-5;
    writeCachedReference(path, image, info);
    const std::optional<CachedReference> cached = readCachedReference(path);
    ASSERT_TRUE(cached.has_value());
    EXPECT_EQ(cached->image.pixels[4], image.pixels[4]);
    EXPECT_EQ(cached->info.renderer, info.renderer);
    EXPECT_EQ(cached->info.spp, 4096u);
    EXPECT_DOUBLE_EQ(cached->info.estimatedRelMse, 2.5e-5);
    EXPECT_TRUE(cached->info.cached);
    std::filesystem::remove_all(dir);
}

TEST(ReferenceCache, DefaultsToXdgCacheHome) {
    const char* saved = std::getenv("XDG_CACHE_HOME");
    const std::string previous = saved ? saved : "";
    setenv("XDG_CACHE_HOME", "/somewhere/cache", 1);
    EXPECT_EQ(defaultCacheDirectory(), "/somewhere/cache/vkpt");
    if (saved)
        setenv("XDG_CACHE_HOME", previous.c_str(), 1);
    else
        unsetenv("XDG_CACHE_HOME");
}

} // namespace
} // namespace vkpt::trade_study_test
