// output_checks.h — every file a render will write is checked before the scene is even
// loaded, so that a typo in a path costs a second, not the render.
#pragma once

#include "app/farm_options.h"
#include "common/render_settings.h"

namespace vkpt {

// Whether an output of this name is the render's whole state (.exr: the image, its layers and
// the moments) rather than an image alone.
bool outputHoldsState(const std::string& outputPath);

// The state file beside an image: the image itself when it is .exr, else
// "dir/name.png" → "dir/name_state.exr".
std::string statePathFor(const std::string& outputPath);

// Throws InputError "<path>: <reason>" unless the image's format is known (.png, .pfm, .hdr,
// .exr), and the folders of the image, its heat map, its state and the statistics JSON exist
// and can be written, and none of those paths is a folder.
void checkOutputPaths(const RenderSettings& settings);

} // namespace vkpt
