// vkpt_study_main.cpp — vkpt-study, the speed-against-accuracy trade study of one scene: error
// against a high-spp reference versus render time for uniform and adaptive sampling, light
// and hemisphere sampling, depth limits, Russian roulette and pipelines specialised to the
// scene against general ones (docs/trade/README.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/command_line.h"
#include "app/run_program.h"
#include "app/scene_setup.h"
#include "common/errors.h"
#include "gpu/device_list.h"
#include "study/study_runner.h"

namespace {

using namespace vkpt;

const char* const kProgram = "vkpt-study";

// Options that override the scale (full, or --quick) whatever their order on the line.
struct ScaleOverrides {
    bool quick = false;
    std::optional<std::uint32_t> width, height, spp, sideSpp, referenceSpp;
};

struct Parsed {
    StudyInvocation invocation;
    ScaleOverrides overrides;
    bool showHelp = false;
};

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::size_t begin = 0;
    while (begin <= text.size()) {
        std::size_t end = text.find(',', begin);
        if (end == std::string::npos) end = text.size();
        if (end > begin) items.push_back(text.substr(begin, end - begin));
        begin = end + 1;
    }
    return items;
}

void checkFamilies(const std::vector<std::string>& families) {
    const std::vector<std::string>& known = studyFamilies();
    for (const std::string& f : families)
        if (std::find(known.begin(), known.end(), f) == known.end())
            throw InputError("option --only: '" + f + "' is not one of " + familyList(known));
}

void addScaleOptions(CommandLine& cl, ScaleOverrides& o) {
    cl.add({"quick",
            {},
            "",
            "the seconds-long version CI runs: 32x32, 64 spp, few settings",
            [&o](auto) { o.quick = true; }});
    cl.add({"res", {'r'}, "W H", "image size (default 128 128)", [&o](auto v) {
                o.width = parseUnsigned("res", v[0], 1);
                o.height = parseUnsigned("res", v[1], 1);
            }});
    cl.add({"spp", {'s'}, "N", "uniform and adaptive budget (default 4096)", [&o](auto v) {
                o.spp = parseUnsigned("spp", v[0], 1);
            }});
    cl.add({"side-spp",
            {},
            "N",
            "light/hemisphere, depth and roulette budget (default 1024)",
            [&o](auto v) { o.sideSpp = parseUnsigned("side-spp", v[0], 1); }});
    cl.add({"reference-spp",
            {},
            "N",
            "samples per pixel of the references (default 16384)",
            [&o](auto v) { o.referenceSpp = parseUnsigned("reference-spp", v[0], 1); }});
}

void addStudyOptions(CommandLine& cl, StudyInvocation& s) {
    cl.add({"name",
            {},
            "NAME",
            "base name of the outputs (default: the scene file's stem)",
            [&s](auto v) { s.name = v[0]; }});
    cl.add({"out",
            {'o'},
            "DIR",
            "directory for NAME.csv, .md, .gp and .svg (default .)",
            [&s](auto v) { s.outDir = v[0]; }});
    cl.add({"cache",
            {},
            "DIR",
            "reference cache (default $XDG_CACHE_HOME/vkpt, ~/.cache/vkpt)",
            [&s](auto v) { s.cacheDir = v[0]; }});
    cl.add({"fresh-references", {}, "", "make the references again even when cached", [&s](auto) {
                s.freshReferences = true;
            }});
    cl.add({"reference-on",
            {},
            "cpu|device",
            "render references with vkpt-ref on all cores (default) or with vkpt",
            [&s](auto v) {
                if (v[0] != "cpu" && v[0] != "device")
                    throw InputError("option --reference-on: '" + v[0] +
                                     "' is not one of cpu, device");
                s.referenceOnDevice = v[0] == "device";
            }});
    cl.add({"only", {}, "LIST", "strategies: " + familyList(studyFamilies()), [&s](auto v) {
                s.families = splitList(v[0]);
                checkFamilies(s.families);
            }});
    cl.add({"merge",
            {},
            "",
            "with --only: keep the other strategies' runs from NAME.csv (same scale)",
            [&s](auto) { s.merge = true; }});
    cl.add(
        {"camera", {}, "N", "render from the scene's camera N (default: the first)", [&s](auto v) {
             s.base.cameraIndex = int(parseUnsigned("camera", v[0]));
         }});
    cl.add({"adaptive-error",
            {},
            "KIND",
            "the adaptive runs' per-pixel error: halves (default) or variance (sigma^2/n alone)",
            [&s](auto v) {
                if (v[0] != "halves" && v[0] != "variance")
                    throw InputError("option --adaptive-error: '" + v[0] +
                                     "' is neither halves nor variance");
                s.base.adaptive.calibrated = v[0] == "halves";
            }});
    cl.add({"note",
            {},
            "TEXT",
            "a sentence for the table (e.g. how loaded the machine was)",
            [&s](auto v) { s.note = v[0]; }});
    cl.add({"no-plot", {}, "", "skip gnuplot (the script is still written)", [&s](auto) {
                s.plot = false;
            }});
    cl.add({"clock",
            {},
            "wall|cpu",
            "time axis (default: cpu on a CPU device such as lavapipe, wall on a GPU)",
            [&s](auto v) {
                if (v[0] != "wall" && v[0] != "cpu")
                    throw InputError("option --clock: '" + v[0] + "' is not one of wall, cpu");
                s.clock = v[0] == "cpu" ? StudyClock::Cpu : StudyClock::Wall;
            }});
    cl.add(
        {"replot", {}, "", "render nothing: redraw the table and plots from NAME.csv", [&s](auto) {
             s.replot = true;
         }});
}

