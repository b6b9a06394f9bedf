// study_output.cpp — the trade study's CSV, Markdown table and gnuplot script.
#include "study/study_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vkpt {

namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof(text), pattern, value);
    return text;
}

std::string seconds(double s) {
    if (!std::isfinite(s)) return "—";
    return s < 10.0 ? format("%.3g s", s) : format("%.0f s", s);
}

double pixels(const StudySummary& summary) {
    return double(summary.width) * summary.height;
}

double samplesPerPixel(const ConvergencePoint& point, const StudySummary& summary) {
    return double(point.figures.samplesTaken) / pixels(summary);
}

double pointSeconds(const ConvergencePoint& point, const StudySummary& summary) {
    return curveSeconds(point, summary.clock);
}

// "0.51 s (16 spp)", or "not reached" when the curve stays above the error.
std::string reachCell(const RunResult& r, const StudySummary& summary, double error) {
    const double t = timeToReach(r.curve, error, summary.clock);
    const double samples = samplesToReach(r.curve, error);
    if (!std::isfinite(t) || !std::isfinite(samples)) return "not reached";
    return seconds(t) + " (" + format("%.0f", samples / pixels(summary)) + " spp)";
}

std::string lastCell(const RunResult& r, const StudySummary& summary) {
    if (r.curve.empty()) return "—";
    const ConvergencePoint& last = r.curve.back();
    return format("%.0f spp, ", samplesPerPixel(last, summary)) +
           seconds(pointSeconds(last, summary)) + ", " + format("%.2e", last.relMse);
}

std::string strategyCell(const RunResult& r) {
    std::string cell = r.run.label;
    if (r.run.reference == StudyReference::Direct) cell += " (direct lighting)";
    if (r.run.label == "uniform" || r.run.label == "max depth 16" ||
        r.run.label == "roulette from 3")
        cell += r.run.family == "uniform" ? " (defaults)" : " (= uniform)";
    if (r.run.label == "specialised pipelines") cell += " (defaults, timed beside general)";
    return cell;
}

void writeHeadlineRows(std::ostream& out, const StudySummary& summary) {
    out << "| strategy | vkpt options | time to relMSE 1e-2 | time to relMSE 1e-3 | last point: "
           "samples/pixel, time, relMSE |\n|---|---|---|---|---|\n";
    for (const RunResult& r : summary.results)
        out << "| " << strategyCell(r) << " | `" << r.run.flags << "` | "
            << reachCell(r, summary, kHeadlineErrors[0]) << " | "
            << reachCell(r, summary, kHeadlineErrors[1]) << " | " << lastCell(r, summary) << " |\n";
}

double meanSetupSeconds(const StudySummary& summary) {
    double total = 0.0;
    int runs = 0;
    for (const RunResult& r : summary.results)
        if (r.sharedWith.empty()) total += r.setupSeconds, ++runs;
    return runs ? total / runs : 0.0;
}

// Where uniform and every adaptive run took identical samples (no adaptive pixel had stopped
// yet), their times differ by measurement noise alone: the largest such sample count and the
// range of the runs' times there.
struct TimingNoise {
    std::uint32_t spp = 0;
    double low = 0.0, high = 0.0;
    int runs = 0;
};

bool allPixelsActive(const ConvergencePoint& p, const StudySummary& summary) {
    return double(p.figures.activePixels) == pixels(summary);
}

const ConvergencePoint* pointAt(const RunResult& r, std::uint32_t spp,
                                const StudySummary& summary) {
    for (const ConvergencePoint& p : r.curve)
        if (p.figures.samplesPerPixel == spp && allPixelsActive(p, summary)) return &p;
    return nullptr;
}

