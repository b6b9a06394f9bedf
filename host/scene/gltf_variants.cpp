// gltf_variants.cpp — KHR_materials_variants: the document's variant list and the primitives'
// mappings from variants to materials (the extension's README: a primitive without a mapping
// for the chosen variant keeps its own material).
#include "scene/gltf_variants.h"

#include <algorithm>
#include <charconv>

#include "scene/gltf_document.h"
#include "scene/gltf_values.h"

namespace vkpt::gltf {
namespace {

constexpr const char* kVariants = "KHR_materials_variants";

std::string listOf(const std::vector<std::string>& names) {
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : ", ") + std::to_string(i) + " '" + names[i] + "'";
    return text;
}

// The variant indices one mapping lists, each checked against the document's count.
std::vector<int> mappedVariants(const tinygltf::Value& mapping, std::size_t variantCount,
                                const std::string& where) {
    const tinygltf::Value* list = findMember(mapping, "variants");
    if (list == nullptr || !list->IsArray() || list->ArrayLen() == 0)
        throw GltfProblem(where + ": variants must be a non-empty array of indices");
    std::vector<int> variants;
    for (std::size_t i = 0; i < list->ArrayLen(); ++i) {
        const tinygltf::Value& entry = list->Get(static_cast<int>(i));
        if (!entry.IsInt() || entry.GetNumberAsInt() < 0 ||
            static_cast<std::size_t>(entry.GetNumberAsInt()) >= variantCount) {
            throw GltfProblem(where + ": variants[" + std::to_string(i) +
                              "] is not the index of one of the file's " +
                              std::to_string(variantCount) + " variants");
        }
        variants.push_back(entry.GetNumberAsInt());
    }
    return variants;
}

} // namespace

std::vector<std::string> materialVariantNames(const tinygltf::Model& model) {
    const tinygltf::Value* extension = findExtension(model.extensions, kVariants);
    if (extension == nullptr) return {};
    const std::string where = std::string("extensions.") + kVariants;
    const tinygltf::Value* list = findMember(*extension, "variants");
    if (list == nullptr || !list->IsArray())
        throw GltfProblem(where + ": variants must be an array");
    std::vector<std::string> names;
    for (std::size_t i = 0; i < list->ArrayLen(); ++i) {
        const std::string place = where + ": variant " + std::to_string(i);
        const tinygltf::Value& variant = list->Get(static_cast<int>(i));
        if (findMember(variant, "name") == nullptr) throw GltfProblem(place + ": name is missing");
        names.push_back(readString(variant, "name", "", place));
    }
    return names;
}

int chooseMaterialVariant(const std::vector<std::string>& names, const std::string& request) {
    if (request.empty()) return -1;
    if (names.empty()) throw GltfProblem("--variant " + request + ": the file has no " + kVariants);
    const auto named = std::find(names.begin(), names.end(), request);
    if (named != names.end()) return static_cast<int>(named - names.begin());
    std::size_t index = 0;
    const auto [end, error] =
        std::from_chars(request.data(), request.data() + request.size(), index);
    if (error == std::errc() && end == request.data() + request.size() && index < names.size())
        return static_cast<int>(index);
    throw GltfProblem("--variant " + request +
                      ": no variant of that name or index (the file's: " + listOf(names) + ")");
}

int variantMaterial(const tinygltf::Primitive& primitive, int variant, std::size_t variantCount,
                    const std::string& where) {
    const tinygltf::Value* extension = findExtension(primitive.extensions, kVariants);
    if (extension == nullptr) return primitive.material;
    const std::string place = where + ": " + kVariants;
    const tinygltf::Value* mappings = findMember(*extension, "mappings");
    if (mappings == nullptr || !mappings->IsArray())
        throw GltfProblem(place + ": mappings must be an array");
    int chosen = primitive.material;
    bool found = false;
    for (std::size_t m = 0; m < mappings->ArrayLen(); ++m) {
        const std::string mappingPlace = place + ": mapping " + std::to_string(m);
        const tinygltf::Value& mapping = mappings->Get(static_cast<int>(m));
        const int material = readIndex(mapping, "material", mappingPlace);
        if (material < 0) throw GltfProblem(mappingPlace + ": material is missing");
        for (int v : mappedVariants(mapping, variantCount, mappingPlace)) {
            if (v != variant || found) continue;
            chosen = material;
            found = true;
        }
    }
    return chosen;
}

} // namespace vkpt::gltf
