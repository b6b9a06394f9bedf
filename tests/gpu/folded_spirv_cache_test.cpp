// folded_spirv_cache_test.cpp — folded kernels kept in files (gpu/folded_spirv_cache.h): a start
// with the same kernel and constants reads the module folded before, other constants make other
// files, a damaged or foreign file is folded again and written over, and the folder comes from
// VKPT_KERNEL_CACHE_DIR or beside the pipeline cache.
#include "../support/test_directory.h"
#include "gpu/cache_files.h"
#include "gpu/folded_spirv_cache.h"
#include "gpu/spirv_specialise.h"
#include "lib/wavefront.h"
#include "vkpt_kernels.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace vkpt::test::folded_spirv_cache_test {
namespace {

// A kernel with a constant that changes its folded module: the camera rays' medium, which
// FEATURE_TRANSMISSION switches on.
KernelDesc cameraRays(bool transmission) {
    KernelDesc desc;
    desc.name = "generate_camera_rays";
    desc.spirv = kernels::findKernel("generate_camera_rays").spirv;
    desc.specializationConstants = {specializeBool(FEATURE_TRANSMISSION, transmission)};
    return desc;
}

// The file's inode: a file written again (a temporary renamed over it) has a new one.
ino_t inodeOf(const std::filesystem::path& file) {
    struct stat status {};
    return stat(file.c_str(), &status) == 0 ? status.st_ino : 0;
}

void overwrite(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// Sets an environment variable for one scope, restoring what was there.
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value)
            setenv(name, value, 1);
        else
            unsetenv(name);
    }
    ~ScopedEnvironment() {
        if (old_)
            setenv(name_, old_->c_str(), 1);
        else
            unsetenv(name_);
    }
    ScopedEnvironment(const ScopedEnvironment&) = delete;
    ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

class FoldedSpirvCacheFiles : public TestDirectory {
protected:
    FoldedSpirvCacheFiles() : TestDirectory("vkpt_folded_spirv") {}
};

TEST_F(FoldedSpirvCacheFiles, ALaterStartReadsTheModuleFoldedBefore) {
    const KernelDesc desc = cameraRays(false);
    const FoldedSpirvCache first(dir_ / "kernels");
    const std::vector<std::uint32_t> folded = first.fold(desc);
    EXPECT_EQ(folded, specialiseSpirv(desc));
    const std::filesystem::path file = first.fileFor(desc);
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const ino_t written = inodeOf(file);

    const FoldedSpirvCache later(dir_ / "kernels");
    EXPECT_EQ(later.fold(desc), folded);
    EXPECT_EQ(inodeOf(file), written) << "the file was written again, not read";
}

TEST_F(FoldedSpirvCacheFiles, OtherConstantsAreAnotherFile) {
    const FoldedSpirvCache cache(dir_);
    const std::vector<std::uint32_t> without = cache.fold(cameraRays(false));
    const std::vector<std::uint32_t> with = cache.fold(cameraRays(true));
    EXPECT_NE(cache.fileFor(cameraRays(false)), cache.fileFor(cameraRays(true)));
    EXPECT_NE(without, with);
    EXPECT_EQ(cache.fold(cameraRays(true)), specialiseSpirv(cameraRays(true)));
    EXPECT_EQ(cache.fold(cameraRays(false)), specialiseSpirv(cameraRays(false)));
}

// Truncated, one byte of the module changed, and another key's file under this key's name:
// each is folded again, and the file written over is whole again.
TEST_F(FoldedSpirvCacheFiles, ADamagedOrForeignFileIsFoldedAgainAndWrittenOver) {
    const FoldedSpirvCache cache(dir_);
    const KernelDesc desc = cameraRays(false);
    const std::vector<std::uint32_t> expected = specialiseSpirv(desc);
    cache.fold(desc);
    const std::filesystem::path file = cache.fileFor(desc);
    const std::vector<std::uint8_t> good = readWholeFile(file);
    cache.fold(cameraRays(true));
    const std::vector<std::uint8_t> foreign = readWholeFile(cache.fileFor(cameraRays(true)));

    std::vector<std::uint8_t> flipped = good;
    flipped[flipped.size() - 9] ^= 0x10u;
    const std::vector<std::uint8_t> truncated(good.begin(), good.begin() + good.size() / 2);
    for (const std::vector<std::uint8_t>& damaged : {truncated, flipped, foreign}) {
        overwrite(file, damaged);
        EXPECT_EQ(cache.fold(desc), expected);
        EXPECT_EQ(readWholeFile(file), good);
    }
}

TEST_F(FoldedSpirvCacheFiles, NoFolderFoldsEveryTimeAndWritesNothing) {
    const FoldedSpirvCache none{std::filesystem::path()};
    EXPECT_EQ(none.fold(cameraRays(false)), specialiseSpirv(cameraRays(false)));
    EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

// VKPT_KERNEL_CACHE_DIR first (tests and scripts); else beside a persistent pipeline cache, the
// one named or the default, which VKPT_NO_PIPELINE_CACHE turns off; else none.
TEST_F(FoldedSpirvCacheFiles, TheFolderComesFromTheEnvironmentOrThePipelineCache) {
    const ScopedEnvironment xdg("XDG_CACHE_HOME", path("xdg").c_str());
    {
        const ScopedEnvironment folder("VKPT_KERNEL_CACHE_DIR", path("shared").c_str());
        EXPECT_EQ(foldedSpirvCacheFolder(false, ""), dir_ / "shared");
        EXPECT_EQ(foldedSpirvCacheFolder(true, path("p/cache.bin")), dir_ / "shared");
    }
    const ScopedEnvironment noFolder("VKPT_KERNEL_CACHE_DIR", nullptr);
    EXPECT_EQ(foldedSpirvCacheFolder(false, ""), std::filesystem::path());
    EXPECT_EQ(foldedSpirvCacheFolder(true, path("p/cache.bin")), dir_ / "p" / "kernels");
    {
        const ScopedEnvironment on("VKPT_NO_PIPELINE_CACHE", "0");
        EXPECT_EQ(foldedSpirvCacheFolder(true, ""), dir_ / "xdg" / "vkpt" / "kernels");
    }
    const ScopedEnvironment off("VKPT_NO_PIPELINE_CACHE", "1");
    EXPECT_EQ(foldedSpirvCacheFolder(true, ""), std::filesystem::path());
}

} // namespace
} // namespace vkpt::test::folded_spirv_cache_test