TimingNoise timingNoise(const StudySummary& summary) {
    TimingNoise noise;
    for (const RunResult& uniform : summary.results) {
        if (uniform.run.family != "uniform") continue;
        for (const ConvergencePoint& u : uniform.curve) {
            std::vector<double> times{pointSeconds(u, summary)};
            for (const RunResult& r : summary.results)
                if (r.run.family == "adaptive") {
                    const ConvergencePoint* p = pointAt(r, u.figures.samplesPerPixel, summary);
                    times.push_back(p ? pointSeconds(*p, summary) : std::nan(""));
                }
            if (times.size() < 2 ||
                std::any_of(times.begin(), times.end(), [](double t) { return !std::isfinite(t); }))
                continue;
            noise.spp = u.figures.samplesPerPixel;
            noise.low = *std::min_element(times.begin(), times.end());
            noise.high = *std::max_element(times.begin(), times.end());
            noise.runs = int(times.size());
        }
    }
    return noise;
}

void writeTimingNoise(std::ostream& out, const StudySummary& summary) {
    const TimingNoise noise = timingNoise(summary);
    if (noise.runs < 2) return;
    out << "\nTiming noise: at " << noise.spp << " spp, before any adaptive pixel had stopped, "
        << "the " << noise.runs << " uniform and adaptive runs had taken identical samples in "
        << seconds(noise.low) << " to " << seconds(noise.high)
        << format(" (±%.0f %% of their middle)",
                  100.0 * (noise.high - noise.low) / (noise.high + noise.low))
        << "; time ratios closer to 1 than that are not a measured difference.\n";
}

void writeSpeedup(std::ostream& out, const StudySummary& summary, const AdaptiveSpeedup& s) {
    const double spp = pixels(summary);
    if (std::abs(s.inSamples() - 1.0) < 0.005) {
        out << "1.00× — reached before any adaptive pixel stopped (" << s.fewestSamplesLabel << ": "
            << format("%.0f", s.adaptiveSamples / spp)
            << " samples/pixel, as uniform), so adaptive sampling is uniform sampling here; the "
            << format("%.2f×", s.inTime()) << " in " << clockName(summary.clock)
            << " time is timing noise\n";
        return;
    }
    out << format("**%.2f×** in ", s.inTime()) << clockName(summary.clock) << " time ("
        << s.fastestLabel << ": " << seconds(s.adaptiveSeconds) << " against "
        << seconds(s.uniformSeconds) << "); " << format("%.2f×", s.inSamples()) << " in samples ("
        << s.fewestSamplesLabel << ": " << format("%.0f", s.adaptiveSamples / spp) << " against "
        << format("%.0f", s.uniformSamples / spp) << " samples/pixel)\n";
}

bool hasFamily(const StudySummary& summary, const std::string& family) {
    return std::any_of(summary.results.begin(), summary.results.end(),
                       [&](const RunResult& r) { return r.run.family == family; });
}

void writeSpeedups(std::ostream& out, const StudySummary& summary) {
    if (!hasFamily(summary, "uniform") || !hasFamily(summary, "adaptive")) return; // --only
    out << "\nSpeedup of adaptive over uniform sampling at equal error, with the best adaptive "
           "setting for each (in time, and in samples taken, which no machine load disturbs):"
           "\n\n";
    for (double error : kHeadlineErrors) {
        const AdaptiveSpeedup s = adaptiveSpeedup(summary.results, error, summary.clock);
        out << "- relMSE " << format("%.0e", error) << ": ";
        if (std::isfinite(s.inTime()) && std::isfinite(s.inSamples()))
            writeSpeedup(out, summary, s);
        else
            out << "not measured: "
                << (std::isfinite(s.uniformSeconds) ? "no adaptive setting reached it"
                                                    : "uniform sampling did not reach it")
                << " within the budget\n";
    }
}

const RunResult* findRun(const StudySummary& summary, const std::string& label) {
    for (const RunResult& r : summary.results)
        if (r.run.label == label) return &r;
    return nullptr;
}

// "**1.04×** (1.3 s against 1.25 s)": general over specialised time, or why there is none.
std::string timeRatio(double general, double specialised) {
    if (!std::isfinite(general) || !std::isfinite(specialised) || specialised <= 0.0)
        return "not measured: not reached within the budget";
    return format("**%.2f×** (", general / specialised) + seconds(general) + " against " +
           seconds(specialised) + ")";
}

