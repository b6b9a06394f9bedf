// pass_figures.h — the wavefront's PassProgress as the convergence tracker's PassFigures:
// the curve's render time leaves out the readbacks and measurements made for the curve itself.
#pragma once

#include "convergence/convergence.h"
#include "render/wavefront.h"

namespace vkpt {

inline PassFigures passFigures(const PassProgress& progress) {
    PassFigures figures;
    figures.pass = progress.passes;
    figures.seconds = progress.seconds;
    figures.renderSeconds = progress.seconds - progress.observerSeconds;
    figures.cpuSeconds = progress.cpuSeconds - progress.observerCpuSeconds;
    figures.samplesPerPixel = progress.samplesPerPixel;
    figures.samplesTaken = progress.samplesTaken;
    figures.activePixels = progress.activePixels;
    return figures;
}

} // namespace vkpt