void addDeviceOptions(CommandLine& cl, StudyInvocation& s) {
    cl.add({"device", {}, "N|NAME", "Vulkan device by index or name substring", [&s](auto v) {
                s.gpu.device = parseDeviceSelection(v[0]);
            }});
    cl.add({"validate",
            {},
            "",
            "enable the Vulkan validation layer (or VKPT_VALIDATION=1)",
            [&s](auto) { s.gpu.validation = true; }});
    cl.add({"path-slots",
            {},
            "N",
            "paths in flight per pass (default: from the device)",
            [&s](auto v) { s.pathSlots = parseUnsigned("path-slots", v[0], 64); }});
}

StudyScale composeScale(const ScaleOverrides& o) {
    StudyScale scale = o.quick ? quickScale() : fullScale();
    if (o.width) scale.width = *o.width, scale.height = *o.height;
    if (o.spp) scale.maxSpp = *o.spp;
    if (o.sideSpp) scale.sideSpp = *o.sideSpp;
    if (o.referenceSpp) scale.referenceSpp = *o.referenceSpp;
    if (scale.adaptiveMinSamples > scale.maxSpp) scale.adaptiveMinSamples = scale.maxSpp;
    return scale;
}

Parsed parseArguments(int argc, char** argv) {
    Parsed parsed;
    CommandLine cl(kProgram);
    addScaleOptions(cl, parsed.overrides);
    addStudyOptions(cl, parsed.invocation);
    addDeviceOptions(cl, parsed.invocation);
    cl.add({"help", {'h'}, "", "show this help", [&](auto) { parsed.showHelp = true; }});
    std::vector<std::string> arguments(argv + 1, argv + argc);
    std::vector<std::string> positional = cl.parse(arguments);
    if (parsed.showHelp) {
        std::fputs(cl.usage("scene.gltf|scene.glb").c_str(), stdout);
        return parsed;
    }
    if (positional.size() != 1) throw InputError("give exactly one scene file (see --help)");
    StudyInvocation& s = parsed.invocation;
    if (s.merge && s.families.empty())
        throw InputError("option --merge: give the strategies to render again with --only");
    s.scale = composeScale(parsed.overrides);
    s.base.scenePath = positional[0];
    s.base.width = s.scale.width;
    s.base.height = s.scale.height;
    if (s.name.empty()) s.name = std::filesystem::path(positional[0]).stem().string();
    return parsed;
}

} // namespace

int main(int argc, char** argv) {
    return vkpt::runProgram(kProgram, [argc, argv] {
        const Parsed parsed = parseArguments(argc, argv);
        if (parsed.showHelp) return 0;
        return runStudy(parsed.invocation);
    });
}