void writePipelineComparison(std::ostream& out, const StudySummary& summary) {
    const RunResult* specialised = findRun(summary, "specialised pipelines");
    const RunResult* general = findRun(summary, "general pipelines");
    if (!specialised || !general || specialised->curve.empty() || general->curve.empty()) return;
    out << "\nGeneral over specialised pipelines (`--general` against the default; the same "
           "samples, rendered one after the other), the general run's "
        << clockName(summary.clock) << " time as a multiple of the specialised run's:\n\n";
    for (double error : kHeadlineErrors)
        out << "- to relMSE " << format("%.0e", error) << ": "
            << timeRatio(timeToReach(general->curve, error, summary.clock),
                         timeToReach(specialised->curve, error, summary.clock))
            << "\n";
    const ConvergencePoint &g = general->curve.back(), &s = specialised->curve.back();
    out << "- the whole budget, " << format("%.0f", samplesPerPixel(g, summary))
        << " samples/pixel: " << timeRatio(pointSeconds(g, summary), pointSeconds(s, summary))
        << "\n- set-up before the first pass (upload and pipeline creation, wall time): "
        << seconds(general->setupSeconds) << " against " << seconds(specialised->setupSeconds)
        << "\n";
}

std::string timeDefinition(const StudySummary& summary) {
    const std::string span = "from the first pass, without the device set-up (" +
                             seconds(meanSetupSeconds(summary)) +
                             " of wall time per run on average) and without the time spent "
                             "measuring after each pass";
    if (summary.clock == StudyClock::Wall) return "Time: wall-clock render time " + span + ".";
    return "Time: the CPU time of the render process, all threads, " + span +
           " — on a CPU device such as lavapipe this is the render's cost, which other work on "
           "a shared machine does not inflate as it does wall time; divide by the device's "
           "threads for the wall time on an idle machine (the CSV has both).";
}

void writeReferences(std::ostream& out, const StudySummary& summary) {
    out << "\n| reference | made by | samples/pixel | max depth | seed | time | its own "
           "estimated relMSE |\n|---|---|---|---|---|---|---|\n";
    for (const ReferenceInfo& r : summary.references)
        out << "| " << (r.kind == StudyReference::Full ? "full (path tracer)" : "direct lighting")
            << " | " << r.renderer << " | " << r.spp << " | "
            << (r.kind == StudyReference::Full ? std::to_string(r.maxDepth) : "1") << " | "
            << kReferenceSeed << " | " << seconds(r.seconds) << (r.cached ? " (cached)" : "")
            << " | " << format("%.2e", r.estimatedRelMse) << " |\n";
}

// ---- gnuplot ----

std::string blockName(std::size_t index) {
    return "$run" + std::to_string(index);
}

void writeCurveBlock(std::ostream& out, const std::string& name,
                     const std::vector<ConvergencePoint>& curve, StudyClock clock) {
    out << name << " << EOD\n";
    for (const ConvergencePoint& p : curve)
        if (std::isfinite(p.relMse) && curveSeconds(p, clock) > 0.0)
            out << format("%.6g", curveSeconds(p, clock)) << " " << format("%.6g", p.relMse)
                << "\n";
    out << "EOD\n";
}

// Each adaptive batch size's last points across its tolerances, labelled with the tolerance.
void writeAdaptiveFronts(std::ostream& out, const StudySummary& summary,
                         std::vector<std::string>& fronts) {
    std::vector<std::uint32_t> batches;
    for (const RunResult& r : summary.results)
        if (r.run.family == "adaptive" && !r.curve.empty()) {
            const std::uint32_t b = r.run.settings.adaptive.batchSize;
            if (std::find(batches.begin(), batches.end(), b) == batches.end()) batches.push_back(b);
        }
    for (std::uint32_t b : batches) {
        const std::string name = "$adaptive" + std::to_string(b);
        out << name << " << EOD\n";
        for (const RunResult& r : summary.results)
            if (r.run.family == "adaptive" && r.run.settings.adaptive.batchSize == b &&
                !r.curve.empty() && std::isfinite(r.curve.back().relMse))
                out << format("%.6g", pointSeconds(r.curve.back(), summary)) << " "
                    << format("%.6g", r.curve.back().relMse) << " \""
                    << format("%g", r.run.settings.adaptive.tolerance) << "\"\n";
        out << "EOD\n";
        fronts.push_back(std::to_string(b));
    }
}

