// interrupt.h — Ctrl-C (SIGINT) and SIGTERM, what a terminal, Slurm, Kubernetes and systemd send
// to stop a job, both ask the renderer to finish the current pass (or round), write the image
// and the state, and exit; a second signal ends the process at once.
#pragma once

#include <atomic>

namespace vkpt {

// Set by the first SIGINT or SIGTERM after installStopHandlers().
const std::atomic<bool>& stopRequested();

// Installs the handlers (SA_RESETHAND: the second signal gets the default action).
void installStopHandlers();

// 128 + the signal that asked to stop (130 for SIGINT, 143 for SIGTERM), as shells report a
// process ended by it; 0 when none did.
int exitCodeForStop();

} // namespace vkpt
