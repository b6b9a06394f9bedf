// live_preview.cpp — atomic image writes, the preview of a render so far, and the hook that
// shares the executors' periodic call between checkpoints and previews.
#include "app/live_preview.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include "app/output_checks.h"
#include "common/errors.h"
#include "driver/denoised_output.h"
#include "image/image_file.h"
#include "image/image_io.h"
#include "state/atomic_write.h"

namespace vkpt {

namespace {

using Clock = std::chrono::steady_clock;

// The image writer's message names the temporary file; writeAtomically names the real one, so
// only the reason is passed on.
std::string reasonOf(const std::string& message, const std::string& temporary) {
    const std::string prefix = temporary + ": cannot write: ";
    return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

// A write and when it last ran.
struct Timed {
    PeriodicWrite periodic;
    Clock::time_point last = Clock::now();

    bool active() const { return periodic.seconds > 0.0 && periodic.write; }
    void runIfDue(const std::vector<PixelRecord>& records,
                  const std::vector<FeatureRecord>& features) {
        if (!active()) return;
        const double since = std::chrono::duration<double>(Clock::now() - last).count();
        if (since < periodic.seconds) return;
        last = Clock::now();
        periodic.write(records, features);
    }
};

} // namespace

void writeDisplayImage(const Image& image, const RenderSettings& settings) {
    const std::string& path = settings.outputPath;
    const std::string extension = detail::lowerCaseExtension(path);
    writeAtomically(path, [&](const std::string& temporary) {
        try {
            writeImageAs(image, temporary, extension, settings.exposure, settings.toneMap);
        } catch (const InputError& error) {
            throw InputError(reasonOf(error.what(), temporary));
        }
    });
}

RecordsWriter previewWriter(const RenderSettings& settings, const PixelRect& crop,
                            RecordsWriter stateWriter, Denoiser* denoiser) {
    if (outputHoldsState(settings.outputPath)) return stateWriter;
    return [&settings, crop, denoiser](const std::vector<PixelRecord>& records,
                                       const std::vector<FeatureRecord>& features) {
        RenderState state;
        state.identity.width = settings.width;
        state.identity.height = settings.height;
        state.window = crop;
        state.pixels = records;
        const Image raw = renderOutputOf(state).image;
        if (!denoiser || features.size() != records.size()) return writeDisplayImage(raw, settings);
        writeDisplayImage(
            denoisedFrame(raw, crop, denoiseWindow(*denoiser, crop, records, features)), settings);
    };
}

PeriodicWrite combinePeriodicWrites(PeriodicWrite checkpoint, PeriodicWrite preview) {
    auto writes = std::make_shared<std::vector<Timed>>();
    for (PeriodicWrite* w : {&checkpoint, &preview})
        if (w->seconds > 0.0 && w->write) writes->push_back({std::move(*w)});
    if (writes->empty()) return {};
    if (writes->size() == 1) return writes->front().periodic;
    double seconds = writes->front().periodic.seconds;
    for (const Timed& t : *writes)
        seconds = std::min(seconds, t.periodic.seconds);
    return {seconds, [writes](const std::vector<PixelRecord>& records,
                              const std::vector<FeatureRecord>& features) {
                for (Timed& t : *writes)
                    t.runIfDue(records, features);
            }};
}

PeriodicWrite periodicWrites(const RenderSettings& settings, RenderPart& part, Denoiser* denoiser) {
    PeriodicWrite checkpoint;
    if (part.checkpointSeconds() > 0.0)
        checkpoint = {part.checkpointSeconds(), part.checkpointWriter()};
    PeriodicWrite preview;
    if (settings.previewSeconds > 0.0)
        preview = {
            settings.previewSeconds,
            previewWriter(settings, part.plan().crop, part.checkpointWriter(denoiser), denoiser)};
    return combinePeriodicWrites(std::move(checkpoint), std::move(preview));
}

} // namespace vkpt
