// study_runner.h — vkpt-study's executor: makes (or finds in the cache) the references, renders
// every run of the plan with the wavefront renderer while measuring its error after each pass,
// and writes the CSV, the table and the plots.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/render_settings.h"
#include "gpu/context.h"
#include "study/study_curves.h"
#include "study/study_plan.h"

namespace vkpt {

struct StudyInvocation {
    RenderSettings base; // scene, size, camera
    StudyScale scale;
    std::string name; // file names: <name>.csv, <name>.md, <name>.gp, <name>.svg, ...
    std::string outDir = ".";
    std::string cacheDir;              // empty: defaultCacheDirectory()
    std::string note;                  // a sentence for the table, e.g. about the machine's load
    std::vector<std::string> families; // empty: every strategy
    bool plot = true;                  // run gnuplot on the script
    bool referenceOnDevice = false;    // references with vkpt's renderer instead of vkpt-ref's
    bool freshReferences = false;      // remake references even when cached
    bool replot = false; // only redraw the table and plots from <name>.csv and <name>-meta.txt
    // Render only `families` and keep every other run from <name>.csv (same size and budgets).
    bool merge = false;
    // The time axis; unset: CPU time on a CPU device (lavapipe), wall time on a GPU.
    std::optional<StudyClock> clock;
    GpuOptions gpu;
    std::uint32_t pathSlots = 0;
};

// Throws InputError when gnuplot is wanted but not on PATH, before anything is rendered.
void checkPlotter(const StudyInvocation& invocation);

// Returns the process exit code (0, or 3 after validation messages).
int runStudy(const StudyInvocation& invocation);

} // namespace vkpt
