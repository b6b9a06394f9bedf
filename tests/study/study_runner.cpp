// study_runner.cpp — references, runs and outputs of the trade study.
#include "study/study_runner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/scene_setup.h"
#include "common/errors.h"
#include "common/progress.h"
#include "gpu/device_list.h"
#include "image/error_metrics.h"
#include "reference/reference_renderer.h"
#include "render/wavefront.h"
#include "study/reference_cache.h"
#include "study/study_data.h"
#include "study/study_output.h"

extern char** environ;

namespace vkpt {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
const char* const kProgram = "vkpt-study";

std::string formatRelMse(double relMse) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3e", relMse);
    return text;
}

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string findOnPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::string directories = path ? path : "";
    std::size_t begin = 0;
    while (begin <= directories.size()) {
        std::size_t end = directories.find(':', begin);
        if (end == std::string::npos) end = directories.size();
        const fs::path candidate = fs::path(directories.substr(begin, end - begin)) / program;
        if (end > begin && access(candidate.c_str(), X_OK) == 0) return candidate.string();
        begin = end + 1;
    }
    return {};
}

// "Intel(R) Xeon(R) ... (2 cores); llvmpipe (LLVM 15.0.6, 256 bits) (CPU, Vulkan 1.3.230, ...)"
std::string describeMachine(const GpuContext& context) {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, cpu = "unknown CPU";
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    std::string device = describeDevice(context.deviceInfo());
    if (device.find(": ") != std::string::npos) device = device.substr(device.find(": ") + 2);
    std::string machine = cpu + " (" + std::to_string(std::thread::hardware_concurrency()) +
                          " hardware threads); device " + device;
    if (const char* threads = std::getenv("LP_NUM_THREADS"))
        machine += ", LP_NUM_THREADS=" + std::string(threads);
    return machine;
}

// The 1-minute load average, to say how busy the machine was while the study timed renders.
std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string first;
    in >> first;
    return first.empty() ? "?" : first;
}

bool wanted(const StudyInvocation& invocation, const std::string& family) {
    if (invocation.families.empty()) return true;
    for (const std::string& f : invocation.families)
        if (f == family) return true;
    return false;
}

// Adds a reference to the summary's list, or replaces the one of its kind that --merge read.
void addReference(std::vector<ReferenceInfo>& references, const ReferenceInfo& info) {
    for (ReferenceInfo& r : references)
        if (r.kind == info.kind) {
            r = info;
            return;
        }
    references.push_back(info);
}

class StudyRunner {
public:
    explicit StudyRunner(const StudyInvocation& invocation)
        : invocation_(invocation), context_(invocation.gpu),
          setup_(setUpScene(invocation.base, kProgram)) {}

    int run();

private:
    const Image& reference(StudyReference kind);
    RenderOutput renderReferenceImage(const RenderSettings& settings, ReferenceInfo& info);
    const SceneSetup& setupFor(const RenderSettings& settings);
    RunResult measure(const StudyRun& run, const std::string& progressLabel);
    const RunResult* sharableRun(const StudyRun& run) const;
    void renderPlan(const StudySummary& earlier);
    void composeNote(const StudySummary& earlier, const std::string& loadAtStart);

    const StudyInvocation& invocation_;
    GpuContext context_;
    SceneSetup setup_;
    std::optional<SceneSetup> generalSetup_; // --general's layout, made for the first such run
    Image references_[2];
    bool haveReference_[2] = {false, false};
    StudySummary summary_;
};

RenderOutput StudyRunner::renderReferenceImage(const RenderSettings& settings,
                                               ReferenceInfo& info) {
    const Clock::time_point start = Clock::now();
    RenderOutput output;
    if (invocation_.referenceOnDevice) {
        WavefrontOptions options;
        options.slotCount = invocation_.pathSlots;
        output =
            renderWavefront(context_, setup_.prepared, setup_.camera, settings, options).output;
        info.renderer = "vkpt (" + context_.deviceInfo().name + ")";
    } else {
        RenderStats stats;
        output = renderReference(setup_.prepared, setup_.camera, settings, stats);
        info.renderer =
            "vkpt-ref (CPU, " + std::to_string(std::thread::hardware_concurrency()) + " threads)";
    }
    info.seconds = secondsSince(start);
    return output;
}

