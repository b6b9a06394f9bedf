// gltf_values.cpp — typed reads of tinygltf::Value with one-line messages. tinygltf's own
// accessors assert on a wrong type (Get(key) on a non-object), so every read checks first.
#include "scene/gltf_values.h"

#include <cmath>

#include "scene/gltf_document.h"

namespace vkpt::gltf {
namespace {

bool isFiniteNumber(const tinygltf::Value& value) {
    return value.IsNumber() && std::isfinite(value.GetNumberAsDouble());
}

[[noreturn]] void failMember(const std::string& where, const std::string& key,
                             const std::string& expected) {
    throw GltfProblem(where + ": " + key + " must be " + expected);
}

} // namespace

const tinygltf::Value* findExtension(const tinygltf::ExtensionMap& extensions,
                                     const std::string& name) {
    const auto found = extensions.find(name);
    return found == extensions.end() ? nullptr : &found->second;
}

const tinygltf::Value* findMember(const tinygltf::Value& object, const std::string& key) {
    if (!object.IsObject() || !object.Has(key)) return nullptr;
    return &object.Get(key);
}

double readNumber(const tinygltf::Value& object, const std::string& key, double fallback,
                  const std::string& where) {
    const tinygltf::Value* value = findMember(object, key);
    if (value == nullptr) return fallback;
    if (!isFiniteNumber(*value)) failMember(where, key, "a finite number");
    return value->GetNumberAsDouble();
}

std::vector<double> readNumbers(const tinygltf::Value& object, const std::string& key,
                                const std::vector<double>& fallback, const std::string& where) {
    const tinygltf::Value* value = findMember(object, key);
    if (value == nullptr) return fallback;
    const std::string expected = "an array of " + std::to_string(fallback.size()) + " numbers";
    if (!value->IsArray() || value->ArrayLen() != fallback.size()) {
        failMember(where, key, expected);
    }
    std::vector<double> numbers;
    for (std::size_t i = 0; i < fallback.size(); ++i) {
        const tinygltf::Value& element = value->Get(static_cast<int>(i));
        if (!isFiniteNumber(element)) failMember(where, key, expected);
        numbers.push_back(element.GetNumberAsDouble());
    }
    return numbers;
}

int readIndex(const tinygltf::Value& object, const std::string& key, const std::string& where) {
    const tinygltf::Value* value = findMember(object, key);
    if (value == nullptr) return -1;
    if (!value->IsInt() || value->GetNumberAsInt() < 0) {
        failMember(where, key, "an index (an integer >= 0)");
    }
    return value->GetNumberAsInt();
}

std::string readString(const tinygltf::Value& object, const std::string& key,
                       const std::string& fallback, const std::string& where) {
    const tinygltf::Value* value = findMember(object, key);
    if (value == nullptr) return fallback;
    if (!value->IsString()) failMember(where, key, "a string");
    return value->Get<std::string>();
}

const tinygltf::Value& arrayElement(const tinygltf::Value& array, int index,
                                    const std::string& what, const std::string& where) {
    const std::size_t count = array.ArrayLen(); // 0 when not an array
    if (index < 0 || static_cast<std::size_t>(index) >= count) {
        throw GltfProblem(where + ": " + what + " " + std::to_string(index) +
                          " does not exist (the file has " + std::to_string(count) + " " + what +
                          (count == 1 ? "" : "s") + ")");
    }
    return array.Get(index);
}

} // namespace vkpt::gltf
