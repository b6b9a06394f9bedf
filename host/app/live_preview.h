// live_preview.h — the image as a viewer sees it: written atomically (a viewer that reloads the
// file never reads half of one), at the end and, with --preview S, every S seconds while the
// render runs. The preview rides on the executors' one periodic hook, which checkpoints also
// use, so that a render without --preview pays nothing for it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/render_part.h"
#include "common/render_settings.h"
#include "denoise/denoiser.h"
#include "image/image.h"
#include "state/render_state.h"

namespace vkpt {

// Writes `image` to settings.outputPath (.png, .pfm or .hdr) under a temporary name, then
// renames it into place; .png with the settings' exposure and tone map. Throws InputError
// "<path>: cannot write: <reason>".
void writeDisplayImage(const Image& image, const RenderSettings& settings);

// The records of the part's crop and their AOVs (empty when the render records none).
using RecordsWriter =
    std::function<void(const std::vector<PixelRecord>&, const std::vector<FeatureRecord>&)>;

// What an executor calls at a pass end (WavefrontOptions and ReferenceOptions: checkpoint and
// checkpointSeconds): every `seconds`, one or both of the writes that are due.
struct PeriodicWrite {
    double seconds = 0.0; // 0: never
    RecordsWriter write;
};

// The preview of a render of `width` × `height` whose records cover `crop`: the image so far
// (0 outside the crop) — denoised by `denoiser` when one is given (--denoise) — or for an .exr
// output the state written by `stateWriter` (the .exr is the image, its layers and the state in
// one file; RenderPart::checkpointWriter(denoiser) adds the denoised image there).
RecordsWriter previewWriter(const RenderSettings& settings, const PixelRect& crop,
                            RecordsWriter stateWriter, Denoiser* denoiser = nullptr);

// The checkpoint and the preview through one hook: it is called every min of the two periods,
// and runs each write whose own period has passed since it last ran (a checkpoint may come up to
// one preview period late). Either may be absent (seconds 0); both absent: seconds 0.
PeriodicWrite combinePeriodicWrites(PeriodicWrite checkpoint, PeriodicWrite preview);

// The hook of a render part: its checkpoints (--checkpoint) and previews (--preview, denoised
// by `denoiser` when given).
PeriodicWrite periodicWrites(const RenderSettings& settings, RenderPart& part,
                             Denoiser* denoiser = nullptr);

} // namespace vkpt
