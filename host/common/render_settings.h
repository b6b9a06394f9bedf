// render_settings.h — what to render and how: the options both vkpt and vkpt-ref accept.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace vkpt {

enum class Integrator { Path, Direct, Normals };
enum class LightSampling { Light, Hemisphere };
// --light-sampler: how next-event estimation chooses an emitter: by the light BVH's importance
// from the shading point (shared/light_tree.h), in proportion to power alone, or (auto, the
// default) by the light BVH in scenes with enough emitters for it to pay (kLightTreeMinEmitters,
// prepare/prepared_scene.h).
enum class LightSampler : std::uint32_t { Auto = 0, Bvh = 1, Power = 2 };
enum class PathFilter : std::uint32_t { All = 0, DirectOnly = 1, IndirectOnly = 2 };
// --instancing: which meshes placed more than once are kept once and walked through a top-level
// BVH (docs/scene-model.md, "Instancing"): by the measured rule, all meshes, or none (every
// placement flattened into world space).
enum class Instancing : std::uint32_t { Auto = 0, On = 1, Off = 2 };
// --default-light: whether a scene that brings no light gets the built-in studio environment
// (docs/scene-model.md, "Default lighting").
enum class DefaultLight : std::uint32_t { Auto = 0, Off = 1 };
// --tonemap: how 8-bit output maps linear radiance (after the exposure) into [0, 1]
// (image/tone_map.h): a plain clamp or the Khronos PBR Neutral operator (the default).
enum class ToneMap : std::uint32_t { Clamp = 0, PbrNeutral = 1 };
// --sampler: where a sample's numbers come from (shared/sampler.h): the scrambled Sobol sequence
// with pixels in Morton order (the default), or independent random numbers (shared/rng.h).
enum class Sampler : std::uint32_t { Sobol = 0, Independent = 1 };

struct AdaptiveSettings {
    bool enabled = false;
    std::uint32_t batchSize = 32;  // test convergence every batchSize samples (CS184's default)
    float tolerance = 0.05f;       // relative half-width of the 95 % interval
    std::uint32_t minSamples = 64; // no pixel stops before this many samples
    // The per-pixel error: σ²/n calibrated by the rendered pixels' two halves (true), or σ²/n
    // alone (false: it overstates the Sobol sampler's error, but a pixel's stop then depends on
    // its own samples only, so tiles of a crop-split render stop exactly as one run's pixels).
    bool calibrated = true;
};

struct RenderSettings {
    std::string scenePath;
    std::string outputPath = "render.png";
    std::uint32_t width = 512;
    std::uint32_t height = 512;
    std::uint32_t samplesPerPixel = 16;
    std::uint32_t maxDepth = 16;    // scattering events: 0 = emitters only, 1 = direct
    std::uint32_t rrStartDepth = 3; // Russian roulette from this scattering event on
    std::uint32_t seed = 0;
    Sampler sampler = Sampler::Sobol;
    std::uint32_t threads = 0; // 0 = all cores
    Integrator integrator = Integrator::Path;
    LightSampling lightSampling = LightSampling::Light;
    std::uint32_t lightSamples = 1;
    LightSampler lightSampler = LightSampler::Auto;
    PathFilter pathFilter = PathFilter::All;
    AdaptiveSettings adaptive;
    float exposure = 0.0f;                 // EV applied to 8-bit output only
    ToneMap toneMap = ToneMap::PbrNeutral; // 8-bit output only, after the exposure
    // --clamp X: a sample's largest component is limited to X (biased; 0 = off, the default).
    float clamp = 0.0f;
    std::optional<int> cameraIndex;
    // The environment seen by rays that leave the scene: --env FILE (equirectangular .hdr, its
    // texels times environmentScale) or --env-color R G B; black when neither is given.
    std::string environmentPath;
    bool environmentColorSet = false;
    float environmentColor[3] = {0.0f, 0.0f, 0.0f};
    float environmentScale = 1.0f;
    DefaultLight defaultLight = DefaultLight::Auto;
    bool general = false; // --general: the all-features pipelines and buffers
    Instancing instancing = Instancing::Auto;
    // --time T: the scene posed by its animations at T seconds; nullopt: at rest.
    std::optional<double> animationTime;
    std::string animation; // --animation N|NAME: the one that plays; "" all of them
    // --variant: the KHR_materials_variants variant whose materials are shown, by name or index;
    // empty: the file's default materials.
    std::string variant;
    bool verbose = false; // --verbose: the scene's feature set and more on stderr
    std::string statsJsonPath;
    bool quiet = false; // no progress bar
    // --preview S: the image so far written to the output path every S seconds (0: never).
    double previewSeconds = 0.0;
    // --denoise: the written image (and the preview) is the denoised one; an .exr output keeps
    // the raw mean in its raw.* layer beside the AOVs (docs/denoise.md).
    bool denoise = false;
};

} // namespace vkpt
