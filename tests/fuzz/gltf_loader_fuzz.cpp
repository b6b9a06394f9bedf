// gltf_loader_fuzz.cpp — libFuzzer entry point over the whole glTF loader: .gltf/.glb parsing,
// the JSON pre-pass, validation of every index and range, instancing (EXT_mesh_gpu_instancing,
// meshes kept once), skins, morph targets, sparse accessors and animations, and the Draco, meshopt,
// WebP, PNG and JPEG decoders. An input either loads or ends in one InputError; anything else (a
// crash, a sanitizer report, another exception, a leak, a hang) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "common/errors.h"
#include "scene/gltf_loader.h"

namespace {

// The loader reads files, so each input is written to one file in a directory of its own (so
// that relative buffer and image URIs find nothing but the input itself).
std::string inputPath() {
    static const std::string path = [] {
        const std::filesystem::path directory =
            std::filesystem::temp_directory_path() / ("vkpt-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(directory);
        return (directory / "input.gltf").string();
    }();
    return path;
}

void writeInput(const std::string& path, const std::uint8_t* data, std::size_t size) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (file == nullptr) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, file) != size) std::abort();
    std::fclose(file);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = inputPath();
    writeInput(path, data, size);
    vkpt::LoadOptions options;
    options.warnUnsupportedExtensions = false;
    // Small inputs would always be flattened (Instancing::Auto); odd-sized ones keep their meshes
    // once and place them by instances, so that both paths of the loader are fuzzed, each input
    // always the same way.
    options.instancing = size % 2 == 1 ? vkpt::Instancing::On : vkpt::Instancing::Auto;
    // Likewise every input whose size is a multiple of 3 is posed by its animations (between
    // keyframes of the seeds in scenes/loader/skin.gltf and morph.gltf); the others at rest.
    if (size % 3 == 0) options.time = 0.375;
    try {
        const vkpt::Scene scene = vkpt::loadGltfScene(path, options);
        (void)scene;
    } catch (const vkpt::InputError&) {
        // Bad input, reported as the interface promises.
    }
    return 0;
}
