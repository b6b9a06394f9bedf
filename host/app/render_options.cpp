// render_options.cpp — option table: long names and CS184's short forms.
#include "app/render_options.h"

#include <cmath>

#include "common/errors.h"
#include "shared/rng.h"

namespace vkpt {

namespace {

Integrator parseIntegrator(const std::string& text) {
    if (text == "path") return Integrator::Path;
    if (text == "direct") return Integrator::Direct;
    if (text == "normals") return Integrator::Normals;
    throw InputError("option --integrator: '" + text + "' is not one of path, direct, normals");
}

Instancing parseInstancing(const std::string& text) {
    if (text == "auto") return Instancing::Auto;
    if (text == "on") return Instancing::On;
    if (text == "off") return Instancing::Off;
    throw InputError("option --instancing: '" + text + "' is not one of auto, on, off");
}

DefaultLight parseDefaultLight(const std::string& text) {
    if (text == "auto") return DefaultLight::Auto;
    if (text == "off") return DefaultLight::Off;
    throw InputError("option --default-light: '" + text + "' is not one of auto, off");
}

ToneMap parseToneMap(const std::string& text) {
    if (text == "neutral") return ToneMap::PbrNeutral;
    if (text == "clamp") return ToneMap::Clamp;
    throw InputError("option --tonemap: '" + text + "' is not one of neutral, clamp");
}

Sampler parseSampler(const std::string& text) {
    if (text == "sobol") return Sampler::Sobol;
    if (text == "independent") return Sampler::Independent;
    throw InputError("option --sampler: '" + text + "' is not one of sobol, independent");
}

LightSampler parseLightSampler(const std::string& text) {
    if (text == "auto") return LightSampler::Auto;
    if (text == "bvh") return LightSampler::Bvh;
    if (text == "power") return LightSampler::Power;
    throw InputError("option --light-sampler: '" + text + "' is not one of auto, bvh, power");
}

LightSampling parseLightSampling(const std::string& text) {
    if (text == "light") return LightSampling::Light;
    if (text == "hemisphere") return LightSampling::Hemisphere;
    throw InputError("option --light-sampling: '" + text + "' is not one of light, hemisphere");
}

void addImageOptions(CommandLine& cl, RenderSettings& s) {
    cl.add({"spp", {'s'}, "N", "samples per pixel (the budget when adaptive)", [&s](auto v) {
                s.samplesPerPixel = parseUnsigned("spp", v[0], 1);
            }});
    cl.add({"res", {'r'}, "W H", "image size in pixels (default 512 512)", [&s](auto v) {
                s.width = parseUnsigned("res", v[0], 1);
                s.height = parseUnsigned("res", v[1], 1);
            }});
    cl.add({"output",
            {'o', 'f'},
            "FILE",
            ".png (sRGB 8-bit), .pfm, .hdr (linear float), .exr (float, layers and state)",
            [&s](auto v) { s.outputPath = v[0]; }});
    cl.add({"exposure", {}, "EV", "scale by 2^EV before 8-bit output (default 0)", [&s](auto v) {
                s.exposure = parseFloat("exposure", v[0]);
            }});
    cl.add({"tonemap",
            {},
            "NAME",
            "8-bit output: neutral (Khronos PBR Neutral, the default) or clamp",
            [&s](auto v) { s.toneMap = parseToneMap(v[0]); }});
    cl.add(
        {"camera", {}, "N", "render from the scene's camera N (default: the first)", [&s](auto v) {
             s.cameraIndex = int(parseUnsigned("camera", v[0]));
         }});
    cl.add({"seed", {}, "N", "random seed (same seed, same image)", [&s](auto v) {
                s.seed = parseUnsigned("seed", v[0]);
            }});
    cl.add({"sampler",
            {},
            "NAME",
            "sobol (scrambled, blue-noise error; the default) or independent",
            [&s](auto v) { s.sampler = parseSampler(v[0]); }});
}

void addIntegratorOptions(CommandLine& cl, RenderSettings& s) {
    cl.add({"integrator", {}, "NAME", "path (default), direct or normals", [&s](auto v) {
                s.integrator = parseIntegrator(v[0]);
            }});
    cl.add({"max-depth",
            {'m'},
            "N",
            "scattering events: 0 emitters only, 1 direct (default 16)",
            [&s](auto v) { s.maxDepth = parseUnsigned("max-depth", v[0]); }});
    cl.add({"rr-depth",
            {},
            "N",
            "Russian roulette from the Nth scattering event (default 3)",
            [&s](auto v) { s.rrStartDepth = parseUnsigned("rr-depth", v[0], 1); }});
    cl.add({"light-sampling",
            {},
            "KIND",
            "direct integrator: light (default) or hemisphere",
            [&s](auto v) { s.lightSampling = parseLightSampling(v[0]); }});
    cl.add({"light-sampler",
            {},
            "KIND",
            "how a light sample chooses its emitter: bvh (a light BVH weighing power, distance "
            "and orientation), power, or auto (default: bvh from 16 emitters on)",
            [&s](auto v) { s.lightSampler = parseLightSampler(v[0]); }});
    cl.add({"hemisphere", {'H'}, "", "same as --light-sampling hemisphere", [&s](auto) {
                s.lightSampling = LightSampling::Hemisphere;
            }});
    cl.add(
        {"light-samples", {'l'}, "N", "light samples per shading point (default 1)", [&s](auto v) {
             s.lightSamples = parseUnsigned("light-samples", v[0]);
         }});
    cl.add({"direct-only", {}, "", "keep paths with at most one scattering event", [&s](auto) {
                s.pathFilter = PathFilter::DirectOnly;
            }});
    cl.add({"indirect-only", {}, "", "keep paths with two or more scattering events", [&s](auto) {
                s.pathFilter = PathFilter::IndirectOnly;
            }});
}

void addSceneOptions(CommandLine& cl, RenderSettings& s) {
    cl.add({"env",
            {},
            "FILE",
            "environment: an equirectangular .hdr image, +Y up (importance sampled)",
            [&s](auto v) { s.environmentPath = v[0]; }});
    cl.add({"env-color",
            {},
            "R G B",
            "environment: a constant radiance (default black)",
            [&s](auto v) {
                for (int c = 0; c < 3; ++c) {
                    s.environmentColor[c] = parseFloat("env-color", v[std::size_t(c)]);
                    if (!(s.environmentColor[c] >= 0.0f))
                        throw InputError("option --env-color: components must be >= 0");
                }
                s.environmentColorSet = true;
            }});
    cl.add({"default-light",
            {},
            "MODE",
            "auto (default): a scene without lights gets a studio environment; off: it stays dark",
            [&s](auto v) { s.defaultLight = parseDefaultLight(v[0]); }});
    cl.add({"env-scale", {}, "X", "multiply the --env image by X (default 1)", [&s](auto v) {
                s.environmentScale = parseFloat("env-scale", v[0]);
                if (!(s.environmentScale >= 0.0f))
                    throw InputError("option --env-scale: X must be >= 0");
            }});
    cl.add({"general",
            {},
            "",
            "build the all-features pipelines and buffers instead of the scene's own set",
            [&s](auto) { s.general = true; }});
    cl.add({"instancing",
            {},
            "MODE",
            "meshes placed many times kept once under a top-level BVH: auto (default: large "
            "scenes), on (every mesh), off (all flattened)",
            [&s](auto v) { s.instancing = parseInstancing(v[0]); }});
    cl.add({"time",
            {},
            "T",
            "pose the scene by its animations at T seconds (default: at rest, as stored)",
            [&s](auto v) {
                const float time = parseFloat("time", v[0]);
                if (!std::isfinite(time)) throw InputError("option --time: T must be finite");
                s.animationTime = double(time);
            }});
    cl.add({"variant",
            {},
            "NAME|N",
            "KHR_materials_variants: show variant NAME (or number N) instead of the default "
            "materials (--verbose lists them)",
            [&s](auto v) { s.variant = v[0]; }});
    cl.add({"animation",
            {},
            "N|NAME",
            "with --time: play only this animation, by index or name (default: all together)",
            [&s](auto v) { s.animation = v[0]; }});
    cl.add({"verbose",
            {'v'},
            "",
            "print the scene's feature set, animations, variants and setup details",
            [&s](auto) { s.verbose = true; }});
}

void addRunOptions(CommandLine& cl, RenderSettings& s) {
    cl.add({"adaptive",
            {'a'},
            "BATCH TOL",
            "stop a pixel when its 95% half-width (1.96 sigma/sqrt(n), calibrated by the two "
            "halves) <= TOL mean, tested every BATCH samples",
            [&s](auto v) {
                s.adaptive.enabled = true;
                s.adaptive.batchSize = parseUnsigned("adaptive", v[0], 1);
                s.adaptive.tolerance = parseFloat("adaptive", v[1]);
            }});
    cl.add({"adaptive-min",
            {},
            "N",
            "adaptive: no pixel stops before N samples (default 64)",
            [&s](auto v) { s.adaptive.minSamples = parseUnsigned("adaptive-min", v[0], 2); }});
    cl.add({"adaptive-error",
            {},
            "KIND",
            "adaptive: a pixel's error: halves (sigma^2/n calibrated by the image's two halves, "
            "default) or variance (sigma^2/n alone: tiles of --crop stop as one run)",
            [&s](auto v) {
                if (v[0] != "halves" && v[0] != "variance")
                    throw InputError("option --adaptive-error: '" + v[0] +
                                     "' is neither halves nor variance");
                s.adaptive.calibrated = v[0] == "halves";
            }});
    cl.add({"clamp",
            {},
            "X",
            "scale each sample down so no component exceeds X (biased: loses energy; default off)",
            [&s](auto v) {
                s.clamp = parseFloat("clamp", v[0]);
                if (!(s.clamp > 0.0f)) throw InputError("option --clamp: X must be positive");
            }});
    cl.add({"threads", {'t'}, "N", "CPU threads (default: all cores)", [&s](auto v) {
                s.threads = parseUnsigned("threads", v[0], 1);
            }});
    cl.add({"stats-json", {}, "FILE", "write the render statistics as JSON", [&s](auto v) {
                s.statsJsonPath = v[0];
            }});
    cl.add({"preview",
            {},
            "S",
            "write the image so far to the output every S seconds (atomically)",
            [&s](auto v) {
                s.previewSeconds = double(parseFloat("preview", v[0]));
                if (!(s.previewSeconds > 0.0))
                    throw InputError("option --preview: S must be positive");
            }});
    cl.add({"denoise",
            {},
            "",
            "write the denoised image (statistics-gated, consistent; an .exr keeps the raw "
            "image in its raw layer)",
            [&s](auto) { s.denoise = true; }});
    cl.add({"quiet", {'q'}, "", "no progress bar", [&s](auto) { s.quiet = true; }});
}

} // namespace

void addRenderOptions(CommandLine& commandLine, RenderSettings& settings) {
    addImageOptions(commandLine, settings);
    addIntegratorOptions(commandLine, settings);
    addSceneOptions(commandLine, settings);
    addRunOptions(commandLine, settings);
}

void validateRenderSettings(const RenderSettings& settings) {
    if (settings.scenePath.empty()) throw InputError("no scene file given (see --help)");
    if (settings.lightSamples > RNG_MAX_LIGHT_SAMPLES)
        throw InputError("option --light-samples: at most " +
                         std::to_string(RNG_MAX_LIGHT_SAMPLES) + " samples");
    if (settings.adaptive.enabled && !(settings.adaptive.tolerance > 0.0f))
        throw InputError("option --adaptive: the tolerance must be positive");
    if (!settings.environmentPath.empty() && settings.environmentColorSet)
        throw InputError("options --env and --env-color: give one environment, not both");
    if (std::uint64_t(settings.width) * settings.height > (1ull << 28))
        throw InputError("option --res: at most 2^28 pixels");
}

} // namespace vkpt
