// write_compressed_scenes.cpp — writes the fuzz corpus's seeds that scenes/ cannot hold as
// small text: the test scene as .glb in every compressed form (tests/support/compressed_gltf.h),
// and empties the corpus directory the fuzzer adds to.
#include <filesystem>
#include <iostream>

#include "compressed_gltf.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: write_compressed_scenes SEED_DIR CORPUS_DIR\n";
        return 1;
    }
    using vkpt::test::GeometryCoding;
    using vkpt::test::ImageCoding;
    const std::filesystem::path seeds = argv[1];
    std::filesystem::create_directories(seeds);
    std::filesystem::remove_all(argv[2]);
    std::filesystem::create_directories(argv[2]);
    const struct {
        const char* name;
        GeometryCoding geometry;
        ImageCoding image;
    } scenes[] = {{"floats_png.glb", GeometryCoding::Floats, ImageCoding::Png},
                  {"draco_png.glb", GeometryCoding::Draco, ImageCoding::Png},
                  {"meshopt_webp.glb", GeometryCoding::Meshopt, ImageCoding::Webp},
                  {"quantized_webp_fallback.glb", GeometryCoding::Quantized,
                   ImageCoding::WebpOverPngFallback}};
    for (const auto& scene : scenes)
        vkpt::test::writeTestScene((seeds / scene.name).string(), scene.geometry, scene.image);
    return 0;
}
