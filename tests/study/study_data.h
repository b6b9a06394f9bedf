// study_data.h — the trade study's measurements on disk: every curve point as CSV (the data
// behind the plots, for any other tool too) and a small description of the study
// (<name>-meta.txt: scene, size, machine, references), which together let vkpt-study --replot
// redraw the table and plots without rendering again.
#pragma once

#include <istream>
#include <ostream>

#include "study/study_output.h"

namespace vkpt {

// One row per curve point, after a header: scene, family, label, reference, flags,
// adaptive_batch, adaptive_tolerance (empty unless adaptive), setup_seconds, pass,
// render_seconds, cpu_seconds, wall_seconds, spp, samples_taken, active_pixels, rmse, rel_mse,
// mean_half_width, estimated_rel_mse, final (1 on a run's last point), shared_with.
void writeStudyCsv(std::ostream& out, const StudySummary& summary);

// Everything of the summary but the runs, one "key value" line each.
void writeStudyMeta(std::ostream& out, const StudySummary& summary);

// The summary the two files describe. The runs get their family, label, flags, reference,
// adaptive settings and curves back (the rest of their settings is not needed to report
// them). Throws InputError naming the line that cannot be read.
StudySummary readStudySummary(std::istream& csv, std::istream& meta);

} // namespace vkpt
