// farm_options.cpp — option table and checks of --task, --crop, --resume, --checkpoint.
#include "app/farm_options.h"

#include <cmath>

#include "common/errors.h"

namespace vkpt {

void addFarmOptions(CommandLine& cl, FarmSettings& farm) {
    cl.add({"task",
            {},
            "K/N",
            "render task K (from 0) of N: its share of every pixel's samples",
            [&farm](auto v) { farm.task = parseTaskShare(v[0]); }});
    cl.add({"crop",
            {},
            "X0 Y0 X1 Y1",
            "render only the pixels x in [X0, X1), y in [Y0, Y1)",
            [&farm](auto v) {
                farm.crop = PixelRect{parseUnsigned("crop", v[0]), parseUnsigned("crop", v[1]),
                                      parseUnsigned("crop", v[2]), parseUnsigned("crop", v[3])};
            }});
    cl.add({"resume",
            {},
            "FILE",
            "continue the render whose state FILE (.exr) holds",
            [&farm](auto v) { farm.resumePath = v[0]; }});
    cl.add({"checkpoint",
            {},
            "S",
            "write the render's state every S seconds (atomically)",
            [&farm](auto v) {
                const float seconds = parseFloat("checkpoint", v[0]);
                if (!(seconds > 0.0f))
                    throw InputError("option --checkpoint: '" + v[0] +
                                     "' is not a positive number of seconds");
                farm.checkpointSeconds = double(seconds);
            }});
}

void validateFarmSettings(const FarmSettings& farm, const RenderSettings& settings) {
    if (farm.task && settings.adaptive.enabled)
        throw InputError("options --task and --adaptive: an adaptive pixel's stop depends on all "
                         "its samples, so tasks cannot share them; split by region with --crop");
    if (farm.task && farm.task->count > settings.samplesPerPixel)
        throw InputError("option --task: " + std::to_string(farm.task->count) + " tasks for " +
                         std::to_string(settings.samplesPerPixel) +
                         " samples per pixel would leave some with none");
    if (!farm.crop) return;
    const PixelRect& c = *farm.crop;
    if (c.empty() || c.x1 > settings.width || c.y1 > settings.height)
        throw InputError("option --crop: " + describeRect(c) +
                         " is not a non-empty rectangle "
                         "inside the " +
                         std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                         " image");
}

SamplePlan samplePlanFor(const FarmSettings& farm, const RenderSettings& settings) {
    SamplePlan plan;
    plan.crop = farm.crop.value_or(fullFrame(settings.width, settings.height));
    plan.range = farm.task ? taskSampleRange(settings.samplesPerPixel, *farm.task)
                           : SampleRange{0, settings.samplesPerPixel};
    return plan;
}

} // namespace vkpt
