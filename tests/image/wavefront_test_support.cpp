// wavefront_test_support.cpp — device renders and comparisons for the image tests.
#include "wavefront_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "image/image_io.h"
#include "prepare/environment_map.h"

namespace vkpt::test {

std::vector<std::string> featureTestScenes() {
    const std::filesystem::path directory = scenePath("test/features");
    std::vector<std::string> found;
    if (!std::filesystem::is_directory(directory)) return found;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
        const std::string extension = entry.path().extension().string();
        if (extension == ".gltf" || extension == ".glb")
            found.push_back("test/features/" + entry.path().filename().string());
    }
    std::sort(found.begin(), found.end());
    return found;
}

LoadedTestScene loadFeatureTestScene(const std::string& relative, bool general,
                                     LightSampler lightSampler) {
    LoadOptions options;
    options.warnUnsupportedExtensions = false;
    LoadedTestScene loaded{loadGltfScene(scenePath(relative), options), {}};
    if (relative == "test/features/environment.gltf")
        loaded.scene.environment =
            readEnvironmentMap(scenePath("test/features/sky.hdr"), glm::vec3(1.0f));
    // Glass alone in the dark is black: these see a uniform sky (glass_render_test.cpp).
    if (relative == "test/features/glass-ball.gltf" ||
        relative == "test/features/absorbing-slab.gltf")
        loaded.scene.environment.radiance = glm::vec3(0.5f, 1.0f, 2.0f);
    PrepareOptions prepare;
    prepare.general = general;
    prepare.lightSampler = lightSampler;
    loaded.prepared = prepareScene(loaded.scene, prepare);
    return loaded;
}

RenderOutput renderOnDevice(GpuContext& context, const LoadedTestScene& loaded,
                            const RenderSettings& settings, RenderStats* stats,
                            const WavefrontOptions& options) {
    gpu::Camera camera = makeGpuCamera(selectCamera(loaded.scene, settings.cameraIndex),
                                       settings.width, settings.height);
    WavefrontResult result = renderWavefront(context, loaded.prepared, camera, settings, options);
    EXPECT_EQ(result.truncatedTraversals, 0u) << "BVH walks cut short by a loop limit";
    if (stats) *stats = result.stats;
    return std::move(result.output);
}

namespace {

// Half h of an output as an output of its own, for compareSameSeed.
RenderOutput halfOutput(const RenderOutput& output, int h) {
    RenderOutput half;
    half.image = output.halves[h];
    return half;
}

} // namespace

void expectSameSeedAsReference(const std::string& name, const LoadedTestScene& scene,
                               const RenderSettings& settings, const RenderOutput& gpu,
                               const RenderStats& gpuStats) {
    RenderStats cpuStats;
    RenderOutput cpu = renderTestScene(scene, settings, &cpuStats);
    SameSeedAgreement a = compareSameSeed(gpu, cpu);
    std::printf("%s: %s; rays %llu vs %llu\n", name.c_str(), a.summary().c_str(),
                (unsigned long long)gpuStats.rays.total(),
                (unsigned long long)cpuStats.rays.total());
    EXPECT_GE(a.fraction(), kSameSeedMinimumAgreement) << writeComparisonImages(name, gpu, cpu);
    EXPECT_EQ(gpuStats.samplesTaken, cpuStats.samplesTaken) << name;
    for (int h = 0; h < 2; ++h) {
        const SameSeedAgreement half = compareSameSeed(halfOutput(gpu, h), halfOutput(cpu, h));
        std::printf("  half %d: %s\n", h, half.summary().c_str());
        EXPECT_GE(half.fraction(), kSameSeedMinimumAgreement) << name << ", half " << h;
        EXPECT_EQ(gpu.halfCounts[h], cpu.halfCounts[h]) << name << ", half " << h;
    }
}

SameSeedAgreement compareSameSeed(const RenderOutput& gpu, const RenderOutput& cpu) {
    SameSeedAgreement agreement;
    agreement.pixels = cpu.image.pixels.size();
    for (std::size_t i = 0; i < cpu.image.pixels.size(); ++i) {
        double worst = 0.0;
        bool ok = true;
        for (int c = 0; c < 3; ++c) {
            double a = gpu.image.pixels[i][c];
            double b = cpu.image.pixels[i][c];
            double difference = std::abs(a - b);
            ok = ok && difference <= kSameSeedRelative * std::abs(b) + kSameSeedAbsolute;
            worst = std::max(worst, difference / std::max(std::abs(b), kSameSeedAbsolute));
        }
        agreement.within += ok ? 1 : 0;
        agreement.aboveOneMillionth += worst > 1e-6 ? 1 : 0;
        if (worst > agreement.largestRelative) {
            agreement.largestRelative = worst;
            agreement.largestPixel = static_cast<std::uint32_t>(i);
        }
    }
    return agreement;
}

std::string SameSeedAgreement::summary() const {
    char line[256];
    std::snprintf(line, sizeof(line),
                  "%llu of %llu pixels within the bound (%.2f %%), %llu outside; %llu differ by "
                  "more than 1e-6 relative, the most by %.3g (pixel %u)",
                  (unsigned long long)within, (unsigned long long)pixels, 100.0 * fraction(),
                  (unsigned long long)(pixels - within), (unsigned long long)aboveOneMillionth,
                  largestRelative, largestPixel);
    return line;
}

std::string writeComparisonImages(const std::string& name, const RenderOutput& gpu,
                                  const RenderOutput& cpu) {
    Image difference(cpu.image.width, cpu.image.height);
    for (std::size_t i = 0; i < difference.pixels.size(); ++i)
        difference.pixels[i] = glm::abs(gpu.image.pixels[i] - cpu.image.pixels[i]);
    const std::filesystem::path directory = std::filesystem::current_path();
    const std::string base = (directory / name).string();
    writePfm(gpu.image, base + ".gpu.pfm");
    writePfm(cpu.image, base + ".cpu.pfm");
    writePfm(difference, base + ".diff.pfm");
    return "images written: " + base + ".gpu.pfm, " + base + ".cpu.pfm, " + base + ".diff.pfm";
}

} // namespace vkpt::test
