// reference_render.h — renders a scene file with the CPU reference in-process for tests,
// quietly, with the settings a test chooses.
#pragma once

#include <string>

#include "common/render_settings.h"
#include "common/render_stats.h"
#include "image/render_output.h"
#include "prepare/prepared_scene.h"
#include "reference/reference_renderer.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

namespace vkpt::test {

// Appended in place: GCC 12 at -O2 warns falsely (-Warray-bounds, its bug 105651) about the
// temporary strings of `std::string(dir) + "/" + relative` once inlined.
inline std::string scenePath(const std::string& relative) {
    std::string path = VKPT_SCENES_DIR "/";
    path += relative;
    return path;
}

// Small, fast defaults for tests: 32×32, 16 spp, no progress output.
inline RenderSettings testSettings(std::uint32_t size = 32, std::uint32_t spp = 16) {
    RenderSettings settings;
    settings.width = size;
    settings.height = size;
    settings.samplesPerPixel = spp;
    settings.quiet = true;
    return settings;
}

struct LoadedTestScene {
    Scene scene;
    PreparedScene prepared;
};

// What a test may add to a scene file: an environment (--env, --env-color), the general
// layout (--general) and the light sampler (--light-sampler).
struct TestSceneOptions {
    SceneEnvironment environment;
    bool general = false;
    LightSampler lightSampler = LightSampler::Auto;
};

inline LoadedTestScene loadTestScene(const std::string& relative,
                                     const TestSceneOptions& sceneOptions = {}) {
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    LoadedTestScene loaded{loadGltfScene(scenePath(relative), options), {}};
    loaded.scene.environment = sceneOptions.environment;
    loaded.prepared =
        prepareScene(loaded.scene, {{}, sceneOptions.general, sceneOptions.lightSampler});
    return loaded;
}

inline RenderOutput renderTestScene(const LoadedTestScene& loaded, const RenderSettings& settings,
                                    RenderStats* statsOut = nullptr) {
    gpu::Camera camera = makeGpuCamera(selectCamera(loaded.scene, settings.cameraIndex),
                                       settings.width, settings.height);
    RenderStats stats;
    RenderOutput output = renderReference(loaded.prepared, camera, settings, stats);
    if (statsOut) *statsOut = stats;
    return output;
}

// The direct integrator's two independent estimators of one scene, for tests that their
// images agree: light sampling at settings.seed and uniform hemisphere directions at seed 1.
struct LightAndHemisphere {
    RenderOutput light;
    RenderOutput hemisphere;
};

inline LightAndHemisphere renderLightAndHemisphere(const LoadedTestScene& loaded,
                                                   RenderSettings settings) {
    settings.integrator = Integrator::Direct;
    settings.lightSampling = LightSampling::Light;
    LightAndHemisphere both;
    both.light = renderTestScene(loaded, settings);
    settings.lightSampling = LightSampling::Hemisphere;
    settings.seed = 1;
    both.hemisphere = renderTestScene(loaded, settings);
    return both;
}

} // namespace vkpt::test
