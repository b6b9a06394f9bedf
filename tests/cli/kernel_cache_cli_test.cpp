// kernel_cache_cli_test.cpp — what vkpt and the driver keep of its kernels between runs. vkpt
// keeps the kernels it folded beside its pipeline cache, and a later run renders the same bits
// from them. Lavapipe compiles each of a scene's kernels once, whatever the image size: a render
// at another size files nothing new in Mesa's shader cache. Lavapipe keys
// a compiled kernel on the sizes of the texel buffers bound to it (gpu/buffer.h,
// keyStableTexelBytes); were they to leak into the key again, every test at a new size would
// run LLVM over kernels it had compiled before, and a fresh machine's suite would take twice
// as long.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../support/child_process.h"
#include "../support/test_directory.h"

namespace vkpt::test::kernel_cache_cli_test {
namespace {

const std::string kCornell = VKPT_SCENES_DIR "/cornell-box.gltf";

class KernelCache : public TestDirectory {
protected:
    KernelCache() : TestDirectory("vkpt_kernel_cache") {}

    // Renders the Cornell box at size² with one sample, into this test's own shader cache.
    void render(int size) {
        const Finished finished =
            runProcess({VKPT, "--quiet", "--spp", "1", "--res", std::to_string(size),
                        std::to_string(size), "-o", path("out.pfm"), kCornell},
                       {"MESA_SHADER_CACHE_DIR=" + path("mesa"), "VKPT_NO_PIPELINE_CACHE=1"});
        ASSERT_EQ(finished.exitCode, 0) << "vkpt at " << size << "²: " << finished.stderrText;
    }

    int cacheEntries(const std::string& folder = "mesa") const {
        if (!std::filesystem::exists(dir_ / folder)) return 0;
        int entries = 0;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(dir_ / folder))
            entries += entry.is_regular_file() ? 1 : 0;
        return entries;
    }

    // vkpt as a user runs it: its caches in $XDG_CACHE_HOME/vkpt (this test's folder), not the
    // suite's shared folder of folded kernels.
    void renderWithUserCaches(const std::string& output) {
        const Finished finished = runProcess(
            {VKPT, "--quiet", "--spp", "2", "--res", "16", "16", "-o", path(output), kCornell},
            {"XDG_CACHE_HOME=" + path("xdg"), "VKPT_NO_PIPELINE_CACHE=0",
             "VKPT_KERNEL_CACHE_DIR="});
        ASSERT_EQ(finished.exitCode, 0) << finished.stderrText;
    }
};

// Every kernel of the Cornell box that has constants is kept folded, once; the second run reads
// them (it writes no file more) and renders the first run's bits.
TEST_F(KernelCache, FoldedKernelsAreKeptBesideThePipelineCacheAndGiveTheSameImage) {
    renderWithUserCaches("first.pfm");
    const int kept = cacheEntries("xdg/vkpt/kernels");
    // The four kernels specialised for the scene's features (generate_camera_rays, trace_closest,
    // shade_hits, trace_shadow); the other three have no constants to fold.
    EXPECT_GE(kept, 4) << "the four specialised wavefront kernels";
    renderWithUserCaches("second.pfm");
    EXPECT_EQ(cacheEntries("xdg/vkpt/kernels"), kept);
    EXPECT_EQ(bytesOf(path("first.pfm")), bytesOf(path("second.pfm")));
}

// 16² and 64² give the per-pixel texel buffers power-of-two sizes (and 64² a range whose bits
// 8-15 are zero), 24² neither: before the sizes were steered, 24², 32² and 64² each filed
// 3-4 entries more than 16² had.
TEST_F(KernelCache, AnotherImageSizeCompilesNoKernelAgain) {
    render(16);
    const int first = cacheEntries();
    if (first == 0) GTEST_SKIP() << "the driver filed nothing in MESA_SHADER_CACHE_DIR";
    for (int size : {24, 32, 64}) {
        render(size);
        EXPECT_EQ(cacheEntries(), first) << "the render at " << size << "² compiled kernels again";
    }
}

} // namespace
} // namespace vkpt::test::kernel_cache_cli_test
