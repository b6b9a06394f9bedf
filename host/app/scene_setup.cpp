// scene_setup.cpp — load → BVH → layout → camera, logged on stderr.
#include "app/scene_setup.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "common/phase_log.h"
#include "prepare/environment_map.h"
#include "prepare/scene_lighting.h"
#include "scene/camera.h"
#include "scene/gltf_loader.h"

namespace vkpt {

namespace {

SceneEnvironment loadEnvironment(const RenderSettings& settings) {
    if (!settings.environmentPath.empty())
        return readEnvironmentMap(settings.environmentPath, glm::vec3(settings.environmentScale));
    SceneEnvironment environment;
    if (settings.environmentColorSet)
        environment.radiance = glm::vec3(settings.environmentColor[0], settings.environmentColor[1],
                                         settings.environmentColor[2]);
    return environment;
}

// The studio for a scene that brings no light (scene_lighting.h), said in one line with the
// options that keep the scene dark.
void lightIfUnlit(Scene& scene, const RenderSettings& settings, const std::string& program) {
    LightingRequest request;
    request.environmentGiven = !settings.environmentPath.empty() || settings.environmentColorSet;
    request.defaultLightAllowed = settings.defaultLight == DefaultLight::Auto;
    request.lightMatters = settings.integrator != Integrator::Normals;
    const LightingDecision decision = applyDefaultLighting(scene, request);
    if (settings.verbose)
        std::fprintf(stderr, "%s: lighting: %s\n", program.c_str(),
                     describeLightingMeasure(decision.measure).c_str());
    if (!decision.useStudio) return;
    std::fprintf(stderr,
                 "%s: %s: %s; lit by the default studio environment (--default-light off or "
                 "--env-color 0 0 0 keeps it dark)\n",
                 program.c_str(), settings.scenePath.c_str(),
                 describeLightingReason(decision.measure).c_str());
}

// "vkpt: material variants: 0 'midnight', 1 'beach' (shown), 2 'street'" for --verbose.
void listVariants(const Scene& scene, const std::string& program) {
    if (scene.materialVariants.empty()) return;
    std::string list;
    for (std::size_t i = 0; i < scene.materialVariants.size(); ++i) {
        list += (i == 0 ? "" : ", ") + std::to_string(i) + " '" + scene.materialVariants[i] + "'";
        if (int(i) == scene.materialVariant) list += " (shown)";
    }
    if (scene.materialVariant < 0) list += "; shown: the default materials (--variant NAME|N)";
    std::fprintf(stderr, "%s: material variants: %s\n", program.c_str(), list.c_str());
}

// " (16438 stored: 2 meshes placed by 12544 instances)" for a two-level scene.
std::string instancingNote(const Scene& scene) {
    if (scene.instances.empty()) return "";
    return " (" + std::to_string(scene.storedTriangleCount()) +
           " stored: " + std::to_string(scene.meshes.size()) +
           (scene.meshes.size() == 1 ? " mesh" : " meshes") + " placed by " +
           std::to_string(scene.instances.size()) +
           (scene.instances.size() == 1 ? " instance)" : " instances)");
}

// One line per animation of the file, with its time range, and which of them pose the scene.
void listAnimations(const Scene& scene, const RenderSettings& settings,
                    const std::string& program) {
    for (std::size_t a = 0; a < scene.animations.size(); ++a) {
        const SceneAnimation& animation = scene.animations[a];
        std::fprintf(stderr,
                     "%s: animation %zu '%s': %zu channels, %.3f s (from %.3f s to %.3f s)\n",
                     program.c_str(), a, animation.name.c_str(), animation.channels,
                     animation.end - animation.start, animation.start, animation.end);
    }
    if (scene.animations.empty()) return;
    if (!settings.animationTime) {
        std::fprintf(stderr, "%s: the scene is at rest (--time T poses it)\n", program.c_str());
        return;
    }
    std::fprintf(stderr, "%s: posed at %.3f s by %s\n", program.c_str(), *settings.animationTime,
                 settings.animation.empty() ? "every animation"
                                            : ("animation " + settings.animation).c_str());
}

} // namespace

SceneSetup setUpScene(const RenderSettings& settings, const std::string& program,
                      const std::function<void(const Scene&)>& afterLoad, FrameCache* frames) {
    SceneSetup setup;
    auto start = std::chrono::steady_clock::now();
    ScopedPhase loadPhase("load");
    LoadOptions loadOptions;
    loadOptions.instancing = settings.instancing;
    loadOptions.time = settings.animationTime;
    loadOptions.animation = settings.animation;
    loadOptions.variant = settings.variant;
    // A still posed at a time is laid out as that frame of the animation is, so that it renders
    // the very image the frame does (docs/scene-model.md, "Frames").
    loadOptions.keepMovingApart =
        settings.animationTime.has_value() && settings.instancing != Instancing::Off;
    std::optional<GltfSceneSource> once;
    std::optional<GltfSceneSource>& read = frames != nullptr ? frames->source : once;
    if (!read) read.emplace(settings.scenePath);
    Scene scene = read->pose(loadOptions);
    if (settings.verbose) {
        listAnimations(scene, settings, program);
        listVariants(scene, program);
    }
    if (frames == nullptr) {
        scene.environment = loadEnvironment(settings);
    } else {
        if (!frames->environment) frames->environment = loadEnvironment(settings);
        scene.environment = *frames->environment;
    }
    lightIfUnlit(scene, settings, program);
    loadPhase.end();
    setup.loadSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    float aspect = float(settings.width) / float(settings.height);
    SceneCamera camera = selectCamera(scene, settings.cameraIndex, aspect);
    setup.camera = makeGpuCamera(camera, settings.width, settings.height);
    if (afterLoad) afterLoad(scene);
    ScopedPhase preparePhase("prepare");
    PrepareOptions prepareOptions{{}, settings.general, settings.lightSampler};
    prepareOptions.bvhCache = frames != nullptr ? &frames->bvhs : nullptr;
    prepareOptions.levelCache = frames != nullptr ? &frames->levels : nullptr;
    setup.prepared = prepareScene(scene, prepareOptions);
    preparePhase.end();
    setup.placedTriangles = scene.placedTriangleCount();
    setup.instances = scene.instances.size();
    setup.meshes = scene.meshes.size();
    const BvhStats& bvh = setup.prepared.bvhStats;
    std::fprintf(stderr,
                 "%s: %s: %llu triangles%s, %zu spheres, %zu emitters; BVH %u nodes, depth %u, "
                 "SAH cost %.2f, built in %.3f s\n",
                 program.c_str(), settings.scenePath.c_str(),
                 static_cast<unsigned long long>(setup.placedTriangles),
                 instancingNote(scene).c_str(), scene.spheres.size(),
                 setup.prepared.emitters.size(), bvh.nodeCount, bvh.maxDepth, double(bvh.sahCost),
                 bvh.buildSeconds);
    if (frames != nullptr) {
        const LevelCacheStats& levels = frames->levels.stats();
        const BvhCacheStats& kept = frames->bvhs.stats();
        if (settings.verbose)
            std::fprintf(stderr,
                         "%s: frame bottom levels: %u taken from the frame before (%llu "
                         "primitives), %u prepared; of their BVHs %u taken from the frame before "
                         "(same boxes), %u built\n",
                         program.c_str(), levels.reused,
                         static_cast<unsigned long long>(levels.reusedPrimitives), levels.prepared,
                         kept.reused, kept.built);
        frames->levels.endFrame();
        frames->bvhs.endFrame();
    }
    if (settings.verbose)
        std::fprintf(stderr, "%s: features: %s%s\n", program.c_str(),
                     describeFeatures(setup.prepared.usedFeatures).c_str(),
                     settings.general ? " (built for all features: --general)" : "");
    if (settings.verbose) {
        const auto dark =
            std::count_if(setup.prepared.emitters.begin(), setup.prepared.emitters.end(),
                          [](const gpu::Emitter& e) { return !(e.selectProbability > 0.0f); });
        std::fprintf(stderr,
                     "%s: %lld of %zu emitters have power 0 (black emissive texture) "
                     "and are never chosen\n",
                     program.c_str(), static_cast<long long>(dark), setup.prepared.emitters.size());
    }
    if (setup.prepared.emitters.empty() && settings.integrator != Integrator::Normals)
        std::fprintf(stderr,
                     "%s: %s: the scene has no emitters; the image will be black (light it with "
                     "--env FILE or --env-color R G B)\n",
                     program.c_str(), settings.scenePath.c_str());
    return setup;
}

int reportFailure(const std::string& program, const std::exception& error, int exitCode) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), error.what());
    return exitCode;
}

} // namespace vkpt