const Image& StudyRunner::reference(StudyReference kind) {
    const int slot = kind == StudyReference::Full ? 0 : 1;
    if (haveReference_[slot]) return references_[slot];
    RenderSettings settings = referenceSettings(invocation_.base, invocation_.scale, kind);
    settings.quiet = false; // minutes at full scale: show progress
    const std::string cacheDir =
        invocation_.cacheDir.empty() ? defaultCacheDirectory() : invocation_.cacheDir;
    const std::string path = referenceCachePath(cacheDir, settings, kind);
    std::optional<CachedReference> cached;
    if (!invocation_.freshReferences) cached = readCachedReference(path);
    if (!cached) {
        std::fprintf(stderr, "%s: making the %s reference, %u spp: %s\n", kProgram,
                     referenceName(kind), settings.samplesPerPixel, path.c_str());
        cached.emplace();
        RenderOutput output = renderReferenceImage(settings, cached->info);
        cached->image = output.image;
        cached->info.spp = settings.samplesPerPixel;
        cached->info.maxDepth = settings.maxDepth;
        cached->info.estimatedRelMse = estimateFromVariance(output).estimatedRelMse;
        writeCachedReference(path, cached->image, cached->info);
        cached->info.path = path;
    } else {
        std::fprintf(stderr, "%s: %s reference from the cache: %s\n", kProgram, referenceName(kind),
                     path.c_str());
    }
    cached->info.kind = kind;
    addReference(summary_.references, cached->info);
    references_[slot] = std::move(cached->image);
    haveReference_[slot] = true;
    return references_[slot];
}

// The scene laid out as the run's pipelines expect it: specialised to its features, or for
// all of them (--general).
const SceneSetup& StudyRunner::setupFor(const RenderSettings& settings) {
    if (!settings.general) return setup_;
    if (!generalSetup_) {
        std::fprintf(stderr, "%s: the scene again, laid out for every feature (--general)\n",
                     kProgram);
        RenderSettings general = invocation_.base;
        general.general = true;
        generalSetup_ = setUpScene(general, kProgram);
    }
    return *generalSetup_;
}

// An earlier run that traced the same samples with at least this budget: its curve's first
// part is this run's curve.
const RunResult* StudyRunner::sharableRun(const StudyRun& run) const {
    if (!run.shareable) return nullptr;
    for (const RunResult& r : summary_.results)
        if (r.sharedWith.empty() && r.run.shareable &&
            sameSamplesExceptBudget(r.run.settings, run.settings) &&
            r.run.settings.samplesPerPixel >= run.settings.samplesPerPixel &&
            r.run.reference == run.reference)
            return &r;
    return nullptr;
}

// A run read off the curve of the run sharableRun found.
RunResult readOff(const StudyRun& run, const RunResult& lender) {
    RunResult result;
    result.run = run;
    result.curve = curvePrefix(lender.curve, run.settings.samplesPerPixel);
    result.sharedWith = lender.run.label;
    return result;
}

// Renders one run, measuring its error after every pass. A full-scale run takes minutes on
// lavapipe, so it shows its progress in samples out of its budget (adaptive runs end early).
RunResult StudyRunner::measure(const StudyRun& run, const std::string& progressLabel) {
    if (const RunResult* lender = sharableRun(run)) return readOff(run, *lender);
    RunResult result;
    result.run = run;
    ConvergenceTracker tracker(&reference(run.reference), 0.0);
    const std::uint64_t budget =
        std::uint64_t(run.settings.samplesPerPixel) * run.settings.width * run.settings.height;
    ProgressBar progressBar(progressLabel, budget);
    WavefrontOptions options;
    options.slotCount = invocation_.pathSlots;
    options.readPixelsAfterPass = true;
    options.afterPass = [&tracker, &progressBar](const PassFigures& figures,
                                                 const RenderOutput* output) {
        tracker.record(figures, output);
        progressBar.setStatus("relMSE " + formatRelMse(tracker.curve().back().relMse));
        progressBar.advance(figures.samplesTaken - progressBar.done());
        return false;
    };
    const SceneSetup& setup = setupFor(run.settings);
    const Clock::time_point start = Clock::now();
    const WavefrontResult rendered =
        renderWavefront(context_, setup.prepared, setup.camera, run.settings, options);
    progressBar.finish();
    result.setupSeconds = secondsSince(start) - rendered.stats.seconds;
    result.curve = tracker.curve();
    if (rendered.truncatedTraversals > 0)
        throw InternalError(run.label + ": BVH traversals were cut short by the driver");
    return result;
}

