// frame_options.h — an animation rendered as a sequence of images: --frames A:B[:STEP] at
// --fps F into numbered files (-o out.####.png), or one frame of it per farm task (--frame I)
// (docs/distributed.md, "Animations").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "common/render_settings.h"

namespace vkpt {

struct FrameRange {
    std::uint32_t first = 0;
    std::uint32_t last = 0; // inclusive
    std::uint32_t step = 1;
};

struct FrameSettings {
    std::optional<FrameRange> range;     // --frames
    std::optional<std::uint32_t> single; // --frame: this one frame of the range
    double fps = 24.0;

    bool any() const { return range || single; }
};

void addFrameOptions(CommandLine& commandLine, FrameSettings& frames);

// Cross-option checks: --animation needs a time (--time or frames); with frames the output (and
// the statistics JSON, when asked for) must name the frame with a run of '#', --time does not
// go with them (each frame has its own), and --frame must be one of the range's frames. Throws
// InputError naming the options.
void validateFrameSettings(const FrameSettings& frames, const RenderSettings& settings);

// The frames this process renders, in order: the range's, or the one --frame names.
std::vector<std::uint32_t> framesToRender(const FrameSettings& frames);

// `pattern` with its last run of '#' replaced by the frame number, zero-padded to the run's
// length ("out.####.png", 7 → "out.0007.png"; a number longer than the run is written whole).
std::string framePath(const std::string& pattern, std::uint32_t frame);

// Whether `path` has a run of '#' to number frames with.
bool namesFrames(const std::string& path);

// The settings of one frame: posed at frame / fps seconds, written to the numbered files.
RenderSettings frameSettings(const RenderSettings& settings, const FrameSettings& frames,
                             std::uint32_t frame);

} // namespace vkpt
