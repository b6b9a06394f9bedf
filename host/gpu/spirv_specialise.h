// spirv_specialise.h — a kernel's SPIR-V with its specialisation constants made constants and the
// code they switch off removed, before the driver sees it.
//
// A driver translates the whole module it is given and only then applies the specialisation
// constants; lavapipe, for one, turns every function of shade_hits into NIR and inlines it before
// the constant branches fall away, so a scene that uses two material features pays for all of
// them at every pipeline creation (docs/gpu.md, "Pipelines"). Folding the constants here with
// SPIRV-Tools' optimiser hands the driver only the code the scene runs.
#pragma once

#include "gpu/kernel.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vkpt {

// `spirv` with every constant of `constants` set to its value and frozen (so are the module's
// other specialisation constants, at their defaults), constant branches folded and dead functions
// dropped. Throws VulkanError, naming `kernelName`, when SPIRV-Tools rejects the module.
std::vector<std::uint32_t> specialiseSpirv(std::span<const std::uint32_t> spirv,
                                           const std::vector<SpecializationConstant>& constants,
                                           const std::string& kernelName);
// The same for a kernel's description: its SPIR-V, constants and name.
std::vector<std::uint32_t> specialiseSpirv(const KernelDesc& desc);

// What the folded module depends on besides the kernel and its constants: the passes and
// SPIRV-Tools' version (folded_spirv_cache.h keys its files on it).
std::string specialiseSpirvVersion();

} // namespace vkpt
