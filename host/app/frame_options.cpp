// frame_options.cpp — option table and checks of --frames, --frame, --fps, and frame names.
#include "app/frame_options.h"

#include <cmath>

#include "common/errors.h"

namespace vkpt {

namespace {

// "A:B" or "A:B:STEP", A <= B, STEP >= 1.
FrameRange parseFrameRange(const std::string& text) {
    FrameRange range;
    const std::size_t colon = text.find(':');
    const std::size_t second = colon == std::string::npos ? colon : text.find(':', colon + 1);
    if (colon == std::string::npos)
        throw InputError("option --frames: '" + text + "' is not A:B or A:B:STEP");
    range.first = parseUnsigned("frames", text.substr(0, colon));
    range.last = parseUnsigned("frames", text.substr(colon + 1, second - colon - 1));
    if (second != std::string::npos)
        range.step = parseUnsigned("frames", text.substr(second + 1), 1);
    if (range.last < range.first)
        throw InputError("option --frames: the last frame " + std::to_string(range.last) +
                         " comes before the first " + std::to_string(range.first));
    return range;
}

bool inRange(const FrameRange& range, std::uint32_t frame) {
    return frame >= range.first && frame <= range.last && (frame - range.first) % range.step == 0;
}

} // namespace

void addFrameOptions(CommandLine& cl, FrameSettings& frames) {
    cl.add({"frames",
            {},
            "A:B[:STEP]",
            "render frames A to B (every STEP-th) of the animation into numbered files: the "
            "output's #### becomes the frame number; frames already written are skipped",
            [&frames](auto v) { frames.range = parseFrameRange(v[0]); }});
    cl.add({"frame",
            {},
            "I",
            "render frame I alone (one frame per farm task; of the --frames range when given)",
            [&frames](auto v) { frames.single = parseUnsigned("frame", v[0]); }});
    cl.add({"fps",
            {},
            "F",
            "frames per second of --frames and --frame (default 24)",
            [&frames](auto v) {
                const float fps = parseFloat("fps", v[0]);
                if (!(fps > 0.0f) || !std::isfinite(fps))
                    throw InputError("option --fps: F must be a positive number");
                frames.fps = double(fps);
            }});
}

void validateFrameSettings(const FrameSettings& frames, const RenderSettings& settings) {
    if (!settings.animation.empty() && !settings.animationTime && !frames.any())
        throw InputError("option --animation: give the time to pose the scene at (--time T, "
                         "--frames or --frame)");
    if (!frames.any()) return;
    if (settings.animationTime)
        throw InputError("options --time and --frames/--frame: each frame is posed at its own "
                         "time, frame / fps");
    if (!namesFrames(settings.outputPath))
        throw InputError("option --frames/--frame: the output '" + settings.outputPath +
                         "' needs a run of '#' for the frame number (out.####.png)");
    if (!settings.statsJsonPath.empty() && !namesFrames(settings.statsJsonPath))
        throw InputError("option --stats-json: with --frames/--frame the name needs a run of '#' "
                         "for the frame number (stats.####.json)");
    if (frames.range && frames.single && !inRange(*frames.range, *frames.single))
        throw InputError("option --frame: frame " + std::to_string(*frames.single) +
                         " is not one of the --frames range");
}

std::vector<std::uint32_t> framesToRender(const FrameSettings& frames) {
    if (frames.single) return {*frames.single};
    std::vector<std::uint32_t> list;
    if (!frames.range) return list;
    for (std::uint64_t frame = frames.range->first; frame <= frames.range->last;
         frame += frames.range->step)
        list.push_back(static_cast<std::uint32_t>(frame));
    return list;
}

bool namesFrames(const std::string& path) {
    return path.find('#') != std::string::npos;
}

std::string framePath(const std::string& pattern, std::uint32_t frame) {
    const std::size_t end = pattern.rfind('#');
    if (end == std::string::npos) return pattern;
    std::size_t begin = end;
    while (begin > 0 && pattern[begin - 1] == '#')
        --begin;
    std::string number = std::to_string(frame);
    const std::size_t width = end + 1 - begin;
    if (number.size() < width) number.insert(0, width - number.size(), '0');
    return pattern.substr(0, begin) + number + pattern.substr(end + 1);
}

RenderSettings frameSettings(const RenderSettings& settings, const FrameSettings& frames,
                             std::uint32_t frame) {
    RenderSettings each = settings;
    each.animationTime = double(frame) / frames.fps;
    each.outputPath = framePath(settings.outputPath, frame);
    if (!settings.statsJsonPath.empty())
        each.statsJsonPath = framePath(settings.statsJsonPath, frame);
    return each;
}

} // namespace vkpt
