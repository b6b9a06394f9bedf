// render_driver.h — runs a render on any executor: batches sized by the executor and capped by
// the driver (an observer's log-spaced measurements, the next checkpoint, the time limit), the
// observer after each batch, checkpoints, stop signals; then the pixels, features and the
// reason it stopped. vkpt and vkpt-ref run their renders through this one loop, so that every
// option that steers it means the same for both.
#pragma once

#include "driver/render_executor.h"
#include "driver/render_run.h"

namespace vkpt {

// Runs `executor` to its end; the result's stats hold the render's wall seconds (the executor
// adds its own counts). Deterministic when the executor is: the image does not depend on how
// the render was cut into batches.
RenderRunResult runRender(RenderExecutor& executor, const RenderRunOptions& options);

} // namespace vkpt
