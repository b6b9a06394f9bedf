// study_data.cpp — the study's CSV and description files, written and read back.
#include "study/study_data.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.h"

namespace vkpt {

namespace {

const char* const kCsvHeader =
    "scene,family,label,reference,flags,adaptive_batch,adaptive_tolerance,setup_seconds,pass,"
    "render_seconds,cpu_seconds,wall_seconds,spp,samples_taken,active_pixels,rmse,rel_mse,"
    "mean_half_width,estimated_rel_mse,final,shared_with";

enum Column {
    kScene,
    kFamily,
    kLabel,
    kReference,
    kFlags,
    kBatch,
    kTolerance,
    kSetup,
    kPass,
    kRender,
    kCpu,
    kWall,
    kSpp,
    kSamples,
    kActive,
    kRmse,
    kRelMse,
    kHalfWidth,
    kEstimate,
    kFinal,
    kShared,
    kColumns
};

std::string number(double value) {
    if (!std::isfinite(value)) return "";
    char text[32];
    std::snprintf(text, sizeof(text), "%.9g", value);
    return text;
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

void writeRow(std::ostream& out, const StudySummary& summary, const RunResult& r,
              const ConvergencePoint& p, bool last) {
    const AdaptiveSettings& a = r.run.settings.adaptive;
    out << summary.name << "," << r.run.family << "," << quoted(r.run.label) << ","
        << referenceName(r.run.reference) << "," << quoted(r.run.flags) << ","
        << (a.enabled ? std::to_string(a.batchSize) : "") << ","
        << (a.enabled ? number(a.tolerance) : "") << "," << number(r.setupSeconds) << ","
        << p.figures.pass << "," << number(p.figures.renderSeconds) << ","
        << number(p.figures.cpuSeconds) << "," << number(p.figures.seconds) << ","
        << p.figures.samplesPerPixel << "," << p.figures.samplesTaken << ","
        << p.figures.activePixels << "," << number(p.rmse) << "," << number(p.relMse) << ","
        << number(p.meanHalfWidth) << "," << number(p.estimatedRelMse) << "," << (last ? 1 : 0)
        << "," << quoted(r.sharedWith) << "\n";
}

// Fields of one CSV line: commas separate, double quotes enclose, "" is a quote.
std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> fields(1);
    bool inQuotes = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (inQuotes && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
            fields.back() += '"', ++i;
        else if (c == '"')
            inQuotes = !inQuotes;
        else if (c == ',' && !inQuotes)
            fields.emplace_back();
        else
            fields.back() += c;
    }
    return fields;
}

double toDouble(const std::string& text) {
    if (text.empty()) return std::nan("");
    return std::stod(text);
}

ConvergencePoint pointFrom(const std::vector<std::string>& f) {
    ConvergencePoint p;
    p.figures.pass = std::uint32_t(std::stoul(f[kPass]));
    p.figures.renderSeconds = toDouble(f[kRender]);
    p.figures.cpuSeconds = toDouble(f[kCpu]);
    p.figures.seconds = toDouble(f[kWall]);
    p.figures.samplesPerPixel = std::uint32_t(std::stoul(f[kSpp]));
    p.figures.samplesTaken = std::stoull(f[kSamples]);
    p.figures.activePixels = std::uint32_t(std::stoul(f[kActive]));
    p.rmse = toDouble(f[kRmse]);
    p.relMse = toDouble(f[kRelMse]);
    p.meanHalfWidth = toDouble(f[kHalfWidth]);
    p.estimatedRelMse = toDouble(f[kEstimate]);
    return p;
}

RunResult runFrom(const std::vector<std::string>& f) {
    RunResult r;
    r.run.family = f[kFamily];
    r.run.label = f[kLabel];
    r.run.reference = f[kReference] == "direct" ? StudyReference::Direct : StudyReference::Full;
    r.run.flags = f[kFlags];
    r.run.settings.adaptive.enabled = !f[kBatch].empty();
    if (r.run.settings.adaptive.enabled) {
        r.run.settings.adaptive.batchSize = std::uint32_t(std::stoul(f[kBatch]));
        r.run.settings.adaptive.tolerance = float(std::stod(f[kTolerance]));
    }
    r.setupSeconds = toDouble(f[kSetup]);
    r.sharedWith = f[kShared];
    return r;
}

void readCsv(std::istream& csv, StudySummary& summary) {
    std::string line;
    if (!std::getline(csv, line) || line != kCsvHeader)
        throw InputError("study CSV: the first line is not vkpt-study's header");
    for (int number = 2; std::getline(csv, line); ++number) {
        const std::vector<std::string> f = splitCsv(line);
        if (f.size() != kColumns)
            throw InputError("study CSV, line " + std::to_string(number) + ": " +
                             std::to_string(f.size()) + " fields, expected " +
                             std::to_string(int(kColumns)));
        try {
            if (summary.results.empty() || summary.results.back().run.label != f[kLabel])
                summary.results.push_back(runFrom(f));
            summary.results.back().curve.push_back(pointFrom(f));
        } catch (const std::logic_error&) {
            throw InputError("study CSV, line " + std::to_string(number) + ": not a number");
        }
        summary.name = f[kScene];
    }
}

ReferenceInfo referenceFrom(std::istringstream& fields) {
    ReferenceInfo info;
    std::string kind;
    int cached = 0;
    fields >> kind >> info.spp >> info.maxDepth >> info.seconds >> info.estimatedRelMse >> cached;
    info.kind = kind == "direct" ? StudyReference::Direct : StudyReference::Full;
    info.cached = cached != 0;
    std::getline(fields >> std::ws, info.renderer);
    return info;
}

void readMeta(std::istream& meta, StudySummary& summary) {
    std::string line;
    while (std::getline(meta, line)) {
        std::istringstream fields(line);
        std::string key, rest;
        fields >> key;
        if (key == "reference") {
            summary.references.push_back(referenceFrom(fields));
            continue;
        }
        if (key == "size") fields >> summary.width >> summary.height;
        if (key == "studySeconds") fields >> summary.studySeconds;
        if (key == "clock")
            summary.clock = (fields >> rest, rest) == "cpu" ? StudyClock::Cpu : StudyClock::Wall;
        std::getline(fields >> std::ws, rest);
        if (key == "scene") summary.scene = rest;
        if (key == "machine") summary.machine = rest;
        if (key == "note") summary.note = rest;
    }
    if (summary.width == 0 || summary.references.empty())
        throw InputError("study description: no size or no reference line");
}

} // namespace

void writeStudyCsv(std::ostream& out, const StudySummary& summary) {
    out << kCsvHeader << "\n";
    for (const RunResult& r : summary.results)
        for (std::size_t i = 0; i < r.curve.size(); ++i)
            writeRow(out, summary, r, r.curve[i], i + 1 == r.curve.size());
}

void writeStudyMeta(std::ostream& out, const StudySummary& summary) {
    out << "scene " << summary.scene << "\nsize " << summary.width << " " << summary.height
        << "\nmachine " << summary.machine << "\nnote " << summary.note << "\nstudySeconds "
        << number(summary.studySeconds) << "\nclock " << clockName(summary.clock) << "\n";
    for (const ReferenceInfo& r : summary.references)
        out << "reference " << referenceName(r.kind) << " " << r.spp << " " << r.maxDepth << " "
            << number(r.seconds) << " " << number(r.estimatedRelMse) << " " << (r.cached ? 1 : 0)
            << " " << r.renderer << "\n";
}

StudySummary readStudySummary(std::istream& csv, std::istream& meta) {
    StudySummary summary;
    readCsv(csv, summary);
    readMeta(meta, summary);
    return summary;
}

} // namespace vkpt