// The uniform curve's first points at or past 4, 16, 64, ... samples per pixel, labelled with
// their count (passes need not end on a power of 4).
void writeUniformMarks(std::ostream& out, const StudySummary& summary) {
    out << "$uniformMarks << EOD\n";
    for (const RunResult& r : summary.results) {
        if (r.run.family != "uniform") continue;
        std::uint64_t next = 4;
        for (const ConvergencePoint& p : r.curve) {
            const std::uint32_t n = p.figures.samplesPerPixel;
            if (n < next || !std::isfinite(p.relMse)) continue;
            out << format("%.6g", pointSeconds(p, summary)) << " " << format("%.6g", p.relMse)
                << " \"" << n << " spp\"\n";
            while (next <= n)
                next *= 4;
        }
    }
    out << "EOD\n";
}

void writeCommonSettings(std::ostream& out, const StudySummary& summary) {
    out << "set logscale xy\nset format y '10^{%L}'\nset grid xtics ytics mxtics mytics lc "
           "rgb '#dddddd'\nset key top right font ',10'\n"
           "set ylabel 'relMSE'\nset xlabel '"
        << (summary.clock == StudyClock::Wall ? "render time [s]"
                                              : "CPU time of the render, all threads [s]")
        << "'\n";
    for (double e : kHeadlineErrors)
        out << "set arrow from graph 0, first " << e << " to graph 1, first " << e
            << " nohead dt 2 lc rgb '#888888'\n";
}

double referenceFloor(const StudySummary& summary, StudyReference kind) {
    for (const ReferenceInfo& r : summary.references)
        if (r.kind == kind) return r.estimatedRelMse;
    return 0.0;
}

// Plot clauses for every run of the families (names separated by spaces), one line each.
std::string familyCurves(const StudySummary& summary, const std::string& families) {
    std::string clauses;
    for (std::size_t i = 0; i < summary.results.size(); ++i) {
        const RunResult& r = summary.results[i];
        if ((" " + families + " ").find(" " + r.run.family + " ") == std::string::npos) continue;
        if (!clauses.empty()) clauses += ", \\\n     ";
        clauses += blockName(i) + " using 1:2 with lines lw 2 title '" + r.run.label + "'";
    }
    return clauses;
}

// The dotted line of the reference's own noise; none when the study has no such reference.
std::vector<std::string> floorClause(const StudySummary& summary, StudyReference kind) {
    const double floor = referenceFloor(summary, kind);
    if (floor <= 0.0) return {};
    return {format("%.6g", floor) +
            " with lines dt 3 lc rgb '#555555' title \"reference's own noise\""};
}

// One plot command of the clauses; a study of a few strategies (--only) may have none for a
// panel, which then stays blank.
void writePlot(std::ostream& out, const std::vector<std::string>& clauses, bool inMultiplot) {
    if (clauses.empty()) {
        if (inMultiplot) out << "set multiplot next\n";
        return;
    }
    out << "plot ";
    for (std::size_t i = 0; i < clauses.size(); ++i)
        out << (i ? ", \\\n     " : "") << clauses[i];
    out << "\n";
}

void writeHeadlinePlot(std::ostream& out, const StudySummary& summary,
                       const std::vector<std::string>& fronts) {
    out << "set title '" << summary.name << " (" << summary.width << "x" << summary.height
        << "): uniform against adaptive sampling'\n";
    std::vector<std::string> clauses;
    if (const std::string uniform = familyCurves(summary, "uniform"); !uniform.empty()) {
        clauses.push_back(uniform);
        clauses.push_back(
            "$uniformMarks using 1:2:3 with labels offset char -1.2,-0.8 font ',8' notitle");
    }
    for (std::size_t i = 0; i < fronts.size(); ++i) {
        const std::string& b = fronts[i];
        clauses.push_back("$adaptive" + b + " using 1:2 with linespoints lw 2 pt 7 title " +
                          "'adaptive, batch " + b + " (label: tolerance)'");
        clauses.push_back("$adaptive" + b + " using 1:2:3 with labels offset char " +
                          (i % 2 ? "1.5,-0.7" : "-1.5,0.8") + " font ',8' notitle");
    }
    if (!clauses.empty())
        for (std::string& floor : floorClause(summary, StudyReference::Full))
            clauses.push_back(floor);
    writePlot(out, clauses, false);
}

