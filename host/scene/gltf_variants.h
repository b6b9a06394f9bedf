// gltf_variants.h — KHR_materials_variants: the file's named material variants and, for a chosen
// one, the material each primitive's mappings give it.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace vkpt::gltf {

// The variants' names (extensions.KHR_materials_variants.variants[i].name) in file order; empty
// when the file has none. Throws GltfProblem for a variant without a string name.
std::vector<std::string> materialVariantNames(const tinygltf::Model& model);

// The variant `request` (--variant) names: a variant of that name, else a decimal index into
// `names`; -1 for an empty request (the default materials). Throws GltfProblem naming the
// variants there are when none matches.
int chooseMaterialVariant(const std::vector<std::string>& names, const std::string& request);

// The glTF material `primitive` shows under `variant` (-1: its own `material`, the default):
// the material of the first mapping that lists the variant (the extension allows one), else its
// own. Every mapping is checked, chosen or not: a variant index must be one of the
// `variantCount` variants, and a mapping must name a material (its range is the loader's check,
// as for `material`). `where` names the primitive.
int variantMaterial(const tinygltf::Primitive& primitive, int variant, std::size_t variantCount,
                    const std::string& where);

} // namespace vkpt::gltf
