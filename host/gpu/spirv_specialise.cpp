// spirv_specialise.cpp — specialisation constants folded with SPIRV-Tools' optimiser.
#include "gpu/spirv_specialise.h"

#include "gpu/vk_check.h"

#include <spirv-tools/libspirv.h>
#include <spirv-tools/optimizer.hpp>

#include <unordered_map>

namespace vkpt {

namespace {

// Constant folding and branch elimination, three rounds: a branch folded in one round can make
// a value constant for the next. No instruction simplification: spirv-opt's rewrote float
// arithmetic enough to move normal_map.gltf's image on 4 pixels when a build-time form of these
// passes was tried, and the folded module must render the driver's image bit for bit.
//
// The functions only the switched-off code called go first, after one branch elimination: the
// rounds then walk a module a fifth the size for a Lambertian scene. The result is the same
// module (each pass works function by function), in less time: the Cornell box's shade_hits
// took 216 ms to create against 247 ms (medians of 6, `vkpt --stats`).
void registerPrunePasses(spvtools::Optimizer& optimizer) {
    optimizer.RegisterPass(spvtools::CreateDeadBranchElimPass());
    optimizer.RegisterPass(spvtools::CreateEliminateDeadFunctionsPass());
    for (int round = 0; round < 3; ++round) {
        optimizer.RegisterPass(spvtools::CreateDeadBranchElimPass());
        optimizer.RegisterPass(spvtools::CreateBlockMergePass());
        optimizer.RegisterPass(spvtools::CreateCCPPass());
    }
    optimizer.RegisterPass(spvtools::CreateDeadBranchElimPass());
    optimizer.RegisterPass(spvtools::CreateEliminateDeadFunctionsPass());
}

} // namespace

std::vector<std::uint32_t> specialiseSpirv(std::span<const std::uint32_t> spirv,
                                           const std::vector<SpecializationConstant>& constants,
                                           const std::string& kernelName) {
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> values;
    for (const SpecializationConstant& constant : constants)
        values[constant.id] = {constant.value};

    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_2);
    std::string messages;
    optimizer.SetMessageConsumer([&messages](spv_message_level_t, const char*,
                                             const spv_position_t& position, const char* text) {
        messages += "word " + std::to_string(position.index) + ": " + text + "; ";
    });
    optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values));
    optimizer.RegisterPass(spvtools::CreateFreezeSpecConstantValuePass());
    optimizer.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
    registerPrunePasses(optimizer);

    std::vector<std::uint32_t> out;
    spvtools::OptimizerOptions options;
    // The modules are the build's own glslang output; validating each again would double the
    // cost, and the validation layer checks what the driver gets in every GPU test.
    options.set_run_validator(false);
    if (!optimizer.Run(spirv.data(), spirv.size(), &out, options)) {
        throw VulkanError("kernel '" + kernelName +
                              "': SPIRV-Tools could not specialise its SPIR-V: " + messages,
                          VK_ERROR_INITIALIZATION_FAILED);
    }
    return out;
}

// Change the number with the passes of registerPrunePasses, or anything else that changes what
// specialiseSpirv makes of a module.
std::string specialiseSpirvVersion() {
    return std::string("vkpt folding 2, ") + spvSoftwareVersionDetailsString();
}

std::vector<std::uint32_t> specialiseSpirv(const KernelDesc& desc) {
    return specialiseSpirv(desc.spirv, desc.specializationConstants, desc.name);
}

} // namespace vkpt