void reportRun(const RunResult& r, std::size_t index, std::size_t count) {
    std::fprintf(stderr, "%s: [%zu/%zu] %s: ", kProgram, index + 1, count, r.run.label.c_str());
    if (r.curve.empty()) {
        std::fprintf(stderr, "no passes\n");
        return;
    }
    const ConvergencePoint& last = r.curve.back();
    if (!r.sharedWith.empty()) std::fprintf(stderr, "the start of '%s', ", r.sharedWith.c_str());
    std::fprintf(stderr, "%.3f s render, %.3f s CPU (+%.3f s set-up), %u passes, relMSE %.3e\n",
                 last.figures.renderSeconds, last.figures.cpuSeconds, r.setupSeconds,
                 last.figures.pass, last.relMse);
}

void runGnuplot(const std::string& directory, const std::string& script) {
    const std::string gnuplot = findOnPath("gnuplot");
    const std::string cd = "cd '" + directory + "'";
    std::vector<std::string> arguments{gnuplot, "-e", cd, script};
    std::vector<char*> argv;
    for (std::string& a : arguments)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    if (posix_spawn(&pid, gnuplot.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
        throw InputError("cannot start " + gnuplot);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw InternalError("gnuplot failed on " + script + " (see its messages above)");
}

template <typename Write> void writeFile(const fs::path& path, Write write) {
    std::ofstream out(path);
    write(out);
    if (!out) throw InputError(path.string() + ": cannot write");
}

// <name>.csv and <name>-meta.txt: the measurements, from which --replot redraws the rest.
void writeData(const fs::path& dir, const StudySummary& summary) {
    fs::create_directories(dir);
    writeFile(dir / (summary.name + ".csv"),
              [&](std::ostream& out) { writeStudyCsv(out, summary); });
    writeFile(dir / (summary.name + "-meta.txt"),
              [&](std::ostream& out) { writeStudyMeta(out, summary); });
}

// <name>.md, <name>.gp and, with gnuplot, <name>-headline.svg and <name>.svg.
void writeReport(const StudyInvocation& invocation, const StudySummary& summary) {
    const fs::path dir = invocation.outDir;
    const std::string name = summary.name;
    const std::string headline = name + "-headline.svg", overview = name + ".svg";
    writeFile(dir / (name + ".md"),
              [&](std::ostream& out) { writeStudyTable(out, summary, overview, headline); });
    const fs::path script = dir / (name + ".gp");
    writeFile(script,
              [&](std::ostream& out) { writeGnuplotScript(out, summary, headline, overview); });
    if (invocation.plot) runGnuplot(fs::absolute(dir).string(), fs::absolute(script).string());
    std::fprintf(stderr, "%s: wrote %s/%s.{csv,md,gp}%s\n", kProgram, dir.string().c_str(),
                 name.c_str(), invocation.plot ? " and the plots (.svg)" : "");
}

StudySummary readSummary(const StudyInvocation& invocation) {
    const fs::path dir = invocation.outDir;
    std::ifstream csv(dir / (invocation.name + ".csv"));
    std::ifstream meta(dir / (invocation.name + "-meta.txt"));
    if (!csv || !meta)
        throw InputError((dir / invocation.name).string() +
                         ".csv and -meta.txt: cannot read (--replot and --merge need an earlier "
                         "study)");
    return readStudySummary(csv, meta);
}

// --merge: the earlier study that the runs not rendered now are kept from, made at this size.
StudySummary readEarlierStudy(const StudyInvocation& invocation) {
    if (!invocation.merge) return {};
    StudySummary earlier = readSummary(invocation);
    if (earlier.width != invocation.base.width || earlier.height != invocation.base.height)
        throw InputError(
            invocation.name + ".csv: made at " + std::to_string(earlier.width) + "x" +
            std::to_string(earlier.height) + ", not " + std::to_string(invocation.base.width) +
            "x" + std::to_string(invocation.base.height) + " (--merge needs the same --res)");
    return earlier;
}

// The earlier study's result of a planned run, with the plan's settings (the CSV keeps only
// what the report needs, and sharing compares settings); none when it has no such run.
std::optional<RunResult> keptRun(const StudySummary& earlier, const StudyRun& run) {
    for (const RunResult& r : earlier.results)
        if (r.run.label == run.label) {
            if (r.run.flags != run.flags)
                throw InputError(earlier.name + ".csv: run '" + run.label + "' was made with '" +
                                 r.run.flags + "', this study's plan has '" + run.flags +
                                 "' (--merge needs the same --spp and --side-spp)");
            RunResult kept = r;
            kept.run = run;
            return kept;
        }
    return std::nullopt;
}

// Renders the wanted runs in the plan's order; with --merge, keeps the others from `earlier`.
void StudyRunner::renderPlan(const StudySummary& earlier) {
    const std::vector<StudyRun> plan = planStudy(invocation_.base, invocation_.scale);
    const std::size_t count =
        std::size_t(std::count_if(plan.begin(), plan.end(), [&](const StudyRun& r) {
            return wanted(invocation_, r.family);
        }));
    std::size_t rendered = 0;
    for (const StudyRun& run : plan) {
        if (wanted(invocation_, run.family)) {
            const std::string label = std::string(kProgram) + ": [" + std::to_string(rendered + 1) +
                                      "/" + std::to_string(count) + "] " + run.label;
            summary_.results.push_back(measure(run, label));
            reportRun(summary_.results.back(), rendered++, count);
        } else if (std::optional<RunResult> kept = keptRun(earlier, run)) {
            // A kept run that was read off another's curve follows it, should that one have
            // been rendered again.
            const RunResult* lender = sharableRun(run);
            summary_.results.push_back(lender ? readOff(run, *lender) : std::move(*kept));
        }
    }
}

// The table's note: --note and the machine's load while this study ran; after --merge, the
// earlier study's note first, and which runs this one rendered.
void StudyRunner::composeNote(const StudySummary& earlier, const std::string& loadAtStart) {
    std::string note = earlier.note;
    const auto add = [&note](const std::string& sentence) {
        if (!sentence.empty()) note += (note.empty() ? "" : " ") + sentence;
    };
    if (invocation_.merge) {
        add("The " + familyList(invocation_.families) +
            " runs were rendered later and merged into this study (--merge).");
        if (earlier.machine != summary_.machine)
            add("The earlier runs' machine: " + earlier.machine + ".");
    }
    add(invocation_.note);
    add("Load average (1 min, /proc/loadavg)" +
        std::string(invocation_.merge ? " while they ran: " : ": ") + loadAtStart +
        " at the start, " + loadAverage() + " at the end.");
    summary_.note = note;
}

int StudyRunner::run() {
    const Clock::time_point start = Clock::now();
    summary_.name = invocation_.name;
    summary_.scene = invocation_.base.scenePath;
    summary_.width = invocation_.base.width;
    summary_.height = invocation_.base.height;
    summary_.machine = describeMachine(context_);
    summary_.clock = invocation_.clock.value_or(
        context_.deviceInfo().type == VK_PHYSICAL_DEVICE_TYPE_CPU ? StudyClock::Cpu
                                                                  : StudyClock::Wall);
    const std::string loadAtStart = loadAverage();
    const StudySummary earlier = readEarlierStudy(invocation_);
    summary_.references = earlier.references;
    renderPlan(earlier);
    summary_.studySeconds = earlier.studySeconds + secondsSince(start);
    composeNote(earlier, loadAtStart);
    writeData(invocation_.outDir, summary_);
    writeReport(invocation_, summary_);
    if (context_.validationMessageCount() > 0)
        throw InternalError("the validation layer reported " +
                            std::to_string(context_.validationMessageCount()) + " messages");
    return 0;
}

} // namespace

void checkPlotter(const StudyInvocation& invocation) {
    if (invocation.plot && findOnPath("gnuplot").empty())
        throw InputError("gnuplot is not on PATH: install it (Debian: apt-get install "
                         "gnuplot-nox; bash ci/install_deps.sh does) or pass --no-plot");
}

int runStudy(const StudyInvocation& invocation) {
    checkPlotter(invocation);
    if (invocation.replot) {
        StudySummary summary = readSummary(invocation);
        if (invocation.clock) summary.clock = *invocation.clock;
        writeReport(invocation, summary);
        return 0;
    }
    StudyRunner runner(invocation);
    return runner.run();
}

} // namespace vkpt
