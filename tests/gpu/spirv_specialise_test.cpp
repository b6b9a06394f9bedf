// spirv_specialise_test.cpp — the SPIR-V a pipeline is created from: specialisation constants
// folded on the host (gpu/spirv_specialise.h), the code they switch off gone, garbage refused.
// The values reaching the kernel are Dispatch.PushAndSpecializationConstantsReachTheKernel's.
#include "gpu/spirv_specialise.h"
#include "gpu/vk_check.h"
#include "shared/host_device.h"
#include "vkpt_kernels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <vector>

namespace vkpt::test::spirv_specialise_test {
namespace {

// SPIR-V opcodes and decorations (SPIR-V 1.6 specification, §3.32 and §3.20).
constexpr std::uint32_t kOpDecorate = 71;
constexpr std::uint32_t kDecorationSpecId = 1;
constexpr std::uint32_t kOpSpecConstantTrue = 48;
constexpr std::uint32_t kOpSpecConstantOp = 52; // 48–52: every OpSpecConstant* instruction
constexpr std::size_t kHeaderWords = 5;

// How many instructions of the module declare or decorate a specialisation constant.
int specialisationInstructions(std::span<const std::uint32_t> spirv) {
    int count = 0;
    for (std::size_t at = kHeaderWords; at < spirv.size();) {
        const std::uint32_t opcode = spirv[at] & 0xFFFFu;
        const std::uint32_t words = spirv[at] >> 16;
        if (opcode >= kOpSpecConstantTrue && opcode <= kOpSpecConstantOp) ++count;
        if (opcode == kOpDecorate && words >= 3 && spirv[at + 2] == kDecorationSpecId) ++count;
        if (words == 0) break;
        at += words;
    }
    return count;
}

std::vector<SpecializationConstant> everyFeature(bool on) {
    std::vector<SpecializationConstant> constants;
    for (std::uint32_t id = 0; id < FEATURE_COUNT; ++id)
        constants.push_back(specializeBool(id, on));
    return constants;
}

std::span<const std::uint32_t> shadeHits() {
    return kernels::findKernel("shade_hits").spirv;
}

TEST(SpirvSpecialise, FoldsEveryConstantSoTheDriverGetsNone) {
    ASSERT_GT(specialisationInstructions(shadeHits()), FEATURE_COUNT);
    const std::vector<std::uint32_t> folded =
        specialiseSpirv(shadeHits(), everyFeature(true), "shade_hits");
    EXPECT_EQ(specialisationInstructions(folded), 0);
}

TEST(SpirvSpecialise, AFeatureSwitchedOffTakesItsCodeWithIt) {
    const std::size_t none = specialiseSpirv(shadeHits(), everyFeature(false), "shade_hits").size();
    const std::size_t all = specialiseSpirv(shadeHits(), everyFeature(true), "shade_hits").size();
    // What the feature constants guard directly goes: the material extensions, sheen, clearcoat,
    // the environment map, ... (88,134 against 74,394 words when this was written). Code that
    // runs on a material's own flags stays, which is why the diffuse build exists.
    EXPECT_LT(none, all * 9 / 10) << none << " words with no feature, " << all << " with all";
    EXPECT_LE(all, shadeHits().size());
}

TEST(SpirvSpecialise, RefusesWhatIsNotSpirvAndNamesTheKernel) {
    const std::vector<std::uint32_t> garbage(64, 0xDEADBEEFu);
    try {
        specialiseSpirv(garbage, everyFeature(true), "not_a_kernel");
        FAIL() << "garbage was specialised";
    } catch (const VulkanError& error) {
        EXPECT_NE(std::string(error.what()).find("not_a_kernel"), std::string::npos)
            << error.what();
    }
}

} // namespace
} // namespace vkpt::test::spirv_specialise_test
