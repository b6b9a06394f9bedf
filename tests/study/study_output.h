// study_output.h — the trade study's results and how they are shown: the headline table as
// Markdown and a gnuplot script (data inline) that draws the log–log plots as SVG.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "study/study_curves.h"

namespace vkpt {

// How a reference was made, for the table and the plot.
struct ReferenceInfo {
    StudyReference kind = StudyReference::Full;
    std::string renderer; // "vkpt-ref (CPU, 2 threads)" or the device
    std::uint32_t spp = 0;
    std::uint32_t maxDepth = 0;
    double seconds = 0.0;         // to make it (0 when it came from the cache)
    double estimatedRelMse = 0.0; // its own noise, from its variances: the floor of every curve
    bool cached = false;
    std::string path;
};

struct StudySummary {
    std::string name;  // "cornell-box"
    std::string scene; // the scene file
    std::uint32_t width = 0, height = 0;
    std::string machine; // CPU and device, as the study saw them
    std::string note;    // --note: e.g. "the machine was shared with a build"
    std::vector<ReferenceInfo> references;
    std::vector<RunResult> results;
    double studySeconds = 0.0;           // wall time of the whole study, references included
    StudyClock clock = StudyClock::Wall; // the time axis of the table and plots
};

// The headline: time to relMSE 1e-2 and 1e-3 per strategy, adaptive's speedup over uniform at
// equal error, the general pipelines' cost over the specialised ones, the references and the
// machine.
void writeStudyTable(std::ostream& out, const StudySummary& summary, const std::string& plotFile,
                     const std::string& headlineFile);

// A gnuplot script that writes `headlineSvg` (uniform vs adaptive) and `overviewSvg` (five
// panels: sampling, light vs hemisphere, depth, roulette, pipelines); the data are inline, so
// the script alone redraws the plots.
void writeGnuplotScript(std::ostream& out, const StudySummary& summary,
                        const std::string& headlineSvg, const std::string& overviewSvg);

} // namespace vkpt
