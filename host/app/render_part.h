// render_part.h — one process's part of a render, apart from its executor: which pixels and
// samples it takes (continuing a resumed state), its checkpoints, and its last writes, which
// never lose the work: when the output cannot be written, the state goes to a rescue file.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/farm_options.h"
#include "app/scene_setup.h"
#include "denoise/denoiser.h"
#include "state/render_state.h"

namespace vkpt {

class RenderPart {
public:
    // Reads the --resume file, if any, so that a bad one is reported before the scene loads.
    RenderPart(std::string program, const RenderSettings& settings, const FarmSettings& farm);

    // Fixes the scene's identity and checks the resumed state against it (InputError naming
    // the file: another scene, settings, seed, size, crop, or samples that are not the start
    // of this render's share).
    void attachScene(const SceneSetup& setup);
    const SamplePlan& plan() const { return plan_; }
    const std::vector<PixelRecord>* resumeRecords() const {
        return resumed_ ? &resumed_->pixels : nullptr;
    }
    // Whether the executor records AOVs: the state files this part writes by plan hold them
    // (an .exr output, checkpoints), the denoiser needs them (--denoise), or the resumed state
    // has them to continue. A state saved
    // only because a render without them was stopped holds no AOV layers.
    bool needsAovs() const;
    // The resumed state's features (plan().crop, row-major), or null.
    const std::vector<FeatureRecord>* resumeFeatures() const;
    double checkpointSeconds() const { return farm_.checkpointSeconds; }
    // Writes the state file (atomically) and says so on stderr. With a denoiser (an .exr
    // --preview under --denoise) the state holds the denoised image too, as the final write's
    // does, so that the preview shows it.
    std::function<void(const std::vector<PixelRecord>&, const std::vector<FeatureRecord>&)>
    checkpointWriter(Denoiser* denoiser = nullptr);

    // The image (or, for .exr, the whole state), its heat map, and the state file when the
    // output is not .exr but checkpoints were asked for or the render was stopped. `features`:
    // the executor's AOVs of the same pixels, or empty. A failed write saves the state to
    // rescuePathFor() first, then throws InputError naming both.
    // `denoised`: the crop's denoised radiance (--denoise), or empty; the image written is then
    // the denoised one, and an .exr output holds both.
    void writeResults(const RenderOutput& output, const std::vector<PixelRecord>& records,
                      const std::vector<FeatureRecord>& features,
                      const std::vector<glm::vec3>& denoised, bool stopped);

private:
    RenderState stateOf(const std::vector<PixelRecord>& records,
                        const std::vector<FeatureRecord>& features) const;
    void checkResumable(const RenderState& resumed);
    void writeState(const RenderState& state, const std::string& path, const char* what);

    std::string program_;
    const RenderSettings& settings_;
    FarmSettings farm_;
    SamplePlan plan_;
    const SceneSetup* setup_ = nullptr;
    StateIdentity identity_;
    std::optional<RenderState> resumed_;
};

} // namespace vkpt
