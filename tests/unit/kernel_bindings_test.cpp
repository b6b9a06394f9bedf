// kernel_bindings_test.cpp — the kernels' binding lists (shaders/lib/kernel_bindings.h) as the
// host builds pipeline layouts from them. What a list can get wrong without the kernel's
// compiler noticing: a binding given twice, frameParams left out, one binding seen as a
// different kind of descriptor by two kernels, though one buffer (BufferTable) serves both, a
// splittable scene array declared as one descriptor, or a scene array no kernel reads.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "lib/wavefront.h"
#include "render/scene_arrays.h"
#include "render/wavefront_kernels.h"

namespace vkpt::kernel_bindings_test {
namespace {

std::string nameOf(WavefrontKernel kernel) {
    return std::string(kernelName(kernel));
}

WavefrontKernel kernelAt(std::size_t index) {
    return static_cast<WavefrontKernel>(index);
}

TEST(KernelBindings, NoKernelListsABindingTwice) {
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        std::set<std::uint32_t> seen;
        for (const KernelBinding& binding : kernelBindings(kernelAt(i)))
            EXPECT_TRUE(seen.insert(binding.binding).second)
                << nameOf(kernelAt(i)) << ": binding " << binding.binding;
    }
}

TEST(KernelBindings, EveryKernelReadsFrameParamsAsAUniformBuffer) {
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        bool found = false;
        for (const KernelBinding& binding : kernelBindings(kernelAt(i)))
            if (binding.binding == BINDING_FRAME_PARAMS)
                found = binding.kind == DescriptorKind::UniformBuffer;
        EXPECT_TRUE(found) << nameOf(kernelAt(i));
    }
}

TEST(KernelBindings, ABindingIsOneKindOfDescriptorInEveryKernel) {
    std::map<std::uint32_t, DescriptorKind> kinds;
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        for (const KernelBinding& binding : kernelBindings(kernelAt(i))) {
            EXPECT_LT(binding.binding, std::uint32_t(BINDING_COUNT)) << nameOf(kernelAt(i));
            const auto [it, first] = kinds.emplace(binding.binding, binding.kind);
            EXPECT_TRUE(first || it->second == binding.kind)
                << nameOf(kernelAt(i)) << ": binding " << binding.binding;
        }
    }
}

// A scene array the host may split (SPLIT in shared/scene_array_table.h) must be a descriptor
// array in every kernel that reads it (its SCENE entry), and nothing else may be one: else a
// split array's chunks past the first would be unbound, or a whole one bound where the kernel
// expects chunks (a TEXELS or BUFFER entry given a scene array's binding).
TEST(KernelBindings, SplittableSceneArraysAreDescriptorArraysEverywhere) {
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i) {
        for (const KernelBinding& binding : kernelBindings(kernelAt(i))) {
            const std::uint32_t expected =
                isSplittableSceneBinding(binding.binding) ? SCENE_ARRAY_MAX_CHUNKS : 1u;
            EXPECT_EQ(binding.count, expected)
                << nameOf(kernelAt(i)) << ": binding " << binding.binding;
        }
    }
}

// A row of the scene array table that no kernel's list names is uploaded for nothing: the
// array's SCENE entry is missing from the kernels that read it, or the row is left over.
TEST(KernelBindings, EverySceneArrayIsReadBySomeKernel) {
    std::set<std::uint32_t> bound;
    for (std::size_t i = 0; i < kWavefrontKernelCount; ++i)
        for (const KernelBinding& binding : kernelBindings(kernelAt(i)))
            bound.insert(binding.binding);
    for (const SceneArrayDesc& desc : sceneArrayList())
        EXPECT_TRUE(bound.contains(desc.binding)) << desc.name;
}

} // namespace
} // namespace vkpt::kernel_bindings_test