void writeOverviewPanel(std::ostream& out, const StudySummary& summary, const std::string& title,
                        const std::string& families, StudyReference reference) {
    out << "set title '" << title << "'\n";
    const std::string curves = familyCurves(summary, families);
    std::vector<std::string> clauses;
    if (!curves.empty()) {
        clauses.push_back(curves);
        for (std::string& floor : floorClause(summary, reference))
            clauses.push_back(floor);
    }
    writePlot(out, clauses, true);
}

} // namespace

void writeStudyTable(std::ostream& out, const StudySummary& summary, const std::string& plotFile,
                     const std::string& headlineFile) {
    out << "# Speed against accuracy: " << summary.name << "\n\n";
    out << "Scene `" << summary.scene << "`, " << summary.width << "×" << summary.height
        << " pixels. Machine: " << summary.machine << ".";
    if (!summary.note.empty()) out << " " << summary.note;
    out << "\n\nError: relMSE = mean over pixels and channels of (x − r)² / (r² + 0.01) against "
           "the reference r below (see `docs/trade/README.md`). "
        << timeDefinition(summary)
        << " Samples/pixel: samples taken over the image's pixels; below `--adaptive-min` (64) "
           "adaptive sampling takes exactly uniform sampling's samples, so any difference in "
           "time there is measurement noise.\n\n";
    out << "![" << summary.name << ": uniform against adaptive sampling](" << headlineFile
        << ")\n\n";
    writeHeadlineRows(out, summary);
    writeSpeedups(out, summary);
    writeTimingNoise(out, summary);
    writePipelineComparison(out, summary);
    writeReferences(out, summary);
    out << "\nAll strategies: ![" << summary.name << ": every strategy](" << plotFile << ")\n\n";
    out << "The study took " << seconds(summary.studySeconds)
        << " of wall time, references included; every curve point is in `" << summary.name
        << ".csv`.\n";
}

void writeGnuplotScript(std::ostream& out, const StudySummary& summary,
                        const std::string& headlineSvg, const std::string& overviewSvg) {
    out << "# " << summary.name << ": error against render time, written by vkpt-study.\n"
        << "# Data inline; `gnuplot " << summary.name << ".gp` redraws " << headlineSvg << " and "
        << overviewSvg << ".\n";
    for (std::size_t i = 0; i < summary.results.size(); ++i)
        writeCurveBlock(out, blockName(i), summary.results[i].curve, summary.clock);
    std::vector<std::string> fronts;
    writeAdaptiveFronts(out, summary, fronts);
    writeUniformMarks(out, summary);
    out << "set terminal svg size 900,640 dynamic enhanced font 'sans,12' background rgb "
           "'white'\nset output '"
        << headlineSvg << "'\n";
    writeCommonSettings(out, summary);
    writeHeadlinePlot(out, summary, fronts);
    out << "unset output\nset terminal svg size 1400,1500 dynamic enhanced font 'sans,12' "
           "background rgb 'white'\nset output '"
        << overviewSvg << "'\nset multiplot layout 3,2 title '" << summary.name
        << ": relMSE against time'\n";
    writeOverviewPanel(out, summary, "uniform and adaptive sampling", "uniform adaptive",
                       StudyReference::Full);
    writeOverviewPanel(out, summary, "direct lighting: light against hemisphere sampling",
                       "sampling", StudyReference::Direct);
    writeOverviewPanel(out, summary, "maximum depth (bias: fewer bounces, less light)", "depth",
                       StudyReference::Full);
    writeOverviewPanel(out, summary, "Russian roulette (max depth 16)", "roulette",
                       StudyReference::Full);
    writeOverviewPanel(out, summary, "pipelines specialised to the scene against general ones",
                       "pipeline", StudyReference::Full);
    out << "unset multiplot\nunset output\n";
}

} // namespace vkpt
